#include "realtime/technique.h"

#include "common/input_error.h"
#include "common/join.h"
#include "realtime/techniques/direct/direct_technique.h"
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_technique.h"
#include "realtime/techniques/illumination_network/illumination_network_technique.h"
#include "realtime/techniques/irradiance_cache/irradiance_cache_technique.h"
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_technique.h"
#include "realtime/techniques/irradiance_volume/irradiance_volume_technique.h"
#include "realtime/techniques/jittered_light_sampling/jittered_light_sampling_technique.h"
#include "realtime/techniques/light_path_map/light_path_map_technique.h"
#include "realtime/techniques/spherical_billboards/spherical_billboards_technique.h"
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_technique.h"

#include <fmt/format.h>

namespace gib::rt {

const std::vector<TechniqueInfo>& techniqueCatalogue() {
  static const std::vector<TechniqueInfo> catalogue = {directTechniqueInfo(),
                                                       stochasticRadiosityTechniqueInfo(),
                                                       irradianceVolumeTechniqueInfo(),
                                                       lightPathMapTechniqueInfo(),
                                                       jitteredLightSamplingTechniqueInfo(),
                                                       hemisphericalGatherTechniqueInfo(),
                                                       irradianceCacheTechniqueInfo(),
                                                       irradianceCacheSplattingTechniqueInfo(),
                                                       sphericalBillboardsTechniqueInfo(),
                                                       illuminationNetworkTechniqueInfo()};
  return catalogue;
}

const TechniqueInfo& findTechnique(std::string_view name) {
  for (const TechniqueInfo& info : techniqueCatalogue())
    if (info.name == name) return info;
  const std::string names =
      "reference, " +
      joinNames(techniqueCatalogue(), ", ", [](const TechniqueInfo& info) { return info.name; });
  throw InputError(fmt::format(
      "unknown technique '{}'; available: {} (see `gibench list techniques`)", name, names));
}

}  // namespace gib::rt
