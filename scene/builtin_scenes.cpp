#include "scene/builtin_scenes.h"

#include "common/input_error.h"
#include "common/join.h"
#include "scene/scene_file.h"

#include <fmt/format.h>
#include <filesystem>

namespace gib::scene {

namespace {

struct BuiltinScene {
  BuiltinSceneInfo info;
  Scene (*make)(const ParameterValues&);
};

const std::vector<BuiltinScene>& registry() {
  static const std::vector<BuiltinScene> scenes = {
      {{"cornell",
        "the Cornell box as published by the Cornell Program of Computer Graphics (mm, spectral "
        "reflectances converted to Rec.709); with a mirror and a glass sphere in place of the "
        "blocks, and a spot light in place of the area light, as variants",
        cornellParameters()},
       &makeCornellBox},
      {{"furnace",
        "inside a closed sphere with albedo 0.5 and emission 0.5, optionally around a perfect "
        "mirror or lossless glass sphere: every pixel's exact radiance is 1.0",
        furnaceParameters()},
       &makeFurnace},
      {{"chamber",
        "procedural marble chamber (vaulted hall, arcades, spot light; ~3 400 triangles at "
        "detail 1, ~85 000 at detail 5) after Szirmay-Kalos et al. Fig. 8.12",
        chamberParameters()},
       &makeChamber},
      {{"cloud",
        "procedural cumulus of 1024 particles (albedo 0.9, g 0, two directional lights and a "
        "sky) after Szirmay-Kalos et al. Fig. 9.21",
        cloudParameters()},
       &makeCloud},
      {{"room",
        "cubic room of red, green, blue and yellow walls lit by four fire balls, with a diffuse or "
        "glossy sphere or torus (the last mesh) in place of the book's skull, bunny, Buddha and "
        "dragon, after Szirmay-Kalos et al. §7.3, Figs. 7.10-7.13",
        roomParameters()},
       &makeRoom},
      {{"outdoor",
        "a ground plane with a diffuse, a glossy, a mirror and a glass sphere and a torus (the "
        "last mesh) under the Preetham clear sky or a latitude-longitude EXR, after Szirmay-Kalos "
        "et al. §4.2 and §8.3",
        outdoorParameters()},
       &makeOutdoor},
  };
  return scenes;
}

}  // namespace

const std::vector<BuiltinSceneInfo>& builtinScenes() {
  static const std::vector<BuiltinSceneInfo> infos = [] {
    std::vector<BuiltinSceneInfo> result;
    for (const BuiltinScene& s : registry()) result.push_back(s.info);
    return result;
  }();
  return infos;
}

Scene loadScene(std::string_view name_or_path, const std::vector<std::string>& parameters) {
  for (const BuiltinScene& s : registry())
    if (s.info.name == name_or_path) {
      const ParameterValues values =
          parseParameters(s.info.parameters, parameters, fmt::format("scene '{}'", s.info.name));
      Scene scene = s.make(values);
      scene.parameters = values.canonical();
      validateScene(scene);
      return scene;
    }
  std::filesystem::path path(name_or_path);
  if (path.extension() == ".toml") {
    if (!parameters.empty())
      throw InputError(
          fmt::format("scene file '{}' takes no --scene-set parameters; edit the file "
                      "instead",
                      path.string()));
    return loadSceneFile(path);
  }
  const std::string names =
      joinNames(registry(), ", ", [](const BuiltinScene& s) { return s.info.name; });
  throw InputError(fmt::format(
      "unknown scene '{}'; use a built-in scene ({}; see `gibench list scenes`) or the path of a "
      ".toml scene file",
      name_or_path, names));
}

}  // namespace gib::scene
