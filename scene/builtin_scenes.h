// One place turns a scene name into a scene: the built-in scenes, or a TOML scene file.
#pragma once

#include "scene/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace gib::scene {

struct BuiltinSceneInfo {
  std::string name;
  std::string description;
};

const std::vector<BuiltinSceneInfo>& builtinScenes();

// A built-in name ("cornell", "furnace") or a path to a .toml scene file. Throws InputError for an
// unknown name, naming the built-in scenes.
Scene loadScene(std::string_view name_or_path);

// The built-in scenes, each in its own file.
Scene makeCornellBox();
Scene makeFurnace();

}  // namespace gib::scene
