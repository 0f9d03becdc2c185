#include "suites/job_execution.h"

#include "common/content_hash.h"
#include "common/input_error.h"
#include "common/splitmix.h"
#include "gib/version.h"
#include "image/display.h"
#include "image/exr_io.h"
#include "image/output_files.h"
#include "image/viewer_data.h"
#include "metrics/convergence_fit.h"
#include "metrics/error_map_display.h"
#include "metrics/metric_registry.h"
#include "metrics/pass_timing_summary.h"
#include "realtime/technique_output.h"
#include "realtime/technique_runner.h"
#include "reference/primary_agreement.h"
#include "reference/progressive_renderer.h"
#include "reference/reference_output.h"
#include "results/results_json.h"
#include "scene/builtin_scenes.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

namespace gib::suites {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string relativePath(const fs::path& run_dir, const fs::path& file) {
  return file.lexically_relative(run_dir).generic_string();
}

// The class the reference is rendered for: the technique's own unless the suite says otherwise.
scene::PathClass referenceClass(const PreparedJob& p) {
  scene::PathClass c = p.path_class;
  const ReferenceSettings& r = p.job->settings.reference;
  if (r.min_bounces) c.min_bounces = *r.min_bounces;
  if (r.max_bounces) c.max_bounces = *r.max_bounces;
  return c;
}

// Where the reference's camera rays go: the suite's choice, else pixel centres for a technique
// (the rasteriser's sample position: its error is then its lighting's) and the box filter for
// the reference's own job (docs/rendering.md, "Pixel sampling").
ref::PixelSampling pixelSampling(const PreparedJob& p) {
  if (const std::optional<std::string>& chosen = p.job->settings.reference.pixel_sampling)
    return ref::parsePixelSampling(*chosen);
  return p.job->isReference() ? ref::PixelSampling::kArea : ref::PixelSampling::kCenter;
}

ref::ReferenceSpec referenceSpec(const PreparedJob& p, const scene::PathClass& path_class) {
  ref::ReferenceSpec spec;
  spec.scene = p.job->scene.nameOrPath();
  spec.scene_parameters = assignmentStrings(p.job->scene_parameters);
  spec.width = p.width;
  spec.height = p.height;
  spec.spp = static_cast<std::uint32_t>(p.job->settings.reference.spp);
  spec.seed = p.job->settings.reference.seed;
  spec.path_class = path_class;
  spec.pixel_sampling = pixelSampling(p);
  return spec;
}

results::ReferenceUse referenceUse(const ref::StoredReference& stored, double seconds) {
  results::ReferenceUse use;
  use.key = stored.entry.key;
  use.spp = static_cast<int>(stored.entry.spec.spp);
  use.seed = stored.entry.spec.seed;
  use.path_class = scene::describePathClass(stored.entry.spec.path_class);
  use.store_hit = stored.hit;
  use.pixel_sampling = ref::pixelSamplingName(stored.entry.spec.pixel_sampling);
  use.render_seconds = stored.hit ? 0.0 : seconds;
  return use;
}

// Fetches (or renders and stores) the reference of `path_class`, saying which on the way.
ref::StoredReference obtainReference(const PreparedJob& p, const JobEnvironment& env,
                                     const scene::PathClass& path_class,
                                     results::ReferenceUse* use) {
  const ref::ReferenceSpec spec = referenceSpec(p, path_class);
  const std::string what = fmt::format(
      "reference {} ({}x{}, {} spp, {})", scene::describePathClass(path_class), spec.width,
      spec.height, spec.spp,
      spec.pixel_sampling == ref::PixelSampling::kCenter ? "pixel centres" : "box filter");
  const Clock::time_point start = Clock::now();
  ref::StoredReference stored =
      env.store->obtain(p.scene, spec, env.progress, [&](const std::string& holder) {
        if (env.note)
          env.note(fmt::format("{}: being rendered by {}, waiting", what,
                               holder.empty() ? "another process" : holder));
      });
  const double seconds = secondsSince(start);
  if (env.note)
    env.note(stored.hit ? fmt::format("{}: in the store", what)
                        : fmt::format("{}: rendered in {:.1f} s", what, seconds));
  *use = referenceUse(stored, seconds);
  return stored;
}

// `disagreement`: the pixels whose primary hit the technique and the reference disagree on, or
// null (metrics::MetricOptions::disagreement).
metrics::MetricReport measure(const image::Image& reference, const image::Image& test,
                              const std::vector<std::string>& names,
                              const image::Image* disagreement = nullptr) {
  metrics::MetricOptions options;
  options.disagreement = disagreement;
  return metrics::evaluateMetrics(reference, test, names, options);
}

// The metric the convergence fit follows: the one the index shows (relMSE when measured, else
// the first value, as results::RunResults::primary_metric), so that the slope describes the
// number a reader compares.
std::string fitMetric(const results::NamedValues& values) {
  for (const auto& [name, value] : values)
    if (name == "relmse") return name;
  return values.empty() ? std::string() : values.front().first;
}

// Least-squares slope of log(metric) against log(x) over the points where both are positive.
void fitConvergence(results::Convergence& convergence) {
  if (convergence.points.empty()) return;
  const std::string metric = fitMetric(convergence.points.front().metrics);
  std::vector<double> x, y;
  for (const results::Convergence::Point& point : convergence.points)
    for (const auto& [name, value] : point.metrics)
      if (name == metric && point.x > 0 && value > 0 && std::isfinite(value)) {
        x.push_back(std::log(point.x));
        y.push_back(std::log(value));
      }
  if (x.size() < 2) return;
  const metrics::LinearFit fit = metrics::fitLine(x, y);
  convergence.fit_metric = metric;
  convergence.fit_slope = fit.slope;
  convergence.fit_intercept = fit.intercept;
  convergence.fit_slope_ci95 = fit.slope_ci95;
}

// Thumbnails are at most this wide: a 100-job index stays light however large the images are.
constexpr int kThumbnailWidth = 128;

// The report viewer's linear data of the reference (mean and standard error of the mean), once
// per reference and run: every job measured against it shares the file.
std::string writeReferenceViewerData(const fs::path& run_dir,
                                     const ref::StoredReference& reference) {
  const fs::path path = run_dir / "viewer" / (reference.entry.key + ".js");
  const std::string relative = relativePath(run_dir, path);
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return relative;  // written by another job of the run
  fs::create_directories(path.parent_path(), ec);
  image::Image standard_error;
  if (reference.variance.pixelCount() > 0) {
    standard_error = reference.variance;
    for (float& value : standard_error.data()) value = std::sqrt(std::max(value, 0.0f));
  }
  image::writeViewerData(path, relative,
                         {{"reference", &reference.mean}, {"stderr", &standard_error}});
  return relative;
}

// A full-precision copy of the stored reference's EXR (mean, variance, direct and indirect
// layers) in the run directory, once per reference and run, so the run stands alone.
std::string copyReferenceExr(const fs::path& run_dir, const ref::StoredReference& reference) {
  const fs::path path = run_dir / "references" / (reference.entry.key + ".exr");
  const std::string relative = relativePath(run_dir, path);
  std::error_code ec;
  if (fs::is_regular_file(path, ec)) return relative;  // copied by another job of the run
  fs::create_directories(path.parent_path(), ec);
  image::copyFileAtomically(reference.entry.dir / "reference.exr", path);
  return relative;
}

// reference.png (a copy of the store's, so the run directory stands alone), difference.png and
// flip.png of `test` against `reference`; the thumbnail and the viewer's linear data.
void writeComparisonImages(const fs::path& run_dir, const fs::path& job_dir,
                           const ref::StoredReference& reference, const image::Image& test,
                           const metrics::MetricReport& report, results::JobOutputs& outputs) {
  const fs::path reference_png = job_dir / "reference.png";
  image::writePng(reference_png, reference.mean);
  outputs.reference_png = relativePath(run_dir, reference_png);
  outputs.reference_exr = copyReferenceExr(run_dir, reference);
  // A picture that is small enough already is its own thumbnail: no second copy of it.
  const image::Image& pictured = test.width() > 0 ? test : reference.mean;
  const std::string& small_enough = test.width() > 0 ? outputs.image_png : outputs.reference_png;
  if (pictured.width() <= kThumbnailWidth && !small_enough.empty()) {
    outputs.thumbnail_png = small_enough;
  } else {
    const fs::path thumbnail = job_dir / "thumbnail.png";
    image::writePng(thumbnail, image::downsampleToWidth(pictured, kThumbnailWidth));
    outputs.thumbnail_png = relativePath(run_dir, thumbnail);
  }
  outputs.reference_viewer_data = writeReferenceViewerData(run_dir, reference);
  const image::Image* flip = nullptr;
  for (const auto& [name, map] : report.maps)
    if (name == "flip") flip = &map;
  const fs::path viewer = job_dir / "viewer.js";
  outputs.viewer_data = relativePath(run_dir, viewer);
  image::writeViewerData(viewer, outputs.viewer_data, {{"image", &test}, {"flip", flip}});
  if (test.width() == 0) return;
  const fs::path difference_png = job_dir / "difference.png";
  image::writePng(difference_png,
                  metrics::errorMapForDisplay(
                      "difference", metrics::absoluteLuminanceDifference(reference.mean, test)));
  outputs.difference_png = relativePath(run_dir, difference_png);
  if (flip) {
    const fs::path flip_png = job_dir / "flip.png";
    image::writePng(flip_png, metrics::errorMapForDisplay("flip", *flip));
    outputs.flip_png = relativePath(run_dir, flip_png);
  }
}

void measureAgainstFullReference(const PreparedJob& p, const JobEnvironment& env,
                                 const image::Image& test, const image::Image* disagreement,
                                 results::JobResult& result) {
  if (referenceClass(p) == scene::PathClass{}) return;  // the class reference is the full one
  results::ReferenceUse use;
  const ref::StoredReference full = obtainReference(p, env, scene::PathClass{}, &use);
  result.full_reference = use;
  result.outputs.full_reference_exr = copyReferenceExr(env.run_dir, full);
  result.metrics_full = measure(full.mean, test, p.job->settings.metrics, disagreement).values;
}

// The reference alone: the stored reference, and when the case lists checkpoints an independent
// render measured against it at each, for the convergence plot.
void runReferenceJob(const PreparedJob& p, const JobEnvironment& env, const fs::path& job_dir,
                     results::JobResult& result) {
  const ref::StoredReference reference =
      obtainReference(p, env, referenceClass(p), &result.reference);
  const std::vector<int>& checkpoints = p.job->settings.checkpoints;
  metrics::MetricReport last_report;
  image::Image last_mean;
  if (!checkpoints.empty()) {
    ref::RenderSettings settings;
    settings.width = p.width;
    settings.height = p.height;
    // The convergence series is rendered with samples of its own: error against a reference
    // that shares its samples would look better than it is.
    settings.seed = independentSeed(p.job->settings.reference.seed);
    settings.path_class = referenceClass(p);
    settings.pixel_sampling = pixelSampling(p);
    settings.progress = env.progress;
    results::Convergence convergence;
    convergence.x_label = "spp";
    // One render to the last checkpoint yields every checkpoint that is a pass boundary
    // (1, 2, 4, …); the others are rendered on their own.
    std::set<int> pending(checkpoints.begin(), checkpoints.end());
    auto record = [&](int spp, const image::Image& mean, double seconds) {
      if (!pending.erase(spp)) return;
      metrics::MetricReport report = measure(reference.mean, mean, p.job->settings.metrics);
      convergence.points.push_back({double(spp), report.values, seconds});
      if (spp == checkpoints.back()) {
        last_report = std::move(report);
        last_mean = mean;
      }
    };
    if (env.note)
      env.note(fmt::format("convergence: independent render to {} spp", checkpoints.back()));
    settings.spp = static_cast<std::uint32_t>(checkpoints.back());
    const Clock::time_point start = Clock::now();
    ref::RenderResult final_render =
        ref::renderReference(p.scene, settings, [&](std::uint32_t spp, const image::Image& mean) {
          record(int(spp), mean, secondsSince(start));
        });
    for (int spp : std::vector<int>(pending.begin(), pending.end())) {
      settings.spp = static_cast<std::uint32_t>(spp);
      const Clock::time_point own_start = Clock::now();
      const ref::RenderResult own = ref::renderReference(p.scene, settings);
      record(spp, own.mean, secondsSince(own_start));
    }
    std::sort(convergence.points.begin(), convergence.points.end(),
              [](const auto& a, const auto& b) { return a.x < b.x; });
    fitConvergence(convergence);
    result.convergence = std::move(convergence);
    result.metrics = last_report.values;

    settings.spp = static_cast<std::uint32_t>(checkpoints.back());
    const fs::path exr = job_dir / "image.exr";
    image::Metadata metadata = ref::referenceMetadata(p.scene, settings);
    ref::addRunMetadata(metadata, final_render);
    const fs::path png = ref::writeReferenceOutputs(exr, final_render, metadata);
    result.outputs.image = relativePath(env.run_dir, exr);
    result.outputs.image_png = relativePath(env.run_dir, png);
  }
  writeComparisonImages(env.run_dir, job_dir, reference, last_mean, last_report, result.outputs);
}

rt::TechniqueRunSettings techniqueSettings(const PreparedJob& p, const JobEnvironment& env) {
  rt::TechniqueRunSettings settings;
  settings.width = p.width;
  settings.height = p.height;
  settings.frames = p.job->settings.frames;
  settings.warmup_frames = p.job->settings.warmup;
  settings.iterations = p.job->settings.iterationCount();
  settings.capture_after = p.job->settings.checkpoints;
  settings.context = env.gl;
  settings.services.ray_caster = ref::embreeRayCasterFactory();
  settings.capture_primary_surfaces = pixelSampling(p) == ref::PixelSampling::kCenter;
  return settings;
}

// An iterative technique's error after each checkpoint's number of iterations, from the images
// the run captured on its way.
results::Convergence techniqueConvergence(const PreparedJob& p,
                                          const std::vector<rt::IterationCapture>& captures,
                                          const image::Image& reference,
                                          const image::Image* disagreement) {
  results::Convergence convergence;
  convergence.x_label = "iterations";
  for (const rt::IterationCapture& capture : captures)
    convergence.points.push_back(
        {double(capture.iterations),
         measure(reference, capture.image, p.job->settings.metrics, disagreement).values,
         capture.iterate_ms * 1e-3});
  fitConvergence(convergence);
  return convergence;
}

// Pixels whose primary hit the rasteriser and the pixel-centre reference disagree on: counted
// and written as a mask (white), not hidden (reference/primary_agreement.h).
// Returns the mask (one channel, 1 where they disagree).
image::Image recordPrimaryAgreement(const PreparedJob& p, const JobEnvironment& env,
                                    const fs::path& job_dir, const rt::PrimarySurfaces& primary,
                                    results::JobResult& result) {
  const ref::PrimaryAgreement agreement =
      ref::comparePrimarySurfaces(p.scene, primary.position, primary.normal);
  result.disagreement_pixels = static_cast<long long>(agreement.disagreements);
  const fs::path png = job_dir / "disagreement.png";
  image::writePng(png, agreement.mask);  // one channel: shown grey, so white where they disagree
  result.outputs.disagreement_png = relativePath(env.run_dir, png);
  return agreement.mask;
}

void runTechniqueJob(const PreparedJob& p, const JobEnvironment& env, const fs::path& job_dir,
                     results::JobResult& result, rt::gl::GlIdentity* gl) {
  const rt::TechniqueRunSettings settings = techniqueSettings(p, env);
  if (env.note)
    env.note(fmt::format("{}: {} warm-up + {} measured frames at {}x{}", p.technique->name,
                         settings.warmup_frames, settings.frames, p.width, p.height));
  const rt::TechniqueRunResult run =
      rt::runTechnique(p.scene, *p.technique, *p.parameters, settings);
  if (gl) *gl = run.gl;
  result.timings = metrics::summarizeProfile(run.profile);
  result.upload_ms = run.upload_ms;
  result.prepare_ms = run.prepare_ms;
  result.iterate_ms = run.iterate_ms;
  result.iterations = run.iterations;
  if (run.iteration_profile.measured_frames > 0)
    result.iteration_timings = metrics::summarizeProfile(run.iteration_profile);
  for (const rt::TechniqueStatistic& statistic : run.statistics)
    result.statistics.emplace_back(statistic.name, statistic.value);

  const fs::path exr = job_dir / "image.exr";
  image::Metadata metadata = rt::techniqueOutputMetadata(
      p.scene, *p.technique, *p.parameters, settings, run, result.timings->root().reported.median);
  const rt::TechniqueOutputFiles files = rt::writeTechniqueOutputs(exr, run, metadata);
  result.outputs.image = relativePath(env.run_dir, exr);
  result.outputs.image_png = relativePath(env.run_dir, files.png);
  for (const rt::AuxiliaryImageFiles& aux : files.auxiliary)
    result.auxiliary_images.push_back({aux.name, aux.description,
                                       relativePath(env.run_dir, aux.exr),
                                       relativePath(env.run_dir, aux.png)});
  const fs::path timings = job_dir / "timings.json";
  image::writeTextFile(timings, results::passTimingsToJson(*result.timings).dump(2) + "\n");
  result.outputs.timings_json = relativePath(env.run_dir, timings);

  const ref::StoredReference reference =
      obtainReference(p, env, referenceClass(p), &result.reference);
  std::optional<image::Image> disagreement;
  if (run.primary) disagreement = recordPrimaryAgreement(p, env, job_dir, *run.primary, result);
  const image::Image* mask = disagreement ? &*disagreement : nullptr;
  const metrics::MetricReport report =
      measure(reference.mean, run.image, p.job->settings.metrics, mask);
  result.metrics = report.values;
  writeComparisonImages(env.run_dir, job_dir, reference, run.image, report, result.outputs);
  measureAgainstFullReference(p, env, run.image, mask, result);
  if (!p.job->settings.checkpoints.empty())
    result.convergence = techniqueConvergence(p, run.captures, reference.mean, mask);
}

std::string jobHash(const PreparedJob& p) {
  const Job& job = *p.job;
  ContentHasher hasher;
  hasher.addString("gibench-job/1");
  hasher.addString(kVersion);
  hasher.addString(job.id);
  hasher.addString(p.scene_hash);
  hasher.addU64(std::uint64_t(p.width));
  hasher.addU64(std::uint64_t(p.height));
  hasher.addString(job.technique);
  if (p.parameters)
    for (const auto& [key, value] : p.parameters->canonical()) hasher.addString(key + "=" + value);
  const RunSettings& s = job.settings;
  for (int value : {s.frames, s.warmup, s.repeats, s.reference.spp,
                    s.reference.min_bounces.value_or(-1), s.reference.max_bounces.value_or(-1)})
    hasher.addU64(std::uint64_t(std::int64_t(value)));
  hasher.addU64(s.reference.seed);
  hasher.addString(ref::pixelSamplingName(pixelSampling(p)));
  for (const std::string& metric : s.metrics) hasher.addString(metric);
  for (int checkpoint : s.checkpoints) hasher.addU64(std::uint64_t(checkpoint));
  if (s.iterations) hasher.addString(fmt::format("iterations={}", *s.iterations));
  return hasher.hexDigest();
}

}  // namespace

