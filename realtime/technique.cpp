#include "realtime/technique.h"

#include "common/input_error.h"
#include "common/join.h"
#include "realtime/techniques/direct/direct_technique.h"
#include "realtime/techniques/distance_map_gather/distance_map_gather_technique.h"
#include "realtime/techniques/distance_map_specular/distance_map_specular_technique.h"
#include "realtime/techniques/environment_map/environment_map_technique.h"
#include "realtime/techniques/environment_shadows/environment_shadows_technique.h"
#include "realtime/techniques/gpu_ray_tracing/gpu_ray_tracing_technique.h"
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_technique.h"
#include "realtime/techniques/illumination_network/illumination_network_technique.h"
#include "realtime/techniques/irradiance_cache/irradiance_cache_technique.h"
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_technique.h"
#include "realtime/techniques/irradiance_volume/irradiance_volume_technique.h"
#include "realtime/techniques/jittered_light_sampling/jittered_light_sampling_technique.h"
#include "realtime/techniques/light_path_map/light_path_map_technique.h"
#include "realtime/techniques/obscurances/obscurances_technique.h"
#include "realtime/techniques/prt/prt_technique.h"
#include "realtime/techniques/spherical_billboards/spherical_billboards_technique.h"
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_technique.h"

#include "scene/scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

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
                                                       illuminationNetworkTechniqueInfo(),
                                                       obscurancesTechniqueInfo(),
                                                       gpuRayTracingTechniqueInfo(),
                                                       distanceMapSpecularTechniqueInfo(),
                                                       distanceMapGatherTechniqueInfo(),
                                                       environmentMapTechniqueInfo(),
                                                       prtTechniqueInfo(),
                                                       environmentShadowsTechniqueInfo()};
  return catalogue;
}

std::string_view needName(TechniqueNeed need) {
  switch (need) {
    case TechniqueNeed::kRayCaster:
      return "ray caster";
    case TechniqueNeed::kMedium:
      return "participating medium";
    case TechniqueNeed::kSpecularMaterials:
      return "specular materials";
    case TechniqueNeed::kEnvironmentLight:
      return "environment light";
    case TechniqueNeed::kShadedObject:
      return "a non-emitting object";
  }
  return "?";
}

const DeclaredOutput* findDeclaredOutput(const std::vector<DeclaredOutput>& declared,
                                         std::string_view name) {
  constexpr std::string_view kFamily = "<n>";
  for (const DeclaredOutput& output : declared) {
    const std::string_view pattern = output.name;
    if (pattern == name) return &output;
    if (!pattern.ends_with(kFamily)) continue;
    const std::string_view prefix = pattern.substr(0, pattern.size() - kFamily.size());
    if (!name.starts_with(prefix) || name.size() == prefix.size()) continue;
    const std::string_view number = name.substr(prefix.size());
    if (number.front() != '0' && std::all_of(number.begin(), number.end(), [](char c) {
          return std::isdigit(static_cast<unsigned char>(c));
        }))
      return &output;
  }
  return nullptr;
}

bool TechniqueInfo::hasNeed(TechniqueNeed need) const {
  return std::find(needs.begin(), needs.end(), need) != needs.end();
}

bool TechniqueInfo::rendersSpecularMaterials() const {
  return renders_specular_materials || hasNeed(TechniqueNeed::kSpecularMaterials);
}

bool needsSceneFeatures(const TechniqueInfo& info) {
  return std::any_of(info.needs.begin(), info.needs.end(),
                     [](TechniqueNeed need) { return need != TechniqueNeed::kRayCaster; });
}

std::optional<std::string> missingNeed(const TechniqueInfo& info, const scene::Scene& scene,
                                       const TechniqueServices& services) {
  if (info.hasNeed(TechniqueNeed::kRayCaster) && !services.ray_caster)
    return fmt::format(
        "technique '{}' traces rays with the harness's ray caster, which this caller did not "
        "lend; run it through `gibench render` or `gibench run`",
        info.name);
  return missingSceneNeed(info, scene);
}

namespace {

// The techniques that render environment maps, from the catalogue, for the refusal's fix.
std::string environmentMapTechniqueNames() {
  std::vector<std::string> names;
  for (const TechniqueInfo& info : techniqueCatalogue())
    if (info.renders_environment_map) names.push_back(info.name);
  return joinNames(names, ", ");
}

}  // namespace

std::optional<std::string> missingSceneNeed(const TechniqueInfo& info, const scene::Scene& scene) {
  // The shading passes know Lambert and Phong only: a technique that does not say it renders
  // mirrors or glass would draw them as diffuse surfaces, a wrong image without an error.
  if (scene.hasIdealSpecular() && !info.rendersSpecularMaterials())
    return fmt::format(
        "technique '{}' does not render ideal mirrors or glass and scene '{}' has them; use the "
        "reference, or a scene without them",
        info.name, scene.name);
  if (!scene.environment.empty() && !info.renders_environment_map)
    return fmt::format(
        "technique '{}' does not render environment maps and scene '{}' has one; use the "
        "reference, {}, or a scene without a map",
        info.name, scene.name, environmentMapTechniqueNames());
  for (TechniqueNeed need : info.needs) {
    switch (need) {
      case TechniqueNeed::kRayCaster:
        continue;
      case TechniqueNeed::kMedium:
        if (!scene.medium.empty()) continue;
        return fmt::format(
            "technique '{}' renders a participating medium and scene '{}' has none; use scene "
            "'cloud' or a scene file with particles",
            info.name, scene.name);
      case TechniqueNeed::kSpecularMaterials:
        if (scene.hasIdealSpecular()) continue;
        return fmt::format(
            "technique '{}' renders ideal mirrors or glass and scene '{}' has no such material; "
            "give it a scene with one",
            info.name, scene.name);
      case TechniqueNeed::kEnvironmentLight:
        if (scene.hasEnvironmentLight()) continue;
        return fmt::format(
            "technique '{}' is lit by an environment and scene '{}' has no sky; give it a scene "
            "with a sky",
            info.name, scene.name);
      case TechniqueNeed::kShadedObject:
        if (std::any_of(scene.meshes.begin(), scene.meshes.end(), [&](const scene::Mesh& mesh) {
              return !mesh.triangles.empty() && !scene.materials[mesh.material].isEmissive();
            }))
          continue;
        return fmt::format(
            "technique '{}' shades one object of the scene and scene '{}' has no mesh that does "
            "not emit; give it a scene with a diffuse or glossy object",
            info.name, scene.name);
    }
  }
  return std::nullopt;
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
