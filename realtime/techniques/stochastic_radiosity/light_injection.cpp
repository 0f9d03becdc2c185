#include "realtime/techniques/stochastic_radiosity/light_injection.h"

#include "realtime/atlas/atlas_lighting.h"
#include "realtime/lighting/light_samples.h"

namespace gib::rt {

int injectDirectLight(const GpuScene& scene, const atlas::AtlasTextures& atlas,
                      const gl::Framebuffer& source) {
  // Spot and directional lights only: no area samples (emitters are in the atlas), no sky.
  const std::vector<LightSample> samples = makeLightSamples(scene.scene(), {}, 0, 0, 0.0f);
  if (samples.empty()) return 0;
  ShadowSettings settings;
  settings.filter = ShadowFilter::kPcf;
  settings.size = 1024;  // once per run, so a fine map costs little
  atlas::AtlasLighting lighting(settings, scene, samples.size());
  lighting.add(scene, samples, atlas, source);
  return int(samples.size());
}

}  // namespace gib::rt