PreparedJob prepareJob(const Job& job) {
  PreparedJob p;
  p.job = &job;
  try {
    p.scene = scene::loadScene(job.scene.nameOrPath(), assignmentStrings(job.scene_parameters));
    p.width = job.settings.width.value_or(p.scene.default_width);
    p.height = job.settings.height.value_or(p.scene.default_height);
    if (!job.isReference()) {
      p.technique = &rt::findTechnique(job.technique);
      p.parameters =
          parseParameters(p.technique->parameters, assignmentStrings(job.technique_parameters),
                          fmt::format("technique '{}'", job.technique));
      const std::unique_ptr<rt::Technique> technique = p.technique->create(*p.parameters);
      p.path_class = technique->pathClassAfter(job.settings.iterations.value_or(0));
      if (!job.settings.checkpoints.empty() && !technique->iterative())
        throw InputError(fmt::format(
            "checkpoints are iteration counts of an iterative technique, and '{}' renders in "
            "one step; remove checkpoints from case '{}'",
            job.technique, job.case_name));
      if (job.settings.iterations && !technique->iterative())
        throw InputError(fmt::format(
            "'{}' renders in one step and takes no iterations; remove iterations from case '{}'",
            job.technique, job.case_name));
    }
  } catch (const InputError& e) {
    throw InputError(fmt::format("job {}: {}", job.id, e.what()));
  }
  p.scene_hash = scene::hashScene(p.scene);
  p.hash = jobHash(p);
  return p;
}

