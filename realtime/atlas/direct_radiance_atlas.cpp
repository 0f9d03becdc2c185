#include "realtime/atlas/direct_radiance_atlas.h"

#include "common/elapsed.h"
#include "realtime/atlas/atlas_lighting.h"
#include "realtime/lighting/light_samples.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>

namespace gib::rt::atlas {

DirectRadianceAtlas makeDirectRadianceAtlas(const GpuScene& scene, int resolution,
                                            int light_samples) {
  const auto start = std::chrono::steady_clock::now();
  DirectRadianceAtlas atlas;
  atlas.triangles = atlasTriangles(scene.scene());
  atlas.layout = layoutAtlas(atlas.triangles, resolution);
  atlas.textures.emplace(bakeAtlasTexels(atlas.triangles, atlas.layout), atlas.triangles,
                         scene.scene());
  atlas.radiance = gl::Texture::make2D(GL_RGBA32F, resolution, resolution);
  atlas.radiance.setFilter(GL_LINEAR, GL_LINEAR);
  const float zero[4] = {0, 0, 0, 0};
  glClearTexImage(atlas.radiance.id(), 0, GL_RGBA, GL_FLOAT, zero);
  gl::Framebuffer target;
  target.attachColor(0, atlas.radiance);
  target.setDrawBuffers(1);
  target.checkComplete();
  const float extent = std::max(glm::length(scene.boundsMax() - scene.boundsMin()), 1e-6f);
  const std::vector<LightSample> samples = makeLightSamples(
      scene.scene(), scene.emitters(), light_samples, light_samples, 1e-3f * extent);
  if (!samples.empty()) {
    ShadowSettings settings;
    settings.filter = ShadowFilter::kPcf;
    settings.size = 512;
    AtlasLighting(settings, scene, samples.size()).add(scene, samples, *atlas.textures, target);
  }
  glFinish();
  atlas.milliseconds = millisecondsSince(start);
  return atlas;
}

}  // namespace gib::rt::atlas
