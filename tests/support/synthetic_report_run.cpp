#include "support/synthetic_report_run.h"

#include "image/display.h"
#include "image/image.h"
#include "image/viewer_data.h"
#include "results/results_json.h"
#include "support/synthetic_timings.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gib::test {

namespace {

constexpr int kWidth = 32, kHeight = 24;
constexpr int kAuxiliarySide = 16;  // auxiliary images: square, smaller than the job's pictures

// Frame samples spread ±10% around the median, deterministically.
std::vector<double> samples(double median, int frames) {
  std::vector<double> out;
  for (int i = 0; i < frames; ++i) out.push_back(median * (0.9 + 0.2 * double(i) / (frames - 1)));
  return out;
}

results::JobOutputs outputsOf(const std::string& slug, bool reference_job) {
  const std::string dir = "jobs/" + slug + "/";
  results::JobOutputs out;
  out.image = dir + "image.exr";
  out.image_png = dir + "image.png";
  out.reference_png = dir + "reference.png";
  out.difference_png = dir + "difference.png";
  if (!reference_job) {
    out.flip_png = dir + "flip.png";
    out.timings_json = dir + "timings.json";
  }
  out.thumbnail_png = dir + "thumbnail.png";
  out.viewer_data = dir + "viewer.js";
  out.reference_viewer_data = "viewer/ref-all-0001.js";
  return out;
}

// Slugs as the suite expansion makes them: '/' → "__", '=' → '-', ',' → "__".
std::string slugOf(const std::string& id) {
  std::string slug;
  for (char c : id) {
    if (c == '/' || c == ',')
      slug += "__";
    else
      slug += c == '=' ? '-' : c;
  }
  return slug;
}

// What every job of the synthetic run shares: the Cornell box at the small picture size.
results::JobResult cornellJob(const std::string& id, const std::string& case_name,
                              const std::string& technique) {
  results::JobResult job;
  job.id = id;
  job.slug = slugOf(id);
  job.case_name = case_name;
  job.scene = "cornell";
  job.technique = technique;
  job.width = kWidth;
  job.height = kHeight;
  return job;
}

}  // namespace

metrics::PassTimings nestedPassTimings(double scale, int frames, const std::string& root) {
  struct Spec {
    const char* path;  // under the root
    double median_ms;
    int calls;
    int gpu_commands;  // draws and dispatches per frame
  };
  const Spec specs[] = {{"", 20.0, 1, 30},
                        {"/gbuffer", 3.0, 1, 1},
                        {"/shadow_maps", 6.0, 4, 24},
                        {"/shadow_maps/cube_faces", 5.0, 24, 24},
                        {"/shading", 10.0, 4, 4}};
  std::vector<SyntheticPass> passes;
  for (const Spec& spec : specs)
    passes.push_back(
        {root + spec.path, samples(spec.median_ms * scale, frames), spec.calls, spec.gpu_commands});
  return syntheticTimings(passes, "cpu");
}

results::JobResult syntheticTechniqueJob(const std::string& sweep, double relmse,
                                         double frame_scale) {
  results::JobResult job = cornellJob("cornell-direct/" + sweep, "cornell-direct", "direct");
  job.scene_hash = "5f1e0c2b9a8d7e6f5f1e0c2b9a8d7e6f";
  job.parameters = {{"shadow", "pcf"}, {"light_samples", "4"}};
  job.path_class = "L(D|S|P){0,1}E";
  job.reference = {"ref-direct-0001", 256, 0, "L(D|S|P){0,1}E", true, 0};
  job.metrics = {{"relmse", relmse}, {"flip_mean", 0.08}, {"psnr", 31.5}};
  job.full_reference = results::ReferenceUse{"ref-all-0001", 256, 0, "all paths", false, 12.5};
  job.metrics_full = {{"relmse", 4 * relmse}, {"flip_mean", 0.21}, {"psnr", 22.0}};
  results::Convergence convergence;
  convergence.x_label = "iterations";
  for (int i = 0; i < 5; ++i) {
    const double x = std::pow(2.0, i);
    convergence.points.push_back({x, {{"relmse", relmse * 8 / std::pow(x, 0.98)}}, 0.1 * x});
  }
  convergence.fit_metric = "relmse";
  convergence.fit_slope = -0.98;
  convergence.fit_slope_ci95 = 0.03;
  job.convergence = convergence;
  job.timings = nestedPassTimings(frame_scale);
  job.upload_ms = 4.5;
  job.prepare_ms = 12.0;
  job.iterate_ms = 0;
  job.iterations = 0;
  job.outputs = outputsOf(job.slug, false);
  job.seconds = 3.2;
  job.job_hash = "j-" + job.slug;
  return job;
}