results::JobResult describeJob(const PreparedJob& p) {
  const Job& job = *p.job;
  results::JobResult result;
  result.id = job.id;
  result.slug = job.slug;
  result.case_name = job.case_name;
  result.scene = job.scene.name;
  if (!job.scene.builtin()) result.scene_file = job.scene.file.string();
  result.scene_hash = p.scene_hash;
  result.technique = job.technique;
  if (p.parameters) result.parameters = p.parameters->canonical();
  result.scene_parameters = job.scene_parameters;
  result.width = p.width;
  result.height = p.height;
  result.path_class =
      scene::describePathClass(job.isReference() ? referenceClass(p) : p.path_class);
  result.job_hash = p.hash;
  return result;
}

results::JobResult executeJob(const PreparedJob& p, const JobEnvironment& env,
                              const fs::path& job_dir, rt::gl::GlIdentity* gl) {
  const Clock::time_point start = Clock::now();
  const Job& job = *p.job;
  results::JobResult result = describeJob(p);
  if (job.isReference())
    runReferenceJob(p, env, job_dir, result);
  else
    runTechniqueJob(p, env, job_dir, result, gl);
  result.seconds = secondsSince(start);
  return result;
}

namespace {

// The classes of the job's references: its class's, then (technique jobs) the full one when that
// differs.
std::vector<scene::PathClass> referenceClasses(const PreparedJob& p) {
  std::vector<scene::PathClass> classes = {referenceClass(p)};
  if (!p.job->isReference() && classes.front() != scene::PathClass{})
    classes.push_back(scene::PathClass{});
  return classes;
}

}  // namespace

