// What most techniques draw before their own light: the camera's G-buffer, the emitters and sky
// it sees, and the direct light of every light sample with shadow maps (book Ch. 4). `direct` is
// this block alone; a technique that adds indirect light (a gather, a cache, a volume, light path
// maps) or a medium draws it first and adds its own passes after. One block, so that every
// technique's direct light, parameters and pass names are the same, and a comparison between two
// techniques measures what they add.
#pragma once

#include "common/parameters.h"
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/lighting/direct_lighting.h"
#include "realtime/pass_declarations.h"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib::rt {

class GpuScene;
class RenderTarget;
namespace gl {
class PassProfiler;
}

class SurfaceLighting {
 public:
  // The shadow-map parameters and `light_samples` (directLightingParameters).
  static ParameterTable parameters();
  // Declares the G-buffer pass and DirectLighting's passes under "frame", with one shading pass
  // per entry of `view_passes` (name, description) for views the caller adds (probe cube maps).
  static void declarePasses(
      PassDeclarations& passes,
      const std::vector<std::pair<std::string_view, std::string>>& view_passes = {});

  // `area_lights` false leaves emissive triangles to the caller (DirectLighting).
  explicit SurfaceLighting(const ParameterValues& parameters, bool area_lights = true);
  SurfaceLighting(const ShadowSettings& settings, int light_samples, bool area_lights = true);

  // The G-buffer at the output size, the light samples and their shadow maps.
  void prepare(const GpuScene& scene, int width, int height);

  // The G-buffer, and what the camera sees of emitters and the sky written into `target`
  // (overwriting it).
  void drawSurfaces(const GpuScene& scene, const RenderTarget& target, gl::PassProfiler& profiler);
  // The direct light added into `target` (the camera view, when `target` is given) and into
  // `views`; `after_batch` as DirectLighting::addDirect.
  void addDirect(const GpuScene& scene, const RenderTarget* target, gl::PassProfiler& profiler,
                 std::vector<LitView> views = {},
                 const DirectLighting::AfterBatch& after_batch = {});
  // drawSurfaces, then addDirect into `target`: the image of `direct`.
  void render(const GpuScene& scene, const RenderTarget& target, gl::PassProfiler& profiler);

  const GBuffer& gbuffer() const { return *gbuffer_; }
  GBuffer& gbuffer() { return *gbuffer_; }  // to draw it again outside a frame
  DirectLighting& lighting() { return lighting_; }
  const DirectLighting& lighting() const { return lighting_; }

 private:
  DirectLighting lighting_;
  std::optional<GBuffer> gbuffer_;
};

}  // namespace gib::rt
