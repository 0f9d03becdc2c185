#include "cli/commands.h"
#include "common/input_error.h"
#include "image/exr_io.h"
#include "reference/reference_output.h"
#include "scene/builtin_scenes.h"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <optional>

namespace gib::cli {

namespace {

struct RenderOptions {
  std::string scene;
  std::string technique = "reference";
  std::optional<int> width;
  std::optional<int> height;
  int spp = 64;
  std::uint64_t seed = 0;
  int min_bounces = 0;
  std::optional<int> max_bounces;
  int threads = 0;
  bool checkpoints = false;
  std::vector<std::string> set;
  std::vector<std::string> scene_set;
  std::string out;
};

int runRender(const RenderOptions& o) {
  if (o.technique != "reference")
    throw InputError(
        fmt::format("unknown technique '{}'; available: reference (see `gibench list techniques`)",
                    o.technique));
  if (!o.set.empty())
    throw InputError(
        fmt::format("technique 'reference' has no parameter '{}'; it takes --spp, "
                    "--seed, --min-bounces, --max-bounces instead",
                    o.set.front().substr(0, o.set.front().find('='))));
  if (o.spp <= 0)
    throw InputError(
        fmt::format("--spp {} renders nothing; give at least 1 sample per pixel", o.spp));
  const std::filesystem::path out(o.out);
  ref::checkOutputPath(out);
  const scene::Scene scene = scene::loadScene(o.scene, o.scene_set);

  ref::RenderSettings settings;
  settings.width = o.width.value_or(scene.default_width);
  settings.height = o.height.value_or(scene.default_height);
  settings.spp = std::uint32_t(o.spp);
  settings.seed = o.seed;
  settings.path_class.min_bounces = o.min_bounces;
  if (o.max_bounces) settings.path_class.max_bounces = *o.max_bounces;
  settings.threads = o.threads;
  settings.progress = true;
  ref::validateRenderSettings(settings);

  image::Metadata metadata = ref::referenceMetadata(scene, settings);
  ref::CheckpointCallback on_checkpoint;
  if (o.checkpoints)
    on_checkpoint = [&](std::uint32_t spp, const image::Image& mean) {
      image::Metadata m = metadata;
      m["gibench/spp"] = std::to_string(spp);
      image::writeExr(ref::checkpointPath(out, spp), {{"", mean}}, m);
    };
  ref::RenderResult result = ref::renderReference(scene, settings, on_checkpoint);
  ref::addRunMetadata(metadata, result);
  std::filesystem::path png = ref::writeReferenceOutputs(out, result, metadata);

  fmt::print("scene      {} (hash {})\n", scene.name, metadata.at("gibench/scene_hash"));
  fmt::print("rendered   {}x{} at {} spp in {:.2f} s ({:.2f} Mrays/s, peak memory {} MiB)\n",
             settings.width, settings.height, settings.spp, result.seconds,
             result.raysPerSecond() * 1e-6, metadata.at("gibench/peak_rss_mb"));
  fmt::print("exr        {}\n", out.string());
  fmt::print("png        {}\n", png.string());
  if (o.checkpoints)
    fmt::print("checkpoints {}\n", ref::checkpointPath(out, 1).parent_path().string());
  return 0;
}

}  // namespace

CommandRunner addRenderCommand(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* render =
      app.add_subcommand("render", "Render a scene with the reference or a technique");
  render->add_option("--scene", o->scene, "built-in scene name or path to a .toml scene file")
      ->required();
  render->add_option("--scene-set", o->scene_set,
                     "scene parameter key=value (repeatable; see `gibench list scenes`)");
  render->add_option("--technique", o->technique, "reference (default) or a technique name");
  render->add_option("--width", o->width, "image width in pixels (default: the scene's)");
  render->add_option("--height", o->height, "image height in pixels (default: the scene's)");
  render->add_option("--spp", o->spp, "samples per pixel")->capture_default_str();
  render->add_option("--seed", o->seed, "random seed")->capture_default_str();
  render
      ->add_option("--min-bounces", o->min_bounces,
                   "only paths with at least this many bounces (0: emitters seen directly)")
      ->capture_default_str();
  render->add_option("--max-bounces", o->max_bounces,
                     "only paths with at most this many bounces (default: unlimited)");
  render->add_option("--threads", o->threads, "worker threads, 0 = all cores (same image)")
      ->capture_default_str();
  render->add_flag("--checkpoints", o->checkpoints,
                   "also write the mean at 1, 2, 4, ... spp as <stem>.sppNNNN.exr");
  render->add_option("--set", o->set, "technique parameter key=value (repeatable)");
  render->add_option("--out", o->out, "output EXR (a PNG is written beside it)")->required();
  return [o] { return runRender(*o); };
}

}  // namespace gib::cli
