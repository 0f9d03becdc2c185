// The baked atlas (atlas_layout.h) on the GPU: one RGBA32F map per surface property, texel for
// texel, read with texelFetch by passes that run over the atlas and bilinearly by views of it.
#pragma once

#include "image/image.h"
#include "realtime/atlas/atlas_layout.h"
#include "realtime/gl/objects.h"

#include <glm/vec3.hpp>

#include <vector>

namespace gib::rt::atlas {

class AtlasTextures {
 public:
  AtlasTextures(const AtlasTexels& texels, const std::vector<AtlasTriangle>& triangles,
                const scene::Scene& scene);

  int resolution() const { return resolution_; }
  const gl::Texture& position() const { return position_; }
  const gl::Texture& normal() const { return normal_; }
  const gl::Texture& albedo() const { return albedo_; }
  const gl::Texture& emission() const { return emission_; }
  // Binds the four maps to their units of gl/binding_plan_shared.h (atlas_maps.glsl's names).
  void bind() const;

 private:
  int resolution_;
  gl::Texture position_, normal_, albedo_, emission_;
};

// An atlas-sized RGB image as read back (image::Image: top row first) turned into one value per
// texel in the order of AtlasTexels (row 0 at the bottom, GL's), so that tests and techniques
// pair each value with its texel.
std::vector<glm::vec3> atlasTexelValues(const image::Image& image);

}  // namespace gib::rt::atlas
