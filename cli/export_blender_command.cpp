// gibench export-blender --scene NAME [--scene-set key=value …] [--lens-radius R --focus-distance
// D]
//                        [--width W --height H] [--spp N] [--seed S] --out SCENE.py
// Writes the scene as a Blender Python script that renders it with Cycles
// (scene/blender_export.h); scripts/cross-check-cycles.sh compares that render with the reference.
#include "cli/commands.h"
#include "image/output_files.h"
#include "scene/blender_export.h"
#include "scene/builtin_scenes.h"

#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <optional>

namespace gib::cli {

namespace {

struct ExportBlenderOptions {
  std::string scene;
  std::vector<std::string> scene_set;
  scene::LensSetting lens;  // as `gibench render --lens-radius --focus-distance`
  std::optional<int> width;
  std::optional<int> height;
  int spp = 64;  // as `gibench render`
  std::uint64_t seed = 0;
  std::string out;
};

int runExportBlender(const ExportBlenderOptions& o) {
  image::checkOutputFile(o.out, ".py");
  scene::Scene scene = scene::loadScene(o.scene, o.scene_set);
  scene::applyLens(scene.camera, o.lens, "--lens-radius", "--focus-distance");
  scene::BlenderExportSettings settings;
  settings.width = o.width.value_or(scene.default_width);
  settings.height = o.height.value_or(scene.default_height);
  settings.spp = o.spp;
  settings.seed = o.seed;
  const scene::BlenderExport exported = scene::exportBlenderScript(scene, settings);
  image::writeTextFile(o.out, exported.script);

  // The script works, but its image is not the reference's: say so where it cannot be missed.
  for (const std::string& warning : exported.warnings)
    fmt::print(stderr, "gibench: warning: scene '{}' is not mapped exactly: {}\n", scene.name,
               warning);
  fmt::print("scene      {} (hash {})\n", scene.name, scene::hashScene(scene));
  fmt::print("script     {} ({}x{}, {} spp, seed {})\n", o.out, settings.width, settings.height,
             settings.spp, settings.seed);
  fmt::print(
      "render     blender -b --factory-startup --python-exit-code 3 --python {} -- OUT.exr\n",
      o.out);
  return 0;
}

}  // namespace

CommandRunner addExportBlenderCommand(CLI::App& app) {
  auto o = std::make_shared<ExportBlenderOptions>();
  CLI::App* command = app.add_subcommand(
      "export-blender", "Write a scene as a Blender Python script that renders it with Cycles");
  command->add_option("--scene", o->scene, "built-in scene name or path to a .toml scene file")
      ->required();
  command->add_option("--scene-set", o->scene_set,
                      "scene parameter key=value (repeatable; see `gibench list scenes`)");
  command->add_option("--lens-radius", o->lens.radius,
                      "thin-lens radius in scene units, 0 for the pinhole (as `gibench render`)");
  command->add_option("--focus-distance", o->lens.focus_distance,
                      "distance in scene units to the plane in focus (as `gibench render`)");
  command->add_option("--width", o->width, "image width in pixels (default: the scene's)");
  command->add_option("--height", o->height, "image height in pixels (default: the scene's)");
  command->add_option("--spp", o->spp, "Cycles samples per pixel")->capture_default_str();
  command->add_option("--seed", o->seed, "Cycles seed (0 to 2^31 - 1)")->capture_default_str();
  command->add_option("--out", o->out, "the Python script to write (.py)")->required();
  return [o] { return runExportBlender(*o); };
}

}  // namespace gib::cli
