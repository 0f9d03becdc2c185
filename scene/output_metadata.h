// The gibench/* metadata every output shares, whoever rendered it (docs/architecture.md, "Images"):
// the program and its version, the technique and its parameters, the scene with its hash,
// provenance and parameters, the image size and the path class. Renderers add their own keys to it.
#pragma once

#include "scene/path_class.h"
#include "scene/scene.h"

#include <map>
#include <string>
#include <string_view>

namespace gib::scene {

// `parameters_json`: the technique's parameters as one JSON object.
std::map<std::string, std::string> outputMetadata(const Scene& scene, std::string_view technique,
                                                  std::string_view parameters_json, int width,
                                                  int height, const PathClass& path_class);

}  // namespace gib::scene