std::vector<ref::ReferenceSpec> jobReferences(const PreparedJob& p) {
  std::vector<ref::ReferenceSpec> specs;
  for (const scene::PathClass& path_class : referenceClasses(p))
    specs.push_back(referenceSpec(p, path_class));
  return specs;
}

void obtainJobReferences(const PreparedJob& p, const JobEnvironment& env) {
  for (const scene::PathClass& path_class : referenceClasses(p)) {
    results::ReferenceUse use;
    obtainReference(p, env, path_class, &use);
  }
}

metrics::PassTimings repeatTechniqueJob(const PreparedJob& p, const JobEnvironment& env) {
  rt::TechniqueRunSettings settings = techniqueSettings(p, env);
  settings.capture_after.clear();  // the convergence series is the first run's
  return metrics::summarizeProfile(
      rt::runTechnique(p.scene, *p.technique, *p.parameters, settings).profile);
}

void recordRepeats(results::JobResult& result, std::vector<metrics::PassTimings> repeats) {
  if (repeats.size() < 2) return;
  std::vector<std::size_t> order(repeats.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return repeats[a].root().reported.median < repeats[b].root().reported.median;
  });
  result.timings = repeats[order[(order.size() - 1) / 2]];
  result.repeats = std::move(repeats);
}

}  // namespace gib::suites