results::RunResults syntheticReportResults(const std::string& run_id, const std::string& commit) {
  results::RunResults results;
  results::RunInfo& run = results.run;
  run.id = run_id;
  run.suite = "smoke";
  run.suite_description = "Cornell box: reference and direct <shadow maps> & friends";
  run.suite_file = "suites/smoke.toml";
  run.started = "2026-11-22T10:04:05Z";
  run.finished = "2026-11-22T10:06:40Z";
  run.gibench_version = "0.1.0+" + commit.substr(0, 12);
  run.git_commit = commit;
  run.build_type = "Release";
  run.host = "testhost";
  run.cpu = "Test CPU @ 3 GHz";
  run.cpu_cores = 2;
  run.embree_version = "3.13.5";
  run.gl_vendor = "Mesa";
  run.gl_renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
  run.gl_version = "4.5 (Core Profile) Mesa 22.3.6";
  run.store = "/tmp/store";
  results.primary_metric = "relmse";

  results::JobResult reference = cornellJob("cornell-reference", "cornell-reference", "reference");
  reference.path_class = "all paths";
  reference.reference = {"ref-all-0001", 256, 0, "all paths", false, 12.5};
  reference.metrics = {{"relmse", 0.0009}, {"flip_mean", 0.02}, {"psnr", 41.0}};
  results::Convergence spp;
  spp.x_label = "spp";
  for (double x : {16.0, 64.0, 256.0}) spp.points.push_back({x, {{"relmse", 0.2 / x}}, 0.01 * x});
  spp.fit_metric = "relmse";
  spp.fit_slope = -1.0;
  spp.fit_slope_ci95 = 0.01;
  reference.convergence = spp;
  reference.timings.reset();  // the reference renderer is not timed per pass
  reference.outputs = outputsOf(reference.slug, true);
  reference.seconds = 12.5;
  results.jobs.push_back(reference);

  results.jobs.push_back(syntheticTechniqueJob("shadow=pcf,light_samples=4", 0.0021));
  results::JobResult vsm = syntheticTechniqueJob("shadow=vsm,light_samples=4", 0.0035, 1.5);
  vsm.parameters[0].second = "vsm";
  vsm.convergence->points.resize(2);
  vsm.convergence->fit_slope_ci95 = std::numeric_limits<double>::infinity();
  results.jobs.push_back(vsm);

  // The PCF job also iterates, with per-iteration passes, counts and an auxiliary image, so the
  // report's figure parts are exercised.
  results::JobResult& pcf_job = results.jobs[1];
  pcf_job.iterations = 8;
  pcf_job.iterate_ms = 16.0;
  pcf_job.iteration_timings = nestedPassTimings(0.1, 8, "iteration");
  pcf_job.statistics = {{"vertices", 3000}, {"atlas_texels", 16000}};
  vsm.statistics = {{"vertices", 300}, {"atlas_texels", 16000}};
  results.jobs[2].statistics = vsm.statistics;
  pcf_job.auxiliary_images = {{"atlas", "the radiance atlas after 8 iterations",
                               "jobs/" + pcf_job.slug + "/image-atlas.exr",
                               "jobs/" + pcf_job.slug + "/image-atlas.png"}};
  results.charts = {{"Frame time against vertex count", "cornell-direct/*", "statistic:vertices",
                     "frame", "parameter:shadow", true, false, false},
                    {"Error against frame time", "*", "frame", "relmse", "", false, true, true}};

  const std::string pcf = results.jobs[1].id;
  results.paper = {{pcf, "relmse", 0.002, "", "Nijasure et al. 2005, Table 1", "64x64 grid"},
                   {pcf, "frame", 40.0, "ms", "Nijasure et al. 2005, Table 1", "Radeon 9800 Pro"}};

  // A figure as a figure suite declares it: the reference's picture beside the PCF image, the
  // PCF job's atlas (of its own size) under it, and a panel whose auxiliary image the reference
  // job does not have, so its page shows a note in that cell. The vsm job is in none.
  results::FigureSpec figure;
  figure.name = "fig-shadows";
  figure.title = "Fig. 1: the reference, PCF and its radiance atlas";
  figure.caption = "Path traced and PCF images above, the atlas under them.";
  figure.columns = 2;
  figure.panels = {{reference.id, "image", "Path traced", 1, 1, ""},
                   {pcf, "image", "PCF", 1, 2, "frame"},
                   {reference.id, "aux:atlas", "No atlas", 2, 1, "none"},
                   {pcf, "aux:atlas", "PCF's radiance atlas", 2, 2, "full:relmse"}};
  results.figures = {figure};
  return results;
}

