#include "realtime/techniques/stochastic_radiosity/light_injection.h"

#include "realtime/gl/fullscreen_pass.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/lighting/light_samples.h"
#include "realtime/lighting/shadow_maps.h"

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
  auto injection = [&](LightSampleKind kind) {
    gl::FullScreenPass pass("realtime/atlas/atlas_light.frag.glsl", shadow_maps.defines(kind));
    shadow_maps.setLookupConstants(pass.program());
    return pass;
  };
  const gl::FullScreenPass point = injection(LightSampleKind::kPoint);
  const gl::FullScreenPass directional = injection(LightSampleKind::kDirectional);
  gl::PassProfiler unmeasured;  // prepare() is timed as a whole; passes outside a frame are no-ops
  for (const LightSample& sample : samples) {
    shadow_maps.render(scene, sample, unmeasured);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_TEST);
    const gl::FullScreenPass& pass = sample.kind == LightSampleKind::kPoint ? point : directional;
    const gl::Program& p = pass.program();
    p.use();
    shadow_maps.bindForLookup(p, sample);
    setLightSampleUniforms(p, sample);
    atlas.bind();
    source.bind();
    glViewport(0, 0, atlas.resolution(), atlas.resolution());
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    pass.draw();
    glDisable(GL_BLEND);
  }
  return int(samples.size());
}

}  // namespace gib::rt
