// The results of one harness run (`gibench run`): what the runner records, results.json holds
// (schema in docs/results-schema.md), the history database stores, the HTML report shows and
// `gibench diff` compares. Plain data; reading and writing are in results/results_json.h. The
// results layer sits below both the harness that produces results and the report that consumes
// them (docs/architecture.md, "Layers").
#pragma once

#include "metrics/pass_timing_summary.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib::results {

// Bumped when a field changes meaning or goes away; adding a field does not bump it (readers
// ignore what they do not know).
inline constexpr int kResultsSchemaVersion = 1;
inline constexpr const char* kResultsSchemaName = "gibench-results";

// Named numbers in a fixed order (metrics in catalogue order: "relmse", "flip_mean", …).
using NamedValues = std::vector<std::pair<std::string, double>>;
// The value named `name`, if there is one.
std::optional<double> findValue(const NamedValues& values, std::string_view name);
// Canonical key=value parameters in suite-file order.
using Assignments = std::vector<std::pair<std::string, std::string>>;

// A change from a base run is noise while |new − base| ≤ max(absolute, relative·|base|).
struct Tolerance {
  double absolute = 0.0;
  double relative = 0.05;
  bool operator==(const Tolerance&) const = default;
};

// A job's frame time regressed when its median grew by more than `relative` of the base median
// and the Mann–Whitney U test of the per-frame samples rejects "same distribution" at
// `significance` (both conditions: a significant 0.5% change is not worth a bisect, and a large
// change in three noisy frames is not significant).
struct TimingTolerance {
  double relative = 0.10;
  double significance = 0.01;
  bool operator==(const TimingTolerance&) const = default;
};

// Set in the suite file ([tolerances]), recorded with the run so that a diff judges a new run by
// the tolerances it was run with.
struct Tolerances {
  Tolerance metric_default;
  std::map<std::string, Tolerance> metrics;  // by metric value name: "relmse", "flip_mean", …
  TimingTolerance timing;
  const Tolerance& forMetric(const std::string& name) const {
    auto it = metrics.find(name);
    return it == metrics.end() ? metric_default : it->second;
  }
  bool operator==(const Tolerances&) const = default;
};

// A number from the source document, shown beside ours in the report of a figure suite.
struct PaperValue {
  std::string job;       // the job id it belongs to
  std::string quantity;  // see results/quantity.h: "relmse", "full:relmse", "frame", "iteration"
  double value = 0;
  std::string unit;    // "ms", "" for a ratio
  std::string source;  // "Nijasure et al. 2005, Table 1"
  std::string note;    // "Radeon 9800 Pro, 64x64 grid"
  // Relative: ours reproduces the value when |ours − value| ≤ tolerance·|value|. Unset for a
  // number we only show (a frame time from other hardware); a value outside its tolerance fails
  // the job in `--junit` (reports/paper_check.h).
  std::optional<double> tolerance = std::nullopt;
  bool operator==(const PaperValue&) const = default;
};

// A chart of a figure suite (`[[chart]]`): one quantity against another over the suite's jobs,
// e.g. time per iteration against vertex count, or error against frame time. Quantities are
// named as in PaperValue (see results/quantity.h).
struct ChartSpec {
  std::string title;
  std::string jobs = "*";  // glob over job ids
  std::string x, y;
  std::string series;  // optional quantity whose values split the points into lines
  bool log_x = false, log_y = false;
  bool front = false;  // mark the Pareto front: the points no other point beats in both x and y
  bool operator==(const ChartSpec&) const = default;
};

// A figure of a figure suite (`[[figure]]`): jobs' pictures in a grid, laid out as the source
// document's figure, each with a caption and one of the job's numbers under it. The report
// gives it a page (report/figure-<name>.html) and a composite picture (figures/<name>.png).
struct FigureSpec {
  struct Panel {
    std::string job;  // a job id of the suite
    // "image", "reference", "difference", "flip" or "aux:<name>" (an auxiliary image of the job,
    // known only once it ran: a panel whose picture the results lack shows a note instead).
    std::string image;
    std::string caption;
    int row = 1, column = 1;  // 1-based cell, resolved when the suite is read
    // A quantity (results/quantity.h) printed under the picture, "none" for no number; empty:
    // the run's primary metric.
    std::string metric;
    bool operator==(const Panel&) const = default;
  };
  std::string name;  // a slug, unique in the suite: the page's and the PNG's file name
  std::string title;
  std::string caption;
  int columns = 1;            // cells per row
  std::vector<Panel> panels;  // file order
  bool operator==(const FigureSpec&) const = default;
};

