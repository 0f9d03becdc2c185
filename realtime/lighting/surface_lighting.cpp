#include "realtime/lighting/surface_lighting.h"

#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/render_target.h"

namespace gib::rt {

ParameterTable SurfaceLighting::parameters() {
  return directLightingParameters();
}

void SurfaceLighting::declarePasses(
    PassDeclarations& passes,
    const std::vector<std::pair<std::string_view, std::string>>& view_passes) {
  passes.add(passPath({kFramePass, kGBufferPass}), "what each pixel's primary ray hits");
  DirectLighting::declarePasses(passes, kFramePass, view_passes);
}

SurfaceLighting::SurfaceLighting(const ParameterValues& parameters, bool area_lights)
    : SurfaceLighting(shadowSettings(parameters), parameters.integer("light_samples"),
                      area_lights) {}

SurfaceLighting::SurfaceLighting(const ShadowSettings& settings, int light_samples,
                                 bool area_lights)
    : lighting_(settings, light_samples, area_lights) {}

void SurfaceLighting::prepare(const GpuScene& scene, int width, int height) {
  gbuffer_.emplace(width, height);
  lighting_.prepare(scene);
}

void SurfaceLighting::drawSurfaces(const GpuScene& scene, const RenderTarget& target,
                                   gl::PassProfiler& profiler) {
  gbuffer_->render(scene, &profiler);
  lighting_.writeEmission(scene, *gbuffer_, target, profiler);
}

void SurfaceLighting::addDirect(const GpuScene& scene, const RenderTarget* target,
                                gl::PassProfiler& profiler, std::vector<LitView> views,
                                const DirectLighting::AfterBatch& after_batch) {
  if (target) views.insert(views.begin(), LitView{&*gbuffer_, target});
  lighting_.addDirect(scene, views, profiler, after_batch);
}

void SurfaceLighting::render(const GpuScene& scene, const RenderTarget& target,
                             gl::PassProfiler& profiler) {
  drawSurfaces(scene, target, profiler);
  addDirect(scene, &target, profiler);
}

}  // namespace gib::rt
