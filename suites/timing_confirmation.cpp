#include "suites/timing_confirmation.h"

#include "common/input_error.h"
#include "common/subprocess.h"
#include "results/results_json.h"

#include <fmt/format.h>

#include <stdexcept>

namespace gib::suites {

namespace fs = std::filesystem;

std::vector<std::string> renderArguments(const results::JobResult& job,
                                         const std::string& gl_device, const fs::path& out_exr,
                                         const fs::path& timings_json) {
  if (!job.timings)
    throw InputError(
        fmt::format("job {} was not timed (a reference job); nothing to confirm", job.id));
  std::string scene = job.scene_file.empty() ? job.scene : job.scene_file;
  std::vector<std::string> args = {"render", "--scene", scene, "--technique", job.technique};
  for (const auto& [key, value] : job.scene_parameters)
    args.insert(args.end(), {"--scene-set", key + "=" + value});
  for (const auto& [key, value] : job.parameters)
    args.insert(args.end(), {"--set", key + "=" + value});
  const metrics::PassTimings& t = *job.timings;
  args.insert(args.end(),
              {"--width", std::to_string(job.width), "--height", std::to_string(job.height),
               "--frames", std::to_string(t.measured_frames), "--warmup",
               std::to_string(t.warmup_frames), "--clock", t.clock});
  if (job.iterations > 0) args.insert(args.end(), {"--iterations", std::to_string(job.iterations)});
  if (!gl_device.empty()) args.insert(args.end(), {"--gl-device", gl_device});
  args.insert(args.end(), {"--timings-json", timings_json.string(), "--out", out_exr.string()});
  return args;
}

namespace {

// One render of `job` by `gibench`: its median frame time.
double timeOnce(const fs::path& gibench, const results::JobResult& job,
                const ConfirmationOptions& options, const std::string& name) {
  const fs::path exr = options.work_dir / (name + ".exr");
  const fs::path timings = options.work_dir / (name + ".json");
  std::vector<std::string> argv = {gibench.string()};
  for (std::string& arg : renderArguments(job, options.gl_device, exr, timings))
    argv.push_back(std::move(arg));
  const ProgramResult r = runProgram(argv, options.work_dir);
  if (r.exit_code != 0) {
    std::string message = r.err;
    while (!message.empty() && message.back() == '\n') message.pop_back();
    throw std::runtime_error(fmt::format("{} could not render job {} (exit {}): {}",
                                         gibench.string(), job.id, r.exit_code,
                                         message.substr(message.rfind('\n') + 1)));
  }
  return results::readPassTimingsFile(timings).root().reported.median;
}

}  // namespace

InterleavedRuns runInterleaved(const results::JobResult& base_job,
                               const results::JobResult& new_job,
                               const ConfirmationOptions& options) {
  if (options.pairs < 2) throw InputError("confirming a timing needs two or more A/B pairs");
  fs::create_directories(options.work_dir);
  InterleavedRuns runs;
  for (int i = 0; i < options.pairs; ++i) {
    runs.base_ms.push_back(timeOnce(options.base_gibench, base_job, options, "base"));
    runs.new_ms.push_back(timeOnce(options.new_gibench, new_job, options, "new"));
    if (options.log)
      options.log(fmt::format("confirming {}: pair {}/{}: base {:.4g} ms, new {:.4g} ms",
                              new_job.id, i + 1, options.pairs, runs.base_ms.back(),
                              runs.new_ms.back()));
  }
  return runs;
}

}  // namespace gib::suites
