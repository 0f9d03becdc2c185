// A scene's participating medium on the GPU, shared by the particle techniques
// (spherical_billboards, illumination_network): the particles as a storage buffer, the
// Henyey–Greenstein phase as a prepared table (book §9.6.3: "implemented by a texture lookup of
// prepared values"), the directional lights as uniforms, and well-spread direction sets for the
// sky and the illumination network.
#pragma once

#include "realtime/gl/objects.h"
#include "scene/scene.h"

#include <glm/vec4.hpp>

#include <string_view>
#include <vector>

namespace gib::rt {

// `count` unit directions spread evenly over the sphere (a spherical Fibonacci set: equal areas,
// no two directions within a band), in xyz; w holds 0.
std::vector<glm::vec4> sphereDirections(int count);

// The phase function p(cos θ) at gpu::kPhaseTableSize evenly spaced cosines from −1 to 1.
std::vector<float> henyeyGreensteinTable(float g);

// Work groups of gpu::kParticleGroupSize invocations that cover `count` particles (or directions).
GLuint particleGroups(int count);

class ParticleMedium {
 public:
  // Uploads the particles of `scene`. Throws gib::InputError naming `technique` when the scene
  // has none (there would be nothing for the technique to render), or more directional lights
  // than the passes take.
  ParticleMedium(const scene::Scene& scene, std::string_view technique);

  int count() const { return count_; }
  const scene::Rgb& albedo() const { return albedo_; }
  float g() const { return g_; }
  const scene::Rgb& sky() const { return sky_; }
  int lightCount() const { return int(lights_.size()); }
  const std::vector<scene::DirectionalLight>& lights() const { return lights_; }

  const gl::Buffer& particles() const { return particles_; }
  // Binds the particle buffer and the phase table to their slots (particle_shared.h).
  void bind() const;
  // Sets a program's light uniforms (u_light_count, u_light_direction[], u_light_irradiance[]),
  // the albedo (u_albedo) and the sky (u_sky) where it declares them.
  void setUniforms(const gl::Program& program) const;
  // Directions towards each light (opposite to their propagation), for transmittance passes.
  std::vector<glm::vec4> towardsLights() const;

 private:
  int count_ = 0;
  scene::Rgb albedo_{0.0f};
  float g_ = 0;
  scene::Rgb sky_{0.0f};
  std::vector<scene::DirectionalLight> lights_;
  gl::Buffer particles_;
  gl::Texture phase_table_;
};

}  // namespace gib::rt
