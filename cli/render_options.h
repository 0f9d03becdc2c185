// The options of `gibench render`, shared by its two paths: the reference path tracer and the
// real-time techniques. Each path rejects the options that belong to the other.
#pragma once

#include "scene/obscurance.h"
#include "scene/scene.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gib::cli {

struct RenderOptions {
  std::string scene;
  std::string technique = "reference";
  std::optional<int> width;
  std::optional<int> height;
  std::vector<std::string> scene_set;
  std::string out;
  // Both: the thin lens over the scene's camera (scene::applyLens). Techniques record it in their
  // metadata and keep their pinhole GL camera.
  scene::LensSetting lens;
  // Reference only.
  int spp = 64;
  std::uint64_t seed = 0;
  long long replicas = 0;  // 0: ref::defaultReplicas
  std::string sampler = "sobol";
  std::string pixel_sampling = "area";
  std::string light_paths = "auto";          // ref::LightPaths
  std::string environment_occlusion = "on";  // or "off": RenderSettings::environment_occlusion
  int min_bounces = 0;
  std::optional<int> max_bounces;
  std::string paths;  // a path expression (scene/path_expression.h); exclusive with the bounces
  int threads = 0;
  bool checkpoints = false;
  // An obscurance instead of radiance (scene/obscurance.h): the fall-off's name, empty for
  // radiance; the mode; d_max as a fraction of the scene's bounding-box diagonal.
  std::string obscurance;
  std::string obscurance_mode = "scalar";
  double d_max = scene::ObscuranceDefinition::kDefaultObscuranceDistanceFraction;
  // Techniques only.
  std::vector<std::string> set;
  int frames = 8;
  int warmup = 2;
  int iterations = 1;
  std::string clock = "auto";
  std::string gl_device;
  std::string timings_json;
};

// Options given on the command line (not defaulted) among `names`, e.g. {"--spp", "--seed"}.
std::vector<std::string> givenOptions(const CLI::App& app, const std::vector<std::string>& names);

// The scene of --scene and --scene-set with the lens of --lens-radius and --focus-distance.
scene::Scene loadRenderScene(const RenderOptions& options);

int renderReference(const RenderOptions& options, const CLI::App& app);
int renderTechnique(const RenderOptions& options, const CLI::App& app);

}  // namespace gib::cli
