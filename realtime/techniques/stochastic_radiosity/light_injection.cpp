#include "realtime/techniques/stochastic_radiosity/light_injection.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/shader_library.h"
#include "realtime/techniques/direct/light_samples.h"
#include "realtime/techniques/direct/shadow_maps.h"

#include <glm/gtc/type_ptr.hpp>

namespace gib::rt {

int injectDirectLight(const GpuScene& scene, const atlas::AtlasTextures& atlas,
                      const gl::Framebuffer& source) {
  // Spot and directional lights only: no area samples (emitters are in the atlas), no sky.
  const std::vector<LightSample> samples = makeLightSamples(scene.scene(), {}, 0, 0, 0.0f);
  if (samples.empty()) return 0;
  ShadowSettings settings;
  settings.filter = ShadowFilter::kPcf;
  settings.size = 1024;  // once per run, so a fine map costs little
  ShadowMaps shadow_maps(settings, scene);
  auto program = [&](LightSampleKind kind) {
    gl::Program p = gl::buildProgram(
        {{GL_VERTEX_SHADER, "shaders/fullscreen.vert.glsl"},
         {GL_FRAGMENT_SHADER, "techniques/stochastic_radiosity/inject_light.frag.glsl"}},
        shadow_maps.defines(kind));
    shadow_maps.setLookupConstants(p);
    return p;
  };
  const gl::Program point = program(LightSampleKind::kPoint);
  const gl::Program directional = program(LightSampleKind::kDirectional);
  gl::PassProfiler unmeasured;  // prepare() is timed as a whole; passes outside a frame are no-ops
  gl::VertexArray empty;
  for (const LightSample& sample : samples) {
    shadow_maps.render(scene, sample, unmeasured);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_TEST);
    const gl::Program& p = sample.kind == LightSampleKind::kPoint ? point : directional;
    p.use();
    shadow_maps.bindForLookup(p, sample);
    glUniform3fv(p.uniform("u_light_intensity"), 1, glm::value_ptr(sample.intensity));
    glUniform1f(p.uniform("u_cos_cone"), sample.cos_cone);
    glUniform1f(p.uniform("u_exponent"), sample.exponent);
    atlas.bind();
    source.bind();
    glViewport(0, 0, atlas.resolution(), atlas.resolution());
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    empty.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_BLEND);
  }
  return int(samples.size());
}

}  // namespace gib::rt
