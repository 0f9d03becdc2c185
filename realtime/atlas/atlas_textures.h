// The baked atlas (atlas_layout.h) on the GPU: one RGBA32F map per surface property, texel for
// texel, read with texelFetch by passes that run over the atlas and bilinearly by views of it.
#pragma once

#include "realtime/atlas/atlas_layout.h"
#include "realtime/gl/objects.h"

namespace gib::rt::atlas {

// Texture units and GLSL names of atlas/atlas_maps.glsl.
inline constexpr GLuint kPositionUnit = 8;   // xyz world sample point, w 1 inside a chart, else 0
inline constexpr GLuint kNormalUnit = 9;     // xyz unit normal, w world area of the texel
inline constexpr GLuint kAlbedoUnit = 10;    // rgb diffuse reflectance ρ
inline constexpr GLuint kEmissionUnit = 11;  // rgb emitted radiance (front side)

class AtlasTextures {
 public:
  AtlasTextures(const AtlasTexels& texels, const std::vector<AtlasTriangle>& triangles,
                const scene::Scene& scene);

  int resolution() const { return resolution_; }
  const gl::Texture& position() const { return position_; }
  const gl::Texture& normal() const { return normal_; }
  const gl::Texture& albedo() const { return albedo_; }
  const gl::Texture& emission() const { return emission_; }
  // Binds the four maps to their units.
  void bind() const;

 private:
  int resolution_;
  gl::Texture position_, normal_, albedo_, emission_;
};

}  // namespace gib::rt::atlas
