#include "realtime/distance_map/distance_map_frame.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/render_target.h"

namespace gib::rt {

void declareDistanceMapPasses(PassDeclarations& passes,
                              const DistanceMapPassDescriptions& descriptions) {
  SurfaceLighting::declarePasses(passes, {{kMapLightPass, "the batch's light in the maps' views"}});
  passes.add(passPath({kFramePass, kMapViewsPass}), descriptions.map_views);
  passes.add(passPath({kFramePass, kComposeMapsPass}), descriptions.compose_maps);
}

void drawSurfacesAndMaps(SurfaceLighting& surface_lighting, const GpuScene& scene,
                         DistanceMaps& maps, int rounds, Frame& frame) {
  gl::PassProfiler& profiler = frame.profiler;
  surface_lighting.drawSurfaces(scene, frame.target, profiler);
  {
    auto pass = profiler.pass(kMapViewsPass);
    maps.rasterise(scene);
    maps.clearLight();
  }
  surface_lighting.addDirect(scene, &frame.target, profiler, {maps.litView(kMapLightPass)});
  auto pass = profiler.pass(kComposeMapsPass);
  maps.compose(scene, rounds);
}

std::vector<image::Image> drawCaptured(int width, int height, int extra,
                                       const std::function<void()>& draw) {
  std::vector<gl::Texture> targets;
  gl::Framebuffer framebuffer;
  for (int i = 0; i <= extra; ++i) {
    targets.push_back(gl::Texture::make2D(GL_RGBA32F, width, height));
    framebuffer.attachColor(i, targets.back());
  }
  framebuffer.setDrawBuffers(extra + 1);
  framebuffer.checkComplete();
  framebuffer.bind();
  const float zero[4] = {0, 0, 0, 0};
  for (int i = 0; i <= extra; ++i) glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, i, zero);
  {
    const gl::PipelineScope viewport({.viewport = gl::PixelRect{0, 0, width, height}});
    draw();
  }
  std::vector<image::Image> images;
  for (std::size_t i = 0; i < targets.size(); ++i)
    images.push_back(gl::readTexture(targets[i], i == 0 ? 3 : 4));
  return images;
}

image::Image unfoldCubes(const gl::Texture& cubes) {
  const int n = cubes.width(), count = cubes.depth() / 6;
  std::vector<float> texels(std::size_t(n) * n * 6 * count * 4);
  glGetTextureImage(cubes.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)),
                    texels.data());
  image::Image strip(6 * n, count * n, 3);
  for (int layer = 0; layer < 6 * count; ++layer)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const float* texel = &texels[((std::size_t(layer) * n + j) * n + i) * 4];
        // Texel row j counts from the bottom (cube_faces.h); the image's from the top.
        float* out = strip.pixel((layer % 6) * n + i, (layer / 6) * n + (n - 1 - j));
        for (int c = 0; c < 3; ++c) out[c] = texel[c];
      }
  return strip;
}

}  // namespace gib::rt
