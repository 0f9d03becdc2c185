// `gibench render --technique NAME`: a real-time technique on the headless GL context, with its
// pass timings.
#include "cli/render_options.h"
#include "common/input_error.h"
#include "common/join.h"
#include "image/exr_io.h"
#include "image/output_files.h"
#include "metrics/pass_timing_summary.h"
#include "realtime/technique_output.h"
#include "realtime/technique_runner.h"
#include "reference/reference_output.h"
#include "results/results_json.h"
#include "scene/builtin_scenes.h"

#include <fmt/format.h>

#include <filesystem>

namespace gib::cli {

int renderTechnique(const RenderOptions& o, const CLI::App& app) {
  const rt::TechniqueInfo& info = rt::findTechnique(o.technique);
  const std::vector<std::string> foreign = givenOptions(
      app, {"--spp", "--seed", "--sampler", "--light-paths", "--environment-occlusion",
            "--pixel-sampling", "--replicas", "--min-bounces", "--max-bounces", "--paths",
            "--threads", "--checkpoints", "--obscurance", "--obscurance-mode", "--d-max"});
  if (!foreign.empty())
    throw InputError(fmt::format(
        "{} applies to the reference path tracer; technique '{}' takes --set key=value (see "
        "`gibench list techniques`)",
        joinNames(foreign, ", "), info.name));
  const ParameterValues parameters =
      parseParameters(info.parameters, o.set, fmt::format("technique '{}'", info.name));
  // As a suite refuses iterations on such a technique (suites/job_execution.cpp).
  if (!givenOptions(app, {"--iterations"}).empty() && !info.create(parameters)->iterative())
    throw InputError(
        fmt::format("technique '{}' renders in one step and takes no --iterations; "
                    "remove it (`gibench list techniques` shows the iterative ones)",
                    info.name));
  const std::filesystem::path out(o.out);
  ref::checkOutputPath(out);
  if (!o.timings_json.empty()) image::checkOutputFile(o.timings_json, ".json");
  const scene::Scene scene = loadRenderScene(o);

  rt::TechniqueRunSettings settings;
  settings.width = o.width.value_or(scene.default_width);
  settings.height = o.height.value_or(scene.default_height);
  settings.frames = o.frames;
  settings.warmup_frames = o.warmup;
  settings.iterations = o.iterations;
  if (o.clock != "auto") settings.precise = o.clock == "cpu";
  settings.context.device = o.gl_device;
  settings.services.ray_caster = ref::embreeRayCasterFactory();
  settings.context.debug = rt::gl::debugOutputByDefault();

  const rt::TechniqueRunResult result = rt::runTechnique(scene, info, parameters, settings);
  const metrics::PassTimings timings = metrics::summarizeProfile(result.profile);

  image::Metadata metadata = rt::techniqueOutputMetadata(scene, info, parameters, settings, result,
                                                         timings.root().reported.median);
  metadata["gibench/peak_rss_mb"] = fmt::format("{:.1f}", ref::peakResidentMegabytes());
  const rt::TechniqueOutputFiles files = rt::writeTechniqueOutputs(out, result, metadata);
  if (!o.timings_json.empty())
    image::writeTextFile(o.timings_json, results::passTimingsToJson(timings).dump(2) + "\n");

  fmt::print("scene      {} (hash {})\n", scene.name, metadata.at("gibench/scene_hash"));
  fmt::print("technique  {} {}\n", info.name,
             joinNames(parameters.canonical(), " ",
                       [](const auto& kv) { return kv.first + "=" + kv.second; }));
  fmt::print("path class {}\n", metadata.at("gibench/path_class"));
  fmt::print("gl         {} | {} | {} ({})\n", result.gl.vendor, result.gl.renderer,
             result.gl.version, result.gl.device);
  fmt::print("prepare    upload {:.1f} ms, prepare {:.1f} ms\n", result.upload_ms,
             result.prepare_ms);
  fmt::print("{}", metrics::formatPassTable(timings));
  if (!result.iteration_profile.passes.empty() && result.iteration_profile.measured_frames > 0) {
    fmt::print("iterations {} in {:.1f} ms\n", result.iterations, result.iterate_ms);
    fmt::print("{}", metrics::formatPassTable(metrics::summarizeProfile(result.iteration_profile)));
  }
  for (const rt::TechniqueStatistic& statistic : result.statistics)
    fmt::print("{:<10} {:g}\n", statistic.name, statistic.value);
  fmt::print("exr        {}\n", out.string());
  fmt::print("png        {}\n", files.png.string());
  for (const rt::AuxiliaryImageFiles& aux : files.auxiliary)
    fmt::print("{:<10} {} ({})\n", aux.name, aux.png.string(), aux.description);
  if (!o.timings_json.empty()) fmt::print("timings    {}\n", o.timings_json);
  return 0;
}

}  // namespace gib::cli