void writeSyntheticOutputs(const std::filesystem::path& run_dir,
                           const results::RunResults& results) {
  for (const results::JobResult& job : results.jobs) {
    const results::JobOutputs& out = job.outputs;
    int variant = 0;
    std::vector<const std::string*> pngs = {&out.image_png, &out.reference_png, &out.difference_png,
                                            &out.flip_png};
    for (const results::AuxiliaryImageOutput& aux : job.auxiliary_images) pngs.push_back(&aux.png);
    for (const std::string* path : pngs) {
      ++variant;
      if (path->empty()) continue;
      std::filesystem::create_directories((run_dir / *path).parent_path());
      // An auxiliary image has a size of its own (an atlas is square), as a figure may show it.
      const bool auxiliary = variant > 4;
      const int width = auxiliary ? kAuxiliarySide : job.width;
      const int height = auxiliary ? kAuxiliarySide : job.height;
      image::Image picture(width, height);
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
          float* p = picture.pixel(x, y);
          p[0] = float(x) / float(width);
          p[1] = float(y) / float(height);
          p[2] = 0.25f * float(variant);
        }
      image::writePng(run_dir / *path, picture);
    }
    if (!out.thumbnail_png.empty())
      image::writePng(run_dir / out.thumbnail_png, syntheticViewerImage(job, "thumbnail"));
    // Linear data for the viewer: the image, its FLIP map and the shared reference.
    const image::Image picture = syntheticViewerImage(job, "image");
    const image::Image flip = syntheticViewerImage(job, "flip");
    if (!out.viewer_data.empty())
      image::writeViewerData(
          run_dir / out.viewer_data, out.viewer_data,
          {{"image", &picture}, {"flip", out.flip_png.empty() ? nullptr : &flip}});
    if (!out.reference_viewer_data.empty()) {
      std::filesystem::create_directories((run_dir / out.reference_viewer_data).parent_path());
      const image::Image reference = syntheticViewerImage(job, "reference");
      const image::Image standard_error = syntheticViewerImage(job, "stderr");
      image::writeViewerData(run_dir / out.reference_viewer_data, out.reference_viewer_data,
                             {{"reference", &reference}, {"stderr", &standard_error}});
    }
  }
}

void writeSyntheticRunDirectory(const std::filesystem::path& run_dir, results::RunResults& results,
                                const std::filesystem::path& store) {
  std::filesystem::create_directories(run_dir);
  results.run.store = store.string();
  writeSyntheticOutputs(run_dir, results);
  results::writeResultsFile(run_dir / "results.json", results);
}

void markFailed(results::JobResult& job, const std::string& reason) {
  job.failure = reason;
  job.metrics.clear();
  job.metrics_full.clear();
  job.timings.reset();
}

image::Image syntheticViewerImage(const results::JobResult& job, const std::string& layer) {
  const int channels = layer == "flip" ? 1 : 3;
  image::Image picture(job.width, job.height, channels);
  for (int y = 0; y < job.height; ++y)
    for (int x = 0; x < job.width; ++x) {
      float* p = picture.pixel(x, y);
      // Distinct, exactly representable in half floats: multiples of 1/64 up to 2.
      const float base = float((x + 2 * y) % 32) / 16.0f;
      if (layer == "flip") {
        p[0] = float((x + y) % 16) / 16.0f;
        continue;
      }
      const float offset = layer == "image" ? 0.125f : layer == "stderr" ? -0.5f : 0.0f;
      p[0] = std::max(0.0f, base + offset);
      p[1] = std::max(0.0f, 0.5f * base + offset);
      p[2] = std::max(0.0f, 0.25f + offset);
    }
  return picture;
}

}  // namespace gib::test
