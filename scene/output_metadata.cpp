#include "scene/output_metadata.h"

#include "gib/version.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace gib::scene {

std::map<std::string, std::string> outputMetadata(const Scene& scene, std::string_view technique,
                                                  std::string_view parameters_json, int width,
                                                  int height, const PathClass& path_class) {
  const bool unlimited = path_class.max_bounces == PathClass::kUnlimited;
  std::map<std::string, std::string> m;
  m["gibench/program"] = kProgramName;
  m["gibench/version"] = kVersion;
  m["gibench/technique"] = technique;
  m["gibench/parameters"] = parameters_json;
  m["gibench/scene"] = scene.name;
  m["gibench/scene_hash"] = hashScene(scene);
  m["gibench/scene_provenance"] = scene.provenance;
  nlohmann::ordered_json scene_parameters = nlohmann::ordered_json::object();
  for (const auto& [key, value] : scene.parameters) scene_parameters[key] = value;
  m["gibench/scene_parameters"] = scene_parameters.dump();
  m["gibench/width"] = std::to_string(width);
  m["gibench/height"] = std::to_string(height);
  // A class is an expression or a bounce range (scene/path_class.h): the image names the one given.
  if (!path_class.expression.empty()) {
    m["gibench/paths"] = path_class.expression;
  } else {
    m["gibench/min_bounces"] = std::to_string(path_class.min_bounces);
    m["gibench/max_bounces"] = unlimited ? "unlimited" : std::to_string(path_class.max_bounces);
  }
  m["gibench/path_class"] = describePathClass(path_class);
  // The thin lens, when there is one (a pinhole image's metadata stays as it was). A technique's
  // image records it too: its GL camera is a pinhole, and these say which lens it is measured
  // against.
  if (scene.camera.lens_radius > 0) {
    m["gibench/lens_radius"] = fmt::format("{}", scene.camera.lens_radius);
    m["gibench/focus_distance"] = fmt::format("{}", focusDistance(scene.camera));
  }
  return m;
}

}  // namespace gib::scene
