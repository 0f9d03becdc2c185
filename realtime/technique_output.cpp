#include "realtime/technique_output.h"

#include "image/display.h"
#include "scene/obscurance.h"
#include "scene/output_metadata.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <stdexcept>

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
  if (result.obscurance) {
    // What the image is of, instead of radiance (docs/rendering.md, "Obscurances").
    metadata["gibench/obscurance"] = scene::describeObscurance(*result.obscurance);
    metadata["gibench/layers"] = "RGB: obscurance W of the last measured frame";
  } else {
    metadata["gibench/layers"] = "RGB: radiance of the last measured frame (linear Rec.709)";
  }
  return metadata;
}

TechniqueOutputFiles writeTechniqueOutputs(const std::filesystem::path& exr_path,
                                           const TechniqueRunResult& result,
                                           const image::Metadata& metadata) {
  auto write = [&](const std::filesystem::path& exr, const image::Image& image) {
    image::writeExr(exr, {{"", image}}, metadata);
    const std::filesystem::path png = std::filesystem::path(exr).replace_extension(".png");
    image::writePng(png, image);
    return png;
  };
  TechniqueOutputFiles files;
  files.png = write(exr_path, result.image);
  for (const AuxiliaryImage& aux : result.auxiliary) {
    // The name becomes part of a file name; a technique that breaks that rule is a bug.
    const bool safe =
        !aux.name.empty() && std::all_of(aux.name.begin(), aux.name.end(), [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
        });
    if (!safe)
      throw std::logic_error(
          fmt::format("auxiliary image name '{}' is not a safe file name part", aux.name));
    const std::filesystem::path exr =
        exr_path.parent_path() / (exr_path.stem().string() + "-" + aux.name + ".exr");
    files.auxiliary.push_back({aux.name, aux.description, exr, write(exr, aux.image)});
  }
  return files;
}

}  // namespace gib::rt
