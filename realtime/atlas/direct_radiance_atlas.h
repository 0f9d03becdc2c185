// The directly lit scene as a radiance atlas: every texel's ρ/π times its shadow-mapped direct
// irradiance (no emission: light seen straight from an emitter is direct light, which the frames
// add themselves). What rasterized hemisphere views of the scene see when they gather one bounce
// (hemispherical gathering, irradiance cache splatting). Built at prepare time.
#pragma once

#include "realtime/atlas/atlas_layout.h"
#include "realtime/atlas/atlas_textures.h"
#include "realtime/gl/objects.h"
#include "realtime/gpu_scene/gpu_scene.h"

#include <optional>
#include <vector>

namespace gib::rt::atlas {

struct DirectRadianceAtlas {
  std::vector<AtlasTriangle> triangles;
  AtlasLayout layout;
  std::optional<AtlasTextures> textures;
  gl::Texture radiance;     // RGBA32F, resolution², linear filtering
  double milliseconds = 0;  // to build it, GPU work finished
};

// `light_samples` points over the area lights and directions over the sky, lit with 512² PCF
// shadow maps.
DirectRadianceAtlas makeDirectRadianceAtlas(const GpuScene& scene, int resolution,
                                            int light_samples);

}  // namespace gib::rt::atlas
