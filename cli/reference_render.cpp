// `gibench render --technique reference`: the Embree path tracer.
#include "cli/render_options.h"
#include "common/input_error.h"
#include "common/join.h"
#include "image/exr_io.h"
#include "reference/reference_output.h"
#include "scene/builtin_scenes.h"
#include "scene/path_expression.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <optional>

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

// The obscurance --obscurance asks for instead of radiance, if any, with its mode and d_max.
std::optional<scene::ObscuranceDefinition> obscuranceOf(const RenderOptions& o,
                                                        const CLI::App& app) {
  const std::vector<std::string> details = givenOptions(app, {"--obscurance-mode", "--d-max"});
  if (givenOptions(app, {"--obscurance"}).empty()) {
    if (!details.empty())
      throw InputError(fmt::format(
          "{} applies to an obscurance; add --obscurance sqrt|ambient_occlusion, or remove it",
          joinNames(details, " and ")));
    return std::nullopt;
  }
  const std::vector<std::string> radiance_only =
      givenOptions(app, {"--paths", "--min-bounces", "--max-bounces", "--light-paths"});
  if (!radiance_only.empty())
    throw InputError(
        fmt::format("an obscurance has no light paths for {} to choose; remove it or --obscurance",
                    joinNames(radiance_only, ", ")));
  scene::ObscuranceDefinition definition;
  definition.falloff = scene::parseObscuranceFalloff(o.obscurance);
  definition.mode = scene::parseObscuranceMode(o.obscurance_mode);
  if (!(std::isfinite(o.d_max) && o.d_max > 0))
    throw InputError(
        fmt::format("--d-max {} is not a positive number; give d_max as a fraction of the scene's "
                    "bounding-box diagonal (default {})",
                    o.d_max, scene::ObscuranceDefinition::kDefaultObscuranceDistanceFraction));
  definition.d_max_fraction = float(o.d_max);
  scene::validateObscuranceDistanceFraction(definition.d_max_fraction);
  return definition;
}

}  // namespace

int renderReference(const RenderOptions& o, const CLI::App& app) {
  const std::vector<std::string> foreign =
      givenOptions(app, {"--set", "--frames", "--warmup", "--iterations", "--clock", "--gl-device",
                         "--timings-json"});
  if (!foreign.empty())
    throw InputError(fmt::format(
        "{} applies to real-time techniques, not the reference; the reference takes --spp, "
        "--seed, --paths, --min-bounces, --max-bounces, --obscurance",
        joinNames(foreign, ", ")));
  if (o.spp <= 0)
    throw InputError(
        fmt::format("--spp {} renders nothing; give at least 1 sample per pixel", o.spp));
  const std::optional<scene::ObscuranceDefinition> obscurance = obscuranceOf(o, app);
  const scene::PathClass path_class = pathClassOf(o, app);
  const std::filesystem::path out(o.out);
  ref::checkOutputPath(out);
  const scene::Scene scene = loadRenderScene(o);

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
  settings.environment_occlusion = o.environment_occlusion != "off";
  settings.path_class = path_class;
  settings.obscurance = obscurance;
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
  if (obscurance)
    fmt::print("image      {} (d_max {:g} scene units), not radiance\n",
               metadata.at("gibench/obscurance"), scene::maxDistance(scene, *obscurance));
  fmt::print("variance   from {} replicas of {} spp ({} degrees of freedom)\n", result.replicas,
             settings.spp / result.replicas, result.variance_dof);
  fmt::print("exr        {}\n", out.string());
  fmt::print("png        {}\n", png.string());
  if (o.checkpoints)
    fmt::print("checkpoints {}\n", ref::checkpointPath(out, 1).parent_path().string());
  return 0;
}

}  // namespace gib::cli
