#include "suites/job_execution.h"

#include "common/content_hash.h"
#include "common/input_error.h"
#include "common/splitmix.h"
#include "gib/version.h"
#include "image/display.h"
#include "image/output_files.h"
#include "metrics/metric_registry.h"
#include "metrics/pass_timing_summary.h"
#include "realtime/technique_output.h"
#include "realtime/technique_runner.h"
#include "reference/primary_agreement.h"
#include "reference/progressive_renderer.h"
#include "reference/reference_output.h"
#include "results/results_json.h"
#include "scene/builtin_scenes.h"
#include "suites/convergence_fit.h"
#include "suites/job_images.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <set>

namespace gib::suites {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The class the reference is rendered for: the technique's own unless the suite says otherwise.
scene::PathClass referenceClass(const PreparedJob& p) {
  const ReferenceSettings& r = p.job->settings.reference;
  if (r.paths) return scene::PathClass::ofExpression(*r.paths);
  scene::PathClass c = p.path_class;
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

// A reference a job is measured against: its class's, with the suite's environment occlusion, or
// the full one (every path, the environment occluded as physics has it).
struct JobReference {
  scene::PathClass path_class;
  bool full = false;
};

JobReference classReference(const PreparedJob& p) {
  return {referenceClass(p), false};
}
JobReference fullReference() {
  return {scene::PathClass{}, true};
}

// The spec of the job's reference, or of its obscurance (then the class is every path, which
// keeps the key canonical: the renderer ignores it).
ref::ReferenceSpec referenceSpec(const PreparedJob& p, const JobReference& of) {
  const scene::PathClass& path_class = of.path_class;
  ref::ReferenceSpec spec;
  spec.scene = p.job->scene.nameOrPath();
  spec.scene_parameters = assignmentStrings(p.job->scene_parameters);
  spec.width = p.width;
  spec.height = p.height;
  spec.spp = static_cast<std::uint32_t>(p.job->settings.reference.spp);
  spec.seed = p.job->settings.reference.seed;
  spec.path_class = p.obscurance ? scene::PathClass{} : path_class;
  spec.pixel_sampling = pixelSampling(p);
  spec.obscurance = p.obscurance;
  spec.environment_occlusion = of.full || p.job->settings.reference.environment_occlusion;
  spec.lens = p.job->settings.lens;
  return spec;
}

results::ReferenceUse referenceUse(const ref::StoredReference& stored, double seconds) {
  results::ReferenceUse use;
  use.key = stored.entry.key;
  use.spp = static_cast<int>(stored.entry.spec.spp);
  use.seed = stored.entry.spec.seed;
  use.path_class = ref::describeReferenceQuantity(stored.entry.spec);
  use.store_hit = stored.hit;
  use.pixel_sampling = ref::pixelSamplingName(stored.entry.spec.pixel_sampling);
  use.render_seconds = stored.hit ? 0.0 : seconds;
  return use;
}

// Fetches (or renders and stores) the reference of `path_class`, saying which on the way.
ref::StoredReference obtainReference(const PreparedJob& p, const JobEnvironment& env,
                                     const JobReference& of, results::ReferenceUse* use) {
  const ref::ReferenceSpec spec = referenceSpec(p, of);
  const std::string what = fmt::format(
      "reference {} ({}x{}, {} spp, {})", ref::describeReferenceQuantity(spec), spec.width,
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

// The pixels a technique job's metrics single out (metrics::MetricOptions): where its primary hit
// and the reference's disagree, and the region its own light reaches (Technique::measuredRegion);
// null where not known.
struct PixelMasks {
  const image::Image* disagreement = nullptr;
  const image::Image* region = nullptr;
};

metrics::MetricReport measure(const image::Image& reference, const image::Image& test,
                              const std::vector<std::string>& names, PixelMasks masks = {}) {
  metrics::MetricOptions options;
  options.disagreement = masks.disagreement;
  options.region = masks.region;
  return metrics::evaluateMetrics(reference, test, names, options);
}

// Whether a technique job has a full reference besides its class's: unless the class's is the
// full one (every path, the environment occluded) or the image is an obscurance, which no
// radiance reference measures.
bool needsFullReference(const PreparedJob& p) {
  if (p.job->isReference() || p.obscurance) return false;
  return referenceClass(p) != scene::PathClass{} ||
         !p.job->settings.reference.environment_occlusion;
}

void measureAgainstFullReference(const PreparedJob& p, const JobEnvironment& env,
                                 const JobDirectory& files, const image::Image& test,
                                 PixelMasks masks, results::JobResult& result) {
  if (!needsFullReference(p)) return;
  results::ReferenceUse use;
  const ref::StoredReference full = obtainReference(p, env, fullReference(), &use);
  result.full_reference = use;
  result.outputs.full_reference_exr = copyReferenceExr(files, full);
  result.metrics_full = measure(full.mean, test, p.job->settings.metrics, masks).values;
}

// The reference alone: the stored reference, and when the case lists checkpoints an independent
// render measured against it at each, for the convergence plot.
void runReferenceJob(const PreparedJob& p, const JobEnvironment& env, const JobDirectory& files,
                     results::JobResult& result) {
  const ref::StoredReference reference =
      obtainReference(p, env, classReference(p), &result.reference);
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
    settings.environment_occlusion = p.job->settings.reference.environment_occlusion;
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
    image::Metadata metadata = ref::referenceMetadata(p.scene, settings);
    ref::addRunMetadata(metadata, final_render);
    const fs::path png = ref::writeReferenceOutputs(files.image_exr, final_render, metadata);
    result.outputs.image = files.relative(files.image_exr);
    result.outputs.image_png = files.relative(png);
  }
  writeComparisonImages(files, reference, last_mean, last_report, result.outputs);
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
                                          const image::Image& reference, PixelMasks masks) {
  results::Convergence convergence;
  convergence.x_label = "iterations";
  for (const rt::IterationCapture& capture : captures)
    convergence.points.push_back(
        {double(capture.iterations),
         measure(reference, capture.image, p.job->settings.metrics, masks).values,
         capture.iterate_ms * 1e-3});
  fitConvergence(convergence);
  return convergence;
}

// Pixels whose primary hit the rasteriser and the pixel-centre reference disagree on: counted
// and written as a mask (white), not hidden (reference/primary_agreement.h).
// Returns the mask (one channel, 1 where they disagree).
image::Image recordPrimaryAgreement(const PreparedJob& p, const JobDirectory& files,
                                    const rt::PrimarySurfaces& primary,
                                    results::JobResult& result) {
  const ref::PrimaryAgreement agreement =
      ref::comparePrimarySurfaces(p.scene, primary.position, primary.normal);
  result.disagreement_pixels = static_cast<long long>(agreement.disagreements);
  // One channel: shown grey, so white where they disagree.
  image::writePng(files.disagreement_png, agreement.mask);
  result.outputs.disagreement_png = files.relative(files.disagreement_png);
  return agreement.mask;
}

void runTechniqueJob(const PreparedJob& p, const JobEnvironment& env, const JobDirectory& files,
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

  image::Metadata metadata = rt::techniqueOutputMetadata(
      p.scene, *p.technique, *p.parameters, settings, run, result.timings->root().reported.median);
  const rt::TechniqueOutputFiles written =
      rt::writeTechniqueOutputs(files.image_exr, run, metadata);
  result.outputs.image = files.relative(files.image_exr);
  result.outputs.image_png = files.relative(written.png);
  for (const rt::AuxiliaryImageFiles& aux : written.auxiliary)
    result.auxiliary_images.push_back(
        {aux.name, aux.description, files.relative(aux.exr), files.relative(aux.png)});
  image::writeTextFile(files.timings_json,
                       results::passTimingsToJson(*result.timings).dump(2) + "\n");
  result.outputs.timings_json = files.relative(files.timings_json);

  const ref::StoredReference reference =
      obtainReference(p, env, classReference(p), &result.reference);
  std::optional<image::Image> disagreement;
  if (run.primary) disagreement = recordPrimaryAgreement(p, files, *run.primary, result);
  const PixelMasks masks{disagreement ? &*disagreement : nullptr,
                         run.region ? &*run.region : nullptr};
  const metrics::MetricReport report =
      measure(reference.mean, run.image, p.job->settings.metrics, masks);
  result.metrics = report.values;
  writeComparisonImages(files, reference, run.image, report, result.outputs);
  measureAgainstFullReference(p, env, files, run.image, masks, result);
  if (!p.job->settings.checkpoints.empty())
    result.convergence = techniqueConvergence(p, run.captures, reference.mean, masks);
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
  // Only when given, so that the hash of every job with a class of bounces stays the same.
  if (s.reference.paths) hasher.addString("paths=" + *s.reference.paths);
  hasher.addString(ref::pixelSamplingName(pixelSampling(p)));
  for (const std::string& metric : s.metrics) hasher.addString(metric);
  for (int checkpoint : s.checkpoints) hasher.addU64(std::uint64_t(checkpoint));
  if (s.iterations) hasher.addString(fmt::format("iterations={}", *s.iterations));
  // Only for an obscurance, so that the hash of every radiance job stays the same.
  if (p.obscurance) hasher.addString(scene::describeObscurance(*p.obscurance));
  // Likewise only without the environment's occlusion.
  if (!s.reference.environment_occlusion) hasher.addString("environment_occlusion=off");
  return hasher.hexDigest();
}

}  // namespace

PreparedJob prepareJob(const Job& job) {
  PreparedJob p;
  p.job = &job;
  try {
    p.scene = scene::loadScene(job.scene.nameOrPath(), assignmentStrings(job.scene_parameters));
    scene::applyLens(p.scene.camera, job.settings.lens, "lens.radius", "lens.focus_distance");
    p.width = job.settings.width.value_or(p.scene.default_width);
    p.height = job.settings.height.value_or(p.scene.default_height);
    if (!job.isReference()) {
      p.technique = &rt::findTechnique(job.technique);
      p.parameters =
          parseParameters(p.technique->parameters, assignmentStrings(job.technique_parameters),
                          fmt::format("technique '{}'", job.technique));
      const std::unique_ptr<rt::Technique> technique = p.technique->create(*p.parameters);
      p.path_class = technique->pathClassAfter(job.settings.iterations.value_or(0));
      p.obscurance = technique->imageObscurance();
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
      p.obscurance ? scene::describeObscurance(*p.obscurance)
                   : scene::describePathClass(job.isReference() ? referenceClass(p) : p.path_class);
  result.job_hash = p.hash;
  return result;
}

results::JobResult executeJob(const PreparedJob& p, const JobEnvironment& env,
                              const JobDirectory& files, rt::gl::GlIdentity* gl) {
  const Clock::time_point start = Clock::now();
  const Job& job = *p.job;
  results::JobResult result = describeJob(p);
  if (job.isReference())
    runReferenceJob(p, env, files, result);
  else
    runTechniqueJob(p, env, files, result, gl);
  result.seconds = secondsSince(start);
  return result;
}

namespace {

// The job's references: its class's, then (technique jobs) the full one when that differs; one
// for an obscurance (referenceSpec makes it the obscurance's).
std::vector<JobReference> jobReferenceList(const PreparedJob& p) {
  std::vector<JobReference> references = {classReference(p)};
  if (needsFullReference(p)) references.push_back(fullReference());
  return references;
}

}  // namespace

std::vector<ref::ReferenceSpec> jobReferences(const PreparedJob& p) {
  std::vector<ref::ReferenceSpec> specs;
  for (const JobReference& of : jobReferenceList(p)) specs.push_back(referenceSpec(p, of));
  return specs;
}

void obtainJobReferences(const PreparedJob& p, const JobEnvironment& env) {
  for (const JobReference& of : jobReferenceList(p)) {
    results::ReferenceUse use;
    obtainReference(p, env, of, &use);
  }
}

metrics::PassTimings repeatTechniqueJob(const PreparedJob& p, const JobEnvironment& env) {
  rt::TechniqueRunSettings settings = techniqueSettings(p, env);
  settings.capture_after.clear();  // the convergence series is the first run's
  return metrics::summarizeProfile(
      rt::runTechnique(p.scene, *p.technique, *p.parameters, settings).profile);
}

}  // namespace gib::suites
