// `spherical_billboards`: a particle medium in real time with single scattering (book §9.3–9.4).
// Every frame: the volume's transmittance from each particle towards the lights and a set of sky
// directions (volume shadowing), each particle's light scattered towards the eye, and the
// particles splatted back to front as billboards whose opacity is the optical depth of the eye
// ray's segment in the particle, clipped against surfaces (spherical) or not (planar). Surfaces
// are lit as `direct` lights them. See README.md beside this file.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/particles/particle_compositor.h"
#include "realtime/particles/particle_medium.h"
#include "realtime/particles/volume_shadow.h"
#include "realtime/technique.h"

#include <optional>

namespace gib::rt {

class SphericalBillboardsTechnique final : public Technique {
 public:
  explicit SphericalBillboardsTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  // Emitters and sky seen directly, direct light on surfaces, single scattering in the medium.
  scene::PathClass pathClass() const override { return {0, 1}; }
  std::vector<TechniqueStatistic> statistics() const override;
  // `clipping`: |planar − spherical|, where classic billboards clip against surfaces (Fig. 9.3).
  std::vector<AuxiliaryImage> auxiliaryImages() override;

  // Each particle's radiance towards the eye per unit opacity (tests).
  const gl::Buffer& particleRadiance() const { return compositor_.source(); }

 private:
  int sky_directions_;
  ParticleCompositor compositor_;
  std::optional<ParticleMedium> medium_;
  std::optional<VolumeShadow> volume_shadow_;
  gl::Buffer directions_, sky_directions_buffer_, transmittance_;
  int width_ = 0, height_ = 0;
};

TechniqueInfo sphericalBillboardsTechniqueInfo();

}  // namespace gib::rt