// The machine's state around a run or a job, recorded so that a noisy timing can be seen as such
// (shown beside the timings in the report).
struct RunConditions {
  double load_before = -1, load_after = -1;  // 1-minute load average; −1 where unreadable
  std::string governor;    // cpu0's frequency governor ("performance"); empty where unreadable
  int other_gibench = -1;  // other gibench processes running at the start; −1 where unknown
  bool operator==(const RunConditions&) const = default;
};

// Where and how one job ran: a run spread over machines (`gibench run --slurm`, `--shard`) shows
// per job which node, scheduler task and GL device it had.
struct JobExecution {
  std::string host;
  std::string scheduler_job;  // Slurm: "<array job id>_<task id>"; empty when run directly
  double queue_seconds = -1;  // from submission to start; −1 when the job was not queued
  std::string gl_renderer;    // technique jobs: the GL_RENDERER string
  bool operator==(const JobExecution&) const = default;
};

struct RunInfo {
  std::string id;  // unique: "<UTC yyyymmdd-hhmmss>-<suite>-<8 hex>"
  std::string suite;
  std::string suite_description;
  std::string suite_file;  // as given on the command line
  std::string suite_hash;  // content hash of the suite file's bytes
  std::string started;     // ISO 8601 UTC, "2026-11-22T10:04:05Z"
  std::string finished;
  std::string gibench_version;  // "0.1.0+abcdef123456-dirty"
  std::string git_commit;       // of the build
  bool git_dirty = false;
  std::string build_type;  // "Release", "Debug", …
  std::string host;
  std::string cpu;  // model name
  int cpu_cores = 0;
  std::string embree_version;
  // The GL implementation of the technique jobs; empty when none ran.
  std::string gl_vendor, gl_renderer, gl_version, gl_device;
  int parallel_jobs = 1;     // --jobs
  std::string store;         // reference store root
  bool complete = true;      // false when some jobs were filtered out (--only)
  RunConditions conditions;  // from the start to the end of the run
  bool operator==(const RunInfo&) const = default;
};

// The reference a job is measured against.
struct ReferenceUse {
  std::string key;  // reference store key
  int spp = 0;
  unsigned long long seed = 0;
  std::string path_class;  // scene::describePathClass: "L(D|S|P){0,1}E", "LS+DE"
  bool store_hit = false;  // found in the store rather than rendered by this run
  double render_seconds = 0;
  // Where the reference's camera rays go: "center" (through each pixel's centre, the rasteriser's
  // sample position: the technique's lighting alone is compared) or "area" (a box filter over the
  // pixel: anti-aliased, for the reference's own checks). Files before it was recorded: "area".
  std::string pixel_sampling = "area";
  bool operator==(const ReferenceUse&) const = default;
};

// Error against x (samples per pixel of the reference, iterations of a technique), with the
// least-squares slope of log(metric) against log(x) of `fit_metric`.
struct Convergence {
  std::string x_label;  // "spp" or "iterations"
  struct Point {
    double x = 0;
    NamedValues metrics;
    double seconds = 0;  // time to reach this point, when known (0 otherwise)
    bool operator==(const Point&) const = default;
  };
  std::vector<Point> points;
  std::string fit_metric;  // empty when there was no fit (fewer than two usable points)
  double fit_slope = 0, fit_intercept = 0, fit_slope_ci95 = 0;
  bool operator==(const Convergence&) const = default;
};

// Paths relative to the run directory; empty when not written.
struct JobOutputs {
  std::string image;           // the job's EXR (technique frame, or the reference's test render)
  std::string image_png;       // the same through the display transform
  std::string reference_png;   // the class reference
  std::string difference_png;  // |test − reference|, amplified
  std::string flip_png;        // the FLIP map (magma), when flip was measured
  std::string timings_json;    // full per-pass timings with every frame's samples
  std::string log;             // a failed job's log (its scheduler task's output), when kept
  std::string thumbnail_png;   // image_png (or the reference's) at most 128 pixels wide
  // The report viewer's linear data (image/viewer_data.h): the job's image and FLIP map, and
  // the reference's mean and standard error (one file per reference, shared by its jobs).
  std::string viewer_data;
  std::string reference_viewer_data;
  // Full-precision copies of the references the job was measured against (reference.exr, and
  // full_reference.exr when the class is narrower), so the run directory stands alone.
  std::string reference_exr;
  std::string full_reference_exr;
  // Technique jobs measured against a pixel-centre reference: the pixels whose primary hit the
  // rasteriser and the ray tracer disagree on (white), with their count.
  std::string disagreement_png;
  bool operator==(const JobOutputs&) const = default;
};

