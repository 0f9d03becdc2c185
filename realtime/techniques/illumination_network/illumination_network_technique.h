// `illumination_network`: multiple scattering in a particle medium by iterating the book's
// illumination network (§9.6). At preparation: D directions shared by all particles, the
// visibility network V (for each particle and direction the particle seen first, and its
// opacity), the lights' volume shadows and the emission array E. Each iteration (step) scatters
// the incoming radiance I once more (scattering pass) and gathers it along V's chains (transport
// pass); frames shade each particle towards the eye from I and splat spherical billboards. See
// README.md beside this file.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/particles/particle_compositor.h"
#include "realtime/particles/particle_medium.h"
#include "realtime/particles/volume_shadow.h"
#include "realtime/technique.h"
#include "realtime/techniques/illumination_network/illumination_network_shared.h"

#include <optional>
#include <vector>

namespace gib::rt {

class IlluminationNetworkTechnique final : public Technique {
 public:
  explicit IlluminationNetworkTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  bool iterative() const override { return true; }
  void step(gl::PassProfiler& profiler) override;
  int iterations() const override { return iterations_; }
  // Iteration k's incoming radiance holds paths of up to k scattering events; the view shading
  // scatters once more.
  scene::PathClass pathClass() const override { return pathClassAfter(iterations_); }
  scene::PathClass pathClassAfter(int iterations) const override { return {0, iterations + 1}; }
  std::vector<TechniqueStatistic> statistics() const override;

  // The network's arrays read back, [particle × D + direction] (tests).
  std::vector<gpu::NetworkLink> visibility() const;
  std::vector<glm::vec4> emission() const;
  std::vector<glm::vec4> incoming() const;
  const std::vector<glm::vec4>& directions() const { return directions_; }
  // Each particle's transmittance towards each light, [particle × lights + light].
  std::vector<float> lightTransmittance() const;

 private:
  void dispatch(const gl::Program& program) const;
  void transport();

  int direction_count_;
  ParticleCompositor compositor_;
  std::optional<ParticleMedium> medium_;
  std::vector<glm::vec4> directions_;
  gl::Program visibility_program_, emission_program_, scattering_program_, transport_program_;
  gl::Texture phase_matrix_;
  gl::Buffer directions_buffer_, visibility_, transmittance_, emission_, source_, incoming_;
  int iterations_ = 0;
  double visibility_ms_ = 0, emission_ms_ = 0, mean_chain_ = 0;
};

TechniqueInfo illuminationNetworkTechniqueInfo();

}  // namespace gib::rt
