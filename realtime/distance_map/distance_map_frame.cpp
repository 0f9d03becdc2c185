#include "realtime/distance_map/distance_map_frame.h"

#include "realtime/gl/pass_profiler.h"
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

}  // namespace gib::rt
