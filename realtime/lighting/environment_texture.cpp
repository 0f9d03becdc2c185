#include "realtime/lighting/environment_texture.h"

#include "realtime/gl/binding_plan_shared.h"
#include "scene/scene.h"

#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <utility>
#include <vector>

namespace gib::rt {

EnvironmentTexture::EnvironmentTexture(const scene::EnvironmentMap& map)
    : map_(map), texture_(gl::Texture::make2D(GL_RGB32F, map.width, map.height)) {
  // Row 0 of the texels (the zenith) is texel row 0, as environment.glsl fetches it.
  texture_.upload(map.texels->data(), GL_RGB);
  // environment.glsl fetches texels by index; nearest sampling states the same for any other
  // reader.
  texture_.setFilter(GL_NEAREST, GL_NEAREST);
}

void EnvironmentTexture::setUniforms(const gl::Program& program) const {
  // EnvironmentMap::toMap turns by −rotation about +y with these float cosine and sine, so the
  // shader's map direction is the reference's to the last bit.
  const float angle = glm::radians(-map_.rotation_deg);
  program.set("u_environment", glm::vec3(std::cos(angle), std::sin(angle), map_.intensity));
}

void EnvironmentTexture::bind() const {
  texture_.bind(gpu::kEnvironmentUnit);
}

scene::EnvironmentMap sceneEnvironment(const scene::Scene& scene, int constant_rows) {
  if (!scene.environment.empty()) return scene.environment;
  if (scene.sky_radiance == scene::Rgb(0.0f)) return {};
  const scene::Rgb& L = scene.sky_radiance;
  std::vector<float> texels;
  texels.reserve(std::size_t(6 * constant_rows * constant_rows));
  for (int t = 0; t < 2 * constant_rows * constant_rows; ++t)
    texels.insert(texels.end(), {L.r, L.g, L.b});
  return scene::makeEnvironmentMap(2 * constant_rows, constant_rows, std::move(texels),
                                   "constant sky");
}

}  // namespace gib::rt
