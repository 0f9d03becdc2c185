#include "realtime/technique_output.h"

#include "image/display.h"
#include "scene/output_metadata.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace gib::rt {

std::string parametersJson(const ParameterValues& values) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const auto& [key, value] : values.canonical()) json[key] = value;
  return json.dump();
}

image::Metadata techniqueOutputMetadata(const scene::Scene& scene, const TechniqueInfo& info,
                                        const ParameterValues& parameters,
                                        const TechniqueRunSettings& settings,
                                        const TechniqueRunResult& result, double frame_ms_median) {
  image::Metadata metadata =
      scene::outputMetadata(scene, info.name, parametersJson(parameters), settings.width,
                            settings.height, result.path_class);
  metadata.merge(techniqueRunMetadata(result, settings));
  metadata["gibench/frame_ms_median"] = fmt::format("{:.3f}", frame_ms_median);
  metadata["gibench/layers"] = "RGB: radiance of the last measured frame (linear Rec.709)";
  return metadata;
}

std::filesystem::path writeTechniqueOutputs(const std::filesystem::path& exr_path,
                                            const TechniqueRunResult& result,
                                            const image::Metadata& metadata) {
  image::writeExr(exr_path, {{"", result.image}}, metadata);
  const std::filesystem::path png = std::filesystem::path(exr_path).replace_extension(".png");
  image::writePng(png, result.image);
  return png;
}

}  // namespace gib::rt
