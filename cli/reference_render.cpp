// `gibench render --technique reference`: the Embree path tracer.
#include "cli/render_options.h"
#include "common/input_error.h"
#include "common/join.h"
#include "image/exr_io.h"
#include "reference/reference_output.h"
#include "scene/builtin_scenes.h"
#include "scene/path_expression.h"

#include <fmt/format.h>

#include <filesystem>

namespace gib::cli {

namespace {

// The class given by --paths or by the bounce options, its shorthand (never both).
scene::PathClass pathClassOf(const RenderOptions& o, const CLI::App& app) {
  const std::vector<std::string> bounces = givenOptions(app, {"--min-bounces", "--max-bounces"});
  if (givenOptions(app, {"--paths"}).empty())
    return scene::PathClass(o.min_bounces, o.max_bounces.value_or(scene::PathClass::kUnlimited));
  if (!bounces.empty())
    throw InputError(fmt::format(
        "--paths and {} both choose the path class; give one (--min-bounces a --max-bounces b is "
        "--paths 'L(D|S|P){{a,b}}E')",
        joinNames(bounces, " and ")));
  return scene::PathClass::ofExpression(scene::PathExpression::parse(o.paths).text());
}

}  // namespace

int renderReference(const RenderOptions& o, const CLI::App& app) {
  const std::vector<std::string> foreign =
      givenOptions(app, {"--set", "--frames", "--warmup", "--iterations", "--clock", "--gl-device",
                         "--timings-json"});
  if (!foreign.empty())
    throw InputError(fmt::format(
        "{} applies to real-time techniques, not the reference; the reference takes --spp, "
        "--seed, --paths, --min-bounces, --max-bounces",
        joinNames(foreign, ", ")));
  if (o.spp <= 0)
    throw InputError(
        fmt::format("--spp {} renders nothing; give at least 1 sample per pixel", o.spp));
  const scene::PathClass path_class = pathClassOf(o, app);
  const std::filesystem::path out(o.out);
  ref::checkOutputPath(out);
  const scene::Scene scene = scene::loadScene(o.scene, o.scene_set);

  ref::RenderSettings settings;
  settings.width = o.width.value_or(scene.default_width);
  settings.height = o.height.value_or(scene.default_height);
  settings.spp = std::uint32_t(o.spp);
  settings.seed = o.seed;
  if (o.replicas < 0 || o.replicas > o.spp)
    throw InputError(fmt::format("--replicas {} is not in 1..--spp ({}); give a divisor of --spp",
                                 o.replicas, o.spp));
  settings.replicas = std::uint32_t(o.replicas);
  settings.sampler = ref::parseSamplerName(o.sampler);
  settings.pixel_sampling = ref::parsePixelSampling(o.pixel_sampling);
  settings.light_paths = ref::parseLightPaths(o.light_paths);
  settings.path_class = path_class;
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
  fmt::print("variance   from {} replicas of {} spp ({} degrees of freedom)\n", result.replicas,
             settings.spp / result.replicas, result.variance_dof);
  fmt::print("exr        {}\n", out.string());
  fmt::print("png        {}\n", png.string());
  if (o.checkpoints)
    fmt::print("checkpoints {}\n", ref::checkpointPath(out, 1).parent_path().string());
  return 0;
}

}  // namespace gib::cli
