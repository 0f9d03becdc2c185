// A suite: the cases a run renders and measures (scene × technique × parameter sweeps), the
// reference each case is measured against, the metrics and the timing repetitions. Read from a
// TOML file by suites/suite_file.h, turned into jobs by suites/job_expansion.h. Every value here
// has been validated against the scene, technique and metric registries.
#pragma once

#include "results/results.h"
#include "scene/scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gib::suites {

// The technique name of a case that renders the reference alone (a convergence series of the
// path tracer, say).
inline constexpr const char* kReferenceTechnique = "reference";

// The reference render a job is measured against.
struct ReferenceSettings {
  int spp = 1024;
  unsigned long long seed = 0;
  // The path class (scene/path_class.h): a range of bounces, or a path expression (its text as
  // PathExpression::text() gives it), never both. Absent: the technique's own
  // (Technique::pathClass()), every path for a reference case. max_bounces may be
  // PathClass::kUnlimited.
  std::optional<int> min_bounces;
  std::optional<int> max_bounces;
  std::optional<std::string> paths;
  // Where the reference's camera rays go ("center" or "area", ref::parsePixelSampling). Absent:
  // pixel centres for a technique case (its error is its lighting's, not anti-aliasing's), the
  // box filter for a reference case (the reference's own convergence, as other renderers do it).
  std::optional<std::string> pixel_sampling;
  // False: the environment lights diffuse and glossy surfaces unblocked in the job's class
  // reference (ref::RenderSettings::environment_occlusion), to tell an environment-mapping
  // technique's convolution error from its missing shadows; the full reference keeps it.
  bool environment_occlusion = true;

  bool operator==(const ReferenceSettings&) const = default;
};

// One parameter of a case: a fixed value, or a sweep over several. Values are canonical
// (ParameterValues::canonical()): `4`, `4.0` and `4e0` of an integer parameter are all "4".
struct Sweep {
  std::string key;
  std::vector<std::string> values;  // at least one, no two equal
  bool swept = false;               // written as an array: the value is part of the job id
};

// What the case renders: a built-in scene or a scene file.
struct SceneSpec {
  std::string name;            // the built-in name, or the file's stem
  std::filesystem::path file;  // absolute path of a scene file; empty for a built-in scene
  bool builtin() const { return file.empty(); }
  // What scene::loadScene takes: the built-in name or the file's path.
  std::string nameOrPath() const { return builtin() ? name : file.string(); }
};

// How a case's jobs are rendered and measured: what [defaults] and a case set besides the scene,
// technique and their parameters. A job carries its case's settings unchanged.
struct RunSettings {
  std::optional<int> width, height;  // absent: the scene's default size
  int frames = 8;                    // measured frames of a technique job
  int warmup = 2;                    // frames rendered before them
  // Whole runs of a technique job (each with a fresh GL context), interleaved with the other
  // jobs' repeats: timing comparisons then test per-repeat medians, not frames of one run.
  int repeats = 1;
  std::vector<std::string> metrics;  // metric registry names, catalogue order
  ReferenceSettings reference;
  // The thin lens over the scene's camera (`lens = { radius, focus_distance }`, scene::applyLens):
  // the reference renders its depth of field; a technique keeps its pinhole, measured against it.
  scene::LensSetting lens;
  // Optional series, strictly increasing: spp of a reference case, iterations of an iterative
  // technique.
  std::vector<int> checkpoints;
  // Iterations of an iterative technique before its measured frames; absent: the last
  // checkpoint, else 1.
  std::optional<int> iterations;

  int iterationCount() const {
    return iterations.value_or(checkpoints.empty() ? 1 : checkpoints.back());
  }
};

struct Case {
  std::string name;  // unique in the suite; default "<scene>-<technique>"
  int line = 0;      // where the case starts in the suite file, for later messages
  SceneSpec scene;
  std::vector<Sweep> scene_parameters;      // `scene_set`, in file order
  std::string technique;                    // a catalogue name or kReferenceTechnique
  std::vector<Sweep> technique_parameters;  // `set`, in file order
  RunSettings settings;
};

struct Suite {
  std::string name;
  std::string description;
  std::filesystem::path file;  // absolute path of the suite file
  std::vector<Case> cases;     // file order
  // [tolerances]: how much a metric or the frame time may change before `gibench diff` calls it
  // a regression; recorded with every run.
  results::Tolerances tolerances;
  // [[paper]]: the source document's numbers, shown beside ours in the report.
  std::vector<results::PaperValue> paper;
  // [[chart]]: figures drawn over the suite's jobs in the report.
  std::vector<results::ChartSpec> charts;
  // [[figure]]: the document's figures as grids of the jobs' pictures, each a page of the report.
  std::vector<results::FigureSpec> figures;
};

}  // namespace gib::suites
