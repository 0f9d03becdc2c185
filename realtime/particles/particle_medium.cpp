#include "realtime/particles/particle_medium.h"

#include "common/input_error.h"
#include "realtime/particles/particle_shared.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace gib::rt {

std::vector<glm::vec4> sphereDirections(int count) {
  std::vector<glm::vec4> directions;
  directions.reserve(std::size_t(count));
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / count;  // equal-area bands
    const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * i;
    directions.emplace_back(float(radius * std::cos(phi)), float(z), float(radius * std::sin(phi)),
                            0.0f);
  }
  return directions;
}

std::vector<float> henyeyGreensteinTable(float g) {
  std::vector<float> table(gpu::kPhaseTableSize);
  for (int i = 0; i < gpu::kPhaseTableSize; ++i)
    table[std::size_t(i)] =
        gpu::henyeyGreensteinPhase(-1.0f + 2.0f * float(i) / float(gpu::kPhaseTableSize - 1), g);
  return table;
}

GLuint particleGroups(int count) {
  return GLuint((count + gpu::kParticleGroupSize - 1) / gpu::kParticleGroupSize);
}

ParticleMedium::ParticleMedium(const scene::Scene& scene, std::string_view technique)
    : count_(int(scene.medium.particles.size())),
      albedo_(scene.medium.albedo),
      g_(scene.medium.g),
      sky_(scene.sky_radiance),
      lights_(scene.directional_lights) {
  if (count_ == 0)
    throw InputError(fmt::format(
        "technique '{}' renders a participating medium and scene '{}' has none; use scene "
        "'cloud' or a scene file with particles",
        technique, scene.name));
  if (int(lights_.size()) > gpu::kMaxParticleLights)
    throw InputError(
        fmt::format("technique '{}' takes at most {} directional lights; scene '{}' "
                    "has {}",
                    technique, gpu::kMaxParticleLights, scene.name, lights_.size()));
  std::vector<gpu::GpuParticle> particles;
  particles.reserve(scene.medium.particles.size());
  for (const scene::MediumParticle& p : scene.medium.particles)
    particles.push_back({glm::vec4(p.centre, p.radius), glm::vec4(p.density, 0.0f, 0.0f, 0.0f)});
  particles_ = gl::Buffer::fromVector(particles);
  phase_table_ = gl::Texture::make2D(GL_R32F, gpu::kPhaseTableSize, 1);
  phase_table_.upload(henyeyGreensteinTable(g_).data(), GL_RED);
  phase_table_.setFilter(GL_LINEAR, GL_LINEAR);
  phase_table_.setWrap(GL_CLAMP_TO_EDGE);
}

void ParticleMedium::bind() const {
  particles_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kParticlesBinding);
  phase_table_.bind(gpu::kPhaseTableUnit);
}

void ParticleMedium::setUniforms(const gl::Program& program) const {
  std::vector<glm::vec3> directions, irradiances;
  for (const scene::DirectionalLight& light : lights_) {
    directions.push_back(light.direction);
    irradiances.emplace_back(light.irradiance.r, light.irradiance.g, light.irradiance.b);
  }
  // particle_medium.glsl declares the medium for every pass that includes it; each pass reads
  // what it needs (the illumination network's visibility pass none of it), and the linker drops
  // the rest.
  program.setIfPresent("u_light_count", int(lights_.size()));
  program.setIfPresent("u_light_direction", std::span<const glm::vec3>(directions));
  program.setIfPresent("u_light_irradiance", std::span<const glm::vec3>(irradiances));
  program.setIfPresent("u_albedo", albedo_);
  program.setIfPresent("u_sky", sky_);
}

std::vector<glm::vec4> ParticleMedium::towardsLights() const {
  std::vector<glm::vec4> towards;
  for (const scene::DirectionalLight& light : lights_) towards.emplace_back(-light.direction, 0.0f);
  return towards;
}

}  // namespace gib::rt
