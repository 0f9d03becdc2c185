#include "realtime/technique_parameters.h"

namespace gib::rt {

ParameterSpec atlasParameter(int default_resolution, std::string doc) {
  return integerChoiceParameter("atlas", default_resolution, {64, 128, 256, 512, 1024}, "texels",
                                std::move(doc));
}

ParameterSpec seedParameter(std::string doc) {
  return numericParameter("seed", ParameterType::kInteger, "0", 0, 2147483647, "", std::move(doc));
}

ParameterSpec lightSamplesParameter() {
  return numericParameter("light_samples", ParameterType::kInteger, "16", 1, 4096, "",
                          "points over the area lights, and directions over the sky, each with "
                          "its own shadow test");
}

}  // namespace gib::rt
