#include "support/technique_frame.h"

namespace gib::test {

rt::TechniqueRunResult renderOneFrame(const scene::Scene& scene, const std::string& technique,
                                      const std::vector<std::string>& set, int size) {
  const rt::TechniqueInfo& info = rt::findTechnique(technique);
  const ParameterValues values = parseParameters(info.parameters, set, technique);
  rt::TechniqueRunSettings settings;
  settings.width = settings.height = size;
  settings.warmup_frames = 0;
  settings.frames = 1;
  settings.context.debug = true;
  return rt::runTechnique(scene, info, values, settings);
}

ref::RenderResult renderClassReference(const scene::Scene& scene, int size, std::uint32_t spp,
                                       scene::PathClass path_class) {
  ref::RenderSettings settings;
  settings.width = settings.height = size;
  settings.spp = spp;
  settings.path_class = path_class;
  return ref::renderReference(scene, settings);
}

}  // namespace gib::test
