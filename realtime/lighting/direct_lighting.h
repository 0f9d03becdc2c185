// Direct illumination from shadow-mapped light samples, added into one or more G-buffers' targets
// (book Ch. 4): what `direct` renders for the camera, and what the irradiance volume renders for
// its probes' cube maps and its camera in the same loop, so that each light sample's shadow map
// is drawn once per frame however many views it lights. Samples go in batches whose shadow maps
// are one array texture, so each view is lit by one pass per batch, not one per sample.
#pragma once

#include "common/parameters.h"
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/lighting/environment_texture.h"
#include "realtime/lighting/light_samples.h"
#include "realtime/lighting/shadow_maps.h"
#include "realtime/pass_declarations.h"
#include "realtime/render_target.h"
#include "realtime/technique.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gib::rt {

namespace gl {
class PassProfiler;
}

// The passes DirectLighting opens, inside its caller's pass.
inline constexpr std::string_view kEmissionPass = "emission";
inline constexpr std::string_view kLightsPass = "lights";
inline constexpr std::string_view kShadingPass = "shading";  // the camera view's light

// A G-buffer to light and the target its light is added to. `pass` names its shading pass in
// the profile, inside kLightsPass (kShadingPass for the camera).
struct LitView {
  const GBuffer* gbuffer = nullptr;
  const RenderTarget* target = nullptr;
  std::string_view pass = kShadingPass;
  bool normals_face_viewer = false;  // a probe view of GBuffer::renderViews
};

class DirectLighting {
 public:
  // `area_lights` false leaves emissive triangles to the caller (jittered light sampling samples
  // them by rasterization): the samples are then the spot, directional and sky lights only.
  DirectLighting(const ShadowSettings& settings, int light_samples, bool area_lights = true);

  // Declares the passes writeEmission and addDirect open under `parent`, with one shading pass
  // per entry of `view_passes` (name, description) besides the camera's.
  static void declarePasses(
      PassDeclarations& passes, std::string_view parent,
      const std::vector<std::pair<std::string_view, std::string>>& view_passes = {});

  // GLSL defines added to the camera's shading passes, set before prepare(): the particle
  // techniques attenuate each sample by their medium (realtime/particles/).
  void setShadingDefines(std::string defines) { shading_defines_ = std::move(defines); }
  // Whether the light samples include the environment (a constant sky's directions, an
  // environment map's drawn by importance), set before prepare(): a technique that lights by the
  // environment itself (environment_map's convolved maps) leaves it out, as `area_lights` false
  // leaves the emitters.
  void setEnvironmentSamples(bool enabled) { environment_samples_ = enabled; }
  // Light samples the caller adds after the scene's, set before prepare(): environment_shadows'
  // cells of the environment (book §4.2.3), each a directional sample with its shadow map.
  void setExtraSamples(std::vector<LightSample> samples) { extra_samples_ = std::move(samples); }
  // Places the light samples and builds the shadow maps and programs.
  void prepare(const GpuScene& scene);

  // Writes what the camera sees of emitters and the sky into `target` (overwriting it).
  void writeEmission(const GpuScene& scene, const GBuffer& gbuffer, const RenderTarget& target,
                     gl::PassProfiler& profiler);
  // What else reads a batch's shadow maps while they are current (light path maps weigh their
  // entry points with them, book §8.4.1): called after the views are lit; a program reads the
  // batch through ShadowMaps::bindForLookup.
  using AfterBatch = std::function<void(const ShadowMaps&)>;

  // For each batch of light samples: their shadow maps, then their light added into every view
  // (one additive pass per view), then `after_batch`. Inside a pass named kLightsPass.
  void addDirect(const GpuScene& scene, const std::vector<LitView>& views,
                 gl::PassProfiler& profiler, const AfterBatch& after_batch = {});

  std::size_t sampleCount() const { return samples_.size(); }
  // The shadow maps addDirect draws (after prepare), for programs that read them in AfterBatch.
  const ShadowMaps& shadowMaps() const { return *shadow_maps_; }
  // The scene's environment map as the emission pass shows it (after prepare), or nullptr for a
  // scene without one: a technique that lights by the map reads the same upload.
  const EnvironmentTexture* environment() const { return environment_ ? &*environment_ : nullptr; }
  // Moves every point sample (area-light points, spot and point lights) by `offset` for the
  // next addDirect: a light that moves between frames. Zero restores the scene's lights.
  void setLightOffset(const glm::vec3& offset) { light_offset_ = offset; }

 private:
  const gl::FullScreenPass& shadePass(LightSampleKind kind) const {
    return kind == LightSampleKind::kPoint ? shade_point_ : shade_directional_;
  }

  ShadowSettings shadow_settings_;
  int light_samples_;
  bool area_lights_;
  bool environment_samples_ = true;
  std::vector<LightSample> extra_samples_;
  std::vector<LightSample> samples_;
  glm::vec3 light_offset_{0.0f};
  std::optional<ShadowMaps> shadow_maps_;
  std::optional<EnvironmentTexture> environment_;
  std::string shading_defines_;
  gl::FullScreenPass emission_, shade_point_, shade_directional_;
};

// Where a light with motion=light is at this frame: it travels a circle of a twentieth of the
// scene's extent once over the run and is back at rest (offset zero) on the last frame, so every
// frame relights as for a moving light and the measured image is the scene's.
glm::vec3 movingLightOffset(const GpuScene& scene, const Frame& frame);

// The shadow-map parameters (filter, sizes, light samples) of every technique that adds direct
// light with DirectLighting, and the settings they give.
ParameterTable directLightingParameters();
ShadowSettings shadowSettings(const ParameterValues& values);

}  // namespace gib::rt