// An image of a technique's internal state (a radiance atlas, one bounce's contribution).
struct AuxiliaryImageOutput {
  std::string name;
  std::string description;
  std::string exr, png;  // relative to the run directory
  bool operator==(const AuxiliaryImageOutput&) const = default;
};

struct JobResult {
  std::string id;    // suite job id: "cornell-direct/shadow=pcf"
  std::string slug;  // the id as a file name
  std::string case_name;
  std::string scene;       // built-in name or scene file stem
  std::string scene_file;  // absolute path of a scene file; empty for a built-in scene
  std::string scene_hash;  // scene::hashScene
  std::string technique;   // catalogue name or "reference"
  Assignments parameters;  // technique parameters (every parameter, defaults included)
  Assignments scene_parameters;
  int width = 0, height = 0;
  std::string path_class;  // of the technique (every path, "L(D|S|P)*E", for the reference)
  ReferenceUse reference;  // the reference of the technique's path class
  // Against the reference of the same path class: the technique's approximation error.
  NamedValues metrics;
  // Against the full (all paths) reference, when the class is narrower: what the technique
  // leaves out as well.
  std::optional<ReferenceUse> full_reference;
  NamedValues metrics_full;
  std::optional<Convergence> convergence;
  // Technique jobs: the per-pass timings of the measured frames (clock, frames, passes with
  // per-frame samples). Absent for reference jobs.
  std::optional<metrics::PassTimings> timings;
  // Iterative techniques: each iteration (step) timed as one unit, in the same form as `timings`
  // with the root pass named "iteration". Absent otherwise.
  std::optional<metrics::PassTimings> iteration_timings;
  // A job run `repeats` > 1 times (each with a fresh GL context): every repeat's timings, in run
  // order; `timings` is then the repeat of the median frame time. Empty for one run.
  std::vector<metrics::PassTimings> repeats;
  RunConditions conditions;  // around the job (all its repeats)
  double upload_ms = 0, prepare_ms = 0, iterate_ms = 0;
  int iterations = 0;
  NamedValues statistics;  // the technique's counts (vertices, texels, grid points)
  // Technique jobs against a pixel-centre reference: pixels whose primary hit differs between the
  // G-buffer and the reference's camera rays (silhouettes, shared edges); -1 when not checked.
  long long disagreement_pixels = -1;
  JobOutputs outputs;
  std::vector<AuxiliaryImageOutput> auxiliary_images;
  double seconds = 0;    // wall time of the whole job
  std::string job_hash;  // hash of everything that defines the job (resume skips a match)
  JobExecution execution;
  // Why the job has no result ("technique 'direct': out of GPU memory …", "no result: the task
  // was cancelled, pre-empted or crashed"); empty when it ran to the end. A local run holds
  // failed jobs the machine could not run (gib::EnvironmentError); a merged run any that failed.
  std::string failure;
  bool operator==(const JobResult&) const = default;

  bool failed() const { return !failure.empty(); }

  // The median frame time on the reported clock, when the job was timed.
  std::optional<double> frameMedianMs() const;
  // What one run of the job measured, the unit run-to-run comparisons use: the median over its
  // repeats of their median frame times, or the median frame time of a single run.
  std::optional<double> runMedianMs() const;
  // The median frame time of each repeat (one value for a job run once; empty when not timed).
  std::vector<double> repeatMediansMs() const;
  // The per-frame samples of the whole frame on the reported clock (empty when not timed).
  std::vector<double> frameSamplesMs() const;
  // The value of a metric against the class reference, if measured.
  std::optional<double> metric(const std::string& name) const;
};

struct RunResults {
  int schema_version = kResultsSchemaVersion;
  RunInfo run;
  Tolerances tolerances;
  // The error metric the index matrix shows and colours: the first metric value of the suite
  // ("relmse" when measured).
  std::string primary_metric;
  std::vector<PaperValue> paper;
  std::vector<ChartSpec> charts;
  std::vector<FigureSpec> figures;
  std::vector<JobResult> jobs;  // suite order
  bool operator==(const RunResults&) const = default;

  const JobResult* findJob(const std::string& id) const;
};

}  // namespace gib::results
