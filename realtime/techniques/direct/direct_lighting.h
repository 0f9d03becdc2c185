// Direct illumination from shadow-mapped light samples, added into one or more G-buffers' targets
// (book Ch. 4): what `direct` renders for the camera, and what the irradiance volume renders for
// its probes' cube maps and its camera in the same loop, so that each light sample's shadow map
// is drawn once per frame however many views it lights.
#pragma once

#include "realtime/gbuffer.h"
#include "realtime/gl/objects.h"
#include "realtime/gpu_scene.h"
#include "realtime/render_target.h"
#include "realtime/techniques/direct/light_samples.h"
#include "realtime/techniques/direct/shadow_maps.h"

#include <optional>
#include <string>
#include <vector>

namespace gib::rt {

namespace gl {
class PassProfiler;
}

// A G-buffer to light and the target its light is added to. `pass` names its shading pass in
// the profile ("shading" for the camera).
struct LitView {
  const GBuffer* gbuffer = nullptr;
  const RenderTarget* target = nullptr;
  std::string pass = "shading";
  bool normals_face_viewer = false;  // a probe view of GBuffer::renderViews
};

class DirectLighting {
 public:
  DirectLighting(const ShadowSettings& settings, int light_samples);

  // Places the light samples and builds the shadow maps and programs.
  void prepare(const GpuScene& scene);

  // Writes what the camera sees of emitters and the sky into `target` (overwriting it).
  void writeEmission(const GpuScene& scene, const GBuffer& gbuffer, const RenderTarget& target,
                     gl::PassProfiler& profiler);
  // For each light sample: its shadow map, then its light added into every view (additive
  // blending). Inside a pass named "lights".
  void addDirect(const GpuScene& scene, const std::vector<LitView>& views,
                 gl::PassProfiler& profiler);

  std::size_t sampleCount() const { return samples_.size(); }
  // Moves every point sample (area-light points, spot and point lights) by `offset` for the
  // next addDirect: a light that moves between frames. Zero restores the scene's lights.
  void setLightOffset(const glm::vec3& offset) { light_offset_ = offset; }

 private:
  const gl::Program& shadeProgram(LightSampleKind kind) const {
    return kind == LightSampleKind::kPoint ? shade_point_ : shade_directional_;
  }
  void drawFullScreen(const RenderTarget& target) const;

  ShadowSettings shadow_settings_;
  int light_samples_;
  std::vector<LightSample> samples_;
  glm::vec3 light_offset_{0.0f};
  std::optional<ShadowMaps> shadow_maps_;
  gl::Program emission_, shade_point_, shade_directional_;
  gl::VertexArray empty_vertex_array_;  // core profile draws need one bound
};

}  // namespace gib::rt
