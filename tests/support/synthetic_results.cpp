#include "support/synthetic_results.h"

#include "support/synthetic_timings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace gib::test {

std::vector<double> noisyFrameTimes(std::uint64_t seed, int frames, double median_ms,
                                    double relative_noise) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> body(0.0, relative_noise);
  std::uniform_real_distribution<double> slow(0.05, 0.20);
  std::bernoulli_distribution hiccup(1.0 / 8.0);
  std::vector<double> samples;
  for (int i = 0; i < frames; ++i) {
    double t = median_ms * std::exp(body(generator));
    if (hiccup(generator)) t *= 1.0 + slow(generator);
    samples.push_back(t);
  }
  return samples;
}

results::JobResult syntheticJob(const std::string& id, const results::NamedValues& metrics,
                                const std::vector<double>& frame_samples_ms) {
  results::JobResult job;
  job.id = id;
  job.slug = id;
  std::replace(job.slug.begin(), job.slug.end(), '/', '_');
  job.case_name = "cornell-direct";
  job.scene = "cornell";
  job.scene_hash = "5ce4e1";
  job.technique = "direct";
  job.parameters = {{"shadow", "pcf"}, {"light_samples", "16"}};
  job.width = 64;
  job.height = 48;
  job.path_class = "L(D|S|P){0,1}E";
  job.reference = {"ref-key-direct", 256, 7, "L(D|S|P){0,1}E", true, 0.0};
  job.metrics = metrics;
  if (!frame_samples_ms.empty()) job.timings = frameTimings(frame_samples_ms);
  job.seconds = 1.5;
  job.job_hash = "hash-" + id;
  return job;
}

results::RunResults syntheticRun(const std::string& id, std::vector<results::JobResult> jobs) {
  results::RunResults run;
  run.run.id = id;
  run.run.suite = "unit";
  run.run.started = "2026-11-22T10:04:05Z";
  run.run.finished = "2026-11-22T10:05:00Z";
  run.run.git_commit = "0123456789abcdef0123456789abcdef01234567";
  run.primary_metric = "relmse";
  run.jobs = std::move(jobs);
  return run;
}

results::RunResults richResults() {
  const double inf = std::numeric_limits<double>::infinity();

  results::JobResult technique = syntheticJob(
      "cornell-direct/shadow=pcf", {{"relmse", 0.0123}, {"flip_mean", 0.071}, {"psnr", inf}},
      noisyFrameTimes(1, 16, 4.2));
  technique.scene_parameters = {{"light_scale", "1.5"}, {"name", "with \"quotes\", commas"}};
  technique.full_reference = results::ReferenceUse{"ref-key-full", 1024,  18446744073709551615ull,
                                                   "all paths",    false, 12.25};
  technique.metrics_full = {{"relmse", 0.25}, {"ssim", 0.91}};
  results::Convergence convergence;
  convergence.x_label = "iterations";
  convergence.points = {{1, {{"relmse", 0.5}}, 0.01}, {4, {{"relmse", 0.125}}, 0.04}};
  convergence.fit_metric = "relmse";
  convergence.fit_slope = -1.0;
  convergence.fit_intercept = -0.69;
  convergence.fit_slope_ci95 = 0.02;
  technique.convergence = convergence;
  technique.upload_ms = 3.5;
  technique.prepare_ms = 11.0;
  technique.iterate_ms = 2.25;
  technique.iterations = 4;
  technique.outputs = {"jobs/a.exr",
                       "jobs/a.png",
                       "jobs/ref.png",
                       "jobs/diff.png",
                       "jobs/flip.png",
                       "jobs/a-timings.json",
                       "slurm/1/logs/gpu-0.log",
                       "jobs/a-thumbnail.png",
                       "jobs/a-viewer.js",
                       "viewer/ref.js",
                       "references/ref.exr",
                       "references/full.exr",
                       "jobs/a-disagreement.png"};
  technique.disagreement_pixels = 17;
  technique.execution = {"node7", "1234_5", 12.5, "llvmpipe (LLVM 15.0.6, 256 bits)"};
  technique.iteration_timings = frameTimings({1.5, 2.0, 2.5, 3.0}, "cpu", "iteration");
  technique.statistics = {{"vertices", 1536}, {"atlas_texels", 12000}};
  technique.auxiliary_images = {
      {"atlas", "the radiance atlas", "jobs/a-atlas.exr", "jobs/a-atlas.png"}};
  technique.repeats = {*technique.timings, frameTimings(noisyFrameTimes(2, 16, 4.3))};
  technique.conditions = {0.25, 1.5, "performance", 0};
  technique.scene_file = "/scenes/room.toml";

  results::JobResult reference;
  reference.id = "cornell-reference";
  reference.slug = "cornell-reference";
  reference.case_name = "cornell-reference";
  reference.scene = "cornell";
  reference.technique = "reference";
  reference.width = 64;
  reference.height = 48;
  reference.path_class = "all paths";
  reference.reference = {"ref-key-full", 1024, 3, "all paths", false, 12.25};
  reference.metrics = {{"relmse", -inf}};

  results::RunResults run = syntheticRun("20261122-100405-unit-0a1b2c3d", {technique, reference});
  run.run.suite_description = "synthetic results";
  run.run.suite_file = "suites/unit.toml";
  run.run.suite_hash = "feedbeef";
  run.run.gibench_version = "0.1.0+0123456789ab-dirty";
  run.run.git_dirty = true;
  run.run.build_type = "Release";
  run.run.host = "bench-host";
  run.run.cpu = "Some CPU @ 3 GHz";
  run.run.cpu_cores = 16;
  run.run.embree_version = "3.13.5";
  run.run.gl_vendor = "Mesa";
  run.run.gl_renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
  run.run.gl_version = "4.5 (Core Profile) Mesa 22.3.6";
  run.run.gl_device = "surfaceless";
  run.run.parallel_jobs = 2;
  run.run.store = "/var/cache/gibench";
  run.run.complete = false;
  run.run.conditions = {0.5, 2.25, "schedutil", 1};
  run.tolerances.metric_default = {0.001, 0.05};
  run.tolerances.metrics["flip_mean"] = {0.0, 0.02};
  run.tolerances.timing = {0.15, 0.001};
  run.paper = {{"cornell-direct/shadow=pcf", "frame", 26.0, "ms", "Nijasure et al. 2005, Table 1",
                "Radeon 9800 Pro"}};
  run.charts = {{"Frame time against light samples", "cornell-direct/*", "parameter:light_samples",
                 "frame", "parameter:shadow", true, false, true}};
  run.figures = {{"fig-6",
                  "Fig. 6: the atlas & the \"image\"",
                  "",
                  3,
                  {{"cornell-direct/shadow=pcf", "aux:atlas", "atlas", 1, 3, "full:relmse"},
                   {"cornell-reference", "image", "", 2, 1, ""}}}};
  return run;
}

}  // namespace gib::test
