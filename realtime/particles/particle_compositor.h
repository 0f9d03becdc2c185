// What the particle techniques share per frame (book §9.3): the surfaces drawn first (G-buffer,
// sky and emitters seen directly, direct light as `direct` adds it), each particle's radiance
// towards the eye from its incoming light, the particles sorted back to front, and their
// billboards blended over the surfaces. The techniques differ in the incoming light they give:
// the sky through the volume's transmittance (spherical_billboards) or the illumination network.
#pragma once

#include "common/parameters.h"
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/objects.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/particles/particle_medium.h"
#include "realtime/pass_declarations.h"
#include "realtime/technique.h"

#include <optional>
#include <string_view>

namespace gib::rt {

inline constexpr std::string_view kParticleShadingPass = "particle shading";
inline constexpr std::string_view kParticleSortPass = "sorting";
inline constexpr std::string_view kBillboardPass = "billboards";

struct BillboardSettings {
  bool spherical = true;
  int opacity = 0;             // gpu::kOpacityLinear, kOpacityGouraud or kOpacityHomogeneous
  bool surface_shadow = true;  // surfaces lit through the medium's transmittance
};

// The incoming light of each particle's view shading: D directions (a buffer of vec4), and either
// the network's incoming radiance (vec4[N × D]) or, where that is null, the sky seen through
// `transmittance` (float[N × stride]: the lights' first, then the D directions').
struct ParticleIncoming {
  const gl::Buffer* transmittance = nullptr;
  int stride = 0;
  const gl::Buffer* directions = nullptr;
  int direction_count = 0;
  const gl::Buffer* radiance = nullptr;
};

class ParticleCompositor {
 public:
  explicit ParticleCompositor(const ParameterValues& parameters);

  // `billboard`, `opacity` and `surface_shadow`, then the surfaces' direct-lighting parameters.
  static ParameterTable parameters();
  // The frame passes: the surfaces', kParticleShadingPass, kParticleSortPass, kBillboardPass.
  static void declarePasses(PassDeclarations& passes);
  // The statistics both particle techniques report of their medium (particles, lights), then
  // the technique's own.
  static std::vector<DeclaredOutput> statistics(std::vector<DeclaredOutput> own);

  // Builds the programs for `scene` and `medium`, which must outlive the compositor's frames.
  void prepare(const GpuScene& scene, const ParticleMedium& medium);
  // The surfaces into frame.target: the G-buffer, the sky and emitters seen directly, direct
  // light through the medium (skipped in a scene of particles alone).
  void renderSurfaces(Frame& frame);
  // Each particle's radiance towards the eye per unit opacity, from the lights (through the
  // first medium.lightCount() transmittances) and `incoming`.
  void shade(const ParticleIncoming& incoming, gl::PassProfiler& profiler);
  // The particles sorted back to front and their billboards blended into frame.target.
  void sortAndSplat(Frame& frame);

  // Each particle's radiance towards the eye of the last shade() (tests).
  const gl::Buffer& source() const { return source_; }
  bool spherical() const { return billboard_.spherical; }
  // Switches between spherical and planar billboards from the next sortAndSplat (the technique's
  // image of what clipping changes).
  void setSpherical(bool spherical);

 private:
  BillboardSettings billboard_;
  SurfaceLighting surface_lighting_;
  const GpuScene* scene_ = nullptr;
  const ParticleMedium* medium_ = nullptr;
  gl::Program shading_, sort_, splat_;
  gl::Buffer source_, order_;
  gl::VertexArray empty_vertex_array_;
};

}  // namespace gib::rt
