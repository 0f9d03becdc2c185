// One place turns a scene name into a scene: the built-in scenes, or a TOML scene file.
#pragma once

#include "common/parameters.h"
#include "scene/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace gib::scene {

struct BuiltinSceneInfo {
  std::string name;
  std::string description;
  ParameterTable parameters;  // set with `--scene-set key=value`
};

const std::vector<BuiltinSceneInfo>& builtinScenes();

// A built-in name ("cornell", "furnace", ...) or a path to a .toml scene file, with "key=value"
// assignments of the built-in scene's parameters. Throws InputError for an unknown name (naming
// the built-in scenes) and for parameters the scene does not take or values out of range. The
// scene's canonical parameter values are recorded in Scene::parameters.
Scene loadScene(std::string_view name_or_path, const std::vector<std::string>& parameters = {});

// The built-in scenes, each in its own file.
Scene makeCornellBox(const ParameterValues& parameters);
ParameterTable cornellParameters();
Scene makeFurnace(const ParameterValues& parameters);
ParameterTable furnaceParameters();
Scene makeChamber(const ParameterValues& parameters);
ParameterTable chamberParameters();
Scene makeCloud(const ParameterValues& parameters);
ParameterTable cloudParameters();
Scene makeRoom(const ParameterValues& parameters);
ParameterTable roomParameters();
Scene makeOutdoor(const ParameterValues& parameters);
ParameterTable outdoorParameters();

}  // namespace gib::scene
