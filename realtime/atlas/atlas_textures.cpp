#include "realtime/atlas/atlas_textures.h"

#include "realtime/gl/binding_plan_shared.h"

#include <glm/vec4.hpp>

namespace gib::rt::atlas {

namespace {

gl::Texture uploadMap(int resolution, const std::vector<glm::vec4>& values) {
  gl::Texture texture = gl::Texture::make2D(GL_RGBA32F, resolution, resolution);
  texture.upload(&values[0].x, GL_RGBA);
  return texture;
}

}  // namespace

AtlasTextures::AtlasTextures(const AtlasTexels& baked, const std::vector<AtlasTriangle>& triangles,
                             const scene::Scene& scene)
    : resolution_(baked.resolution) {
  const std::size_t n = baked.texels.size();
  std::vector<glm::vec4> position(n, glm::vec4(0.0f)), normal(n, glm::vec4(0.0f)),
      albedo(n, glm::vec4(0.0f)), emission(n, glm::vec4(0.0f));
  for (std::size_t i = 0; i < n; ++i) {
    const AtlasTexel& texel = baked.texels[i];
    if (!texel.inChart()) continue;
    const scene::Material& material =
        scene.materials[triangles[std::size_t(texel.triangle)].material];
    position[i] = glm::vec4(texel.position, 1.0f);
    normal[i] = glm::vec4(texel.normal, texel.area);
    // Diffuse-only: a Phong material's specular lobe is left out (the technique's approximation).
    albedo[i] = glm::vec4(material.diffuse, 0.0f);
    emission[i] = glm::vec4(material.emission, 0.0f);
  }
  position_ = uploadMap(resolution_, position);
  normal_ = uploadMap(resolution_, normal);
  albedo_ = uploadMap(resolution_, albedo);
  emission_ = uploadMap(resolution_, emission);
}

void AtlasTextures::bind() const {
  position_.bind(gpu::kAtlasPositionUnit);
  normal_.bind(gpu::kAtlasNormalUnit);
  albedo_.bind(gpu::kAtlasAlbedoUnit);
  emission_.bind(gpu::kAtlasEmissionUnit);
}

std::vector<glm::vec3> atlasTexelValues(const image::Image& image) {
  const int r = image.height();
  std::vector<glm::vec3> values(std::size_t(image.width()) * std::size_t(r));
  for (int y = 0; y < r; ++y)  // the image's rows run top to bottom, GL's bottom to top
    for (int x = 0; x < image.width(); ++x) {
      const float* v = image.pixel(x, r - 1 - y);
      values[std::size_t(y * image.width() + x)] = {v[0], v[1], v[2]};
    }
  return values;
}

}  // namespace gib::rt::atlas
