#include "results/results_json.h"

#include "common/input_error.h"
#include "image/output_files.h"
#include "results/json_fields.h"
#include "results/json_members.h"
#include "results/json_number.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace gib::results {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;
using detail::JsonField;
using detail::JsonMember;
using detail::jsonMember;

constexpr const char* kJobSchemaName = "gibench-job";
constexpr const char* kResultsFix =
    "the file is damaged or was not written by gibench; run the suite again (`gibench run`)";

// The plain members of each struct, in file order.

const std::array<JsonMember<RunInfo>, 22> kRunInfoMembers = {{
    jsonMember<&RunInfo::id>("id"),
    jsonMember<&RunInfo::suite>("suite"),
    jsonMember<&RunInfo::suite_description>("suite_description"),
    jsonMember<&RunInfo::suite_file>("suite_file"),
    jsonMember<&RunInfo::suite_hash>("suite_hash"),
    jsonMember<&RunInfo::started>("started"),
    jsonMember<&RunInfo::finished>("finished"),
    jsonMember<&RunInfo::gibench_version>("gibench_version"),
    jsonMember<&RunInfo::git_commit>("git_commit"),
    jsonMember<&RunInfo::git_dirty>("git_dirty"),
    jsonMember<&RunInfo::build_type>("build_type"),
    jsonMember<&RunInfo::host>("host"),
    jsonMember<&RunInfo::cpu>("cpu"),
    jsonMember<&RunInfo::cpu_cores>("cpu_cores"),
    jsonMember<&RunInfo::embree_version>("embree_version"),
    jsonMember<&RunInfo::gl_vendor>("gl_vendor"),
    jsonMember<&RunInfo::gl_renderer>("gl_renderer"),
    jsonMember<&RunInfo::gl_version>("gl_version"),
    jsonMember<&RunInfo::gl_device>("gl_device"),
    jsonMember<&RunInfo::parallel_jobs>("parallel_jobs"),
    jsonMember<&RunInfo::store>("store"),
    jsonMember<&RunInfo::complete>("complete"),
}};

const std::array<JsonMember<RunConditions>, 4> kConditionsMembers = {{
    jsonMember<&RunConditions::load_before>("load_before"),
    jsonMember<&RunConditions::load_after>("load_after"),
    jsonMember<&RunConditions::governor>("governor"),
    jsonMember<&RunConditions::other_gibench>("other_gibench"),
}};

const std::array<JsonMember<Tolerance>, 2> kToleranceMembers = {{
    jsonMember<&Tolerance::absolute>("absolute"),
    jsonMember<&Tolerance::relative>("relative"),
}};

const std::array<JsonMember<TimingTolerance>, 2> kTimingToleranceMembers = {{
    jsonMember<&TimingTolerance::relative>("relative"),
    jsonMember<&TimingTolerance::significance>("significance"),
}};

const std::array<JsonMember<PaperValue>, 6> kPaperValueMembers = {{
    jsonMember<&PaperValue::job>("job"),
    jsonMember<&PaperValue::quantity>("quantity"),
    jsonMember<&PaperValue::value>("value"),
    jsonMember<&PaperValue::unit>("unit"),
    jsonMember<&PaperValue::source>("source"),
    jsonMember<&PaperValue::note>("note"),
}};

const std::array<JsonMember<ChartSpec>, 8> kChartMembers = {{
    jsonMember<&ChartSpec::title>("title"),
    jsonMember<&ChartSpec::jobs>("jobs"),
    jsonMember<&ChartSpec::x>("x"),
    jsonMember<&ChartSpec::y>("y"),
    jsonMember<&ChartSpec::series>("series"),
    jsonMember<&ChartSpec::log_x>("log_x"),
    jsonMember<&ChartSpec::log_y>("log_y"),
    jsonMember<&ChartSpec::front>("front"),
}};

const std::array<JsonMember<FigureSpec>, 4> kFigureMembers = {{
    jsonMember<&FigureSpec::name>("name"),
    jsonMember<&FigureSpec::title>("title"),
    jsonMember<&FigureSpec::caption>("caption"),
    jsonMember<&FigureSpec::columns>("columns"),
}};

const std::array<JsonMember<FigureSpec::Panel>, 6> kPanelMembers = {{
    jsonMember<&FigureSpec::Panel::job>("job"),
    jsonMember<&FigureSpec::Panel::image>("image"),
    jsonMember<&FigureSpec::Panel::caption>("caption"),
    jsonMember<&FigureSpec::Panel::row>("row"),
    jsonMember<&FigureSpec::Panel::column>("column"),
    jsonMember<&FigureSpec::Panel::metric>("metric"),
}};

const std::array<JsonMember<AuxiliaryImageOutput>, 4> kAuxiliaryImageMembers = {{
    jsonMember<&AuxiliaryImageOutput::name>("name"),
    jsonMember<&AuxiliaryImageOutput::description>("description"),
    jsonMember<&AuxiliaryImageOutput::exr>("exr"),
    jsonMember<&AuxiliaryImageOutput::png>("png"),
}};

const std::array<JsonMember<ReferenceUse>, 6> kReferenceMembers = {{
    jsonMember<&ReferenceUse::key>("key"),
    jsonMember<&ReferenceUse::spp>("spp"),
    jsonMember<&ReferenceUse::seed>("seed"),
    jsonMember<&ReferenceUse::path_class>("path_class"),
    jsonMember<&ReferenceUse::store_hit>("store_hit"),
    jsonMember<&ReferenceUse::render_seconds>("render_seconds"),
}};

const std::array<JsonMember<Convergence>, 5> kConvergenceMembers = {{
    jsonMember<&Convergence::x_label>("x_label"),
    jsonMember<&Convergence::fit_metric>("fit_metric"),
    jsonMember<&Convergence::fit_slope>("fit_slope"),
    jsonMember<&Convergence::fit_intercept>("fit_intercept"),
    jsonMember<&Convergence::fit_slope_ci95>("fit_slope_ci95"),
}};

const std::array<JsonMember<Convergence::Point>, 2> kPointMembers = {{
    jsonMember<&Convergence::Point::x>("x"),
    jsonMember<&Convergence::Point::seconds>("seconds"),
}};

const std::array<JsonMember<JobExecution>, 4> kExecutionMembers = {{
    jsonMember<&JobExecution::host>("host"),
    jsonMember<&JobExecution::scheduler_job>("scheduler_job"),
    jsonMember<&JobExecution::queue_seconds>("queue_seconds"),
    jsonMember<&JobExecution::gl_renderer>("gl_renderer"),
}};

const std::array<JsonMember<JobOutputs>, 6> kOutputsMembers = {{
    jsonMember<&JobOutputs::image>("image"),
    jsonMember<&JobOutputs::image_png>("image_png"),
    jsonMember<&JobOutputs::reference_png>("reference_png"),
    jsonMember<&JobOutputs::difference_png>("difference_png"),
    jsonMember<&JobOutputs::flip_png>("flip_png"),
    jsonMember<&JobOutputs::timings_json>("timings_json"),
}};

const std::array<JsonMember<JobResult>, 15> kJobMembers = {{
    jsonMember<&JobResult::id>("id"),
    jsonMember<&JobResult::slug>("slug"),
    jsonMember<&JobResult::case_name>("case"),
    jsonMember<&JobResult::scene>("scene"),
    jsonMember<&JobResult::scene_hash>("scene_hash"),
    jsonMember<&JobResult::technique>("technique"),
    jsonMember<&JobResult::width>("width"),
    jsonMember<&JobResult::height>("height"),
    jsonMember<&JobResult::path_class>("path_class"),
    jsonMember<&JobResult::upload_ms>("upload_ms"),
    jsonMember<&JobResult::prepare_ms>("prepare_ms"),
    jsonMember<&JobResult::iterate_ms>("iterate_ms"),
    jsonMember<&JobResult::iterations>("iterations"),
    jsonMember<&JobResult::seconds>("seconds"),
    jsonMember<&JobResult::job_hash>("job_hash"),
}};

const std::array<JsonMember<metrics::PassTimings>, 4> kPassTimingsMembers = {{
    jsonMember<&metrics::PassTimings::clock>("clock"),
    jsonMember<&metrics::PassTimings::precise>("precise"),
    jsonMember<&metrics::PassTimings::warmup_frames>("warmup_frames"),
    jsonMember<&metrics::PassTimings::measured_frames>("measured_frames"),
}};

const std::array<JsonMember<metrics::PassTiming>, 5> kPassTimingMembers = {{
    jsonMember<&metrics::PassTiming::name>("name"),
    jsonMember<&metrics::PassTiming::path>("path"),
    jsonMember<&metrics::PassTiming::depth>("depth"),
    jsonMember<&metrics::PassTiming::share>("share"),
    jsonMember<&metrics::PassTiming::calls_per_frame>("calls_per_frame"),
}};

// A struct that is nothing but plain members, as a JSON object.
template <typename Struct, std::size_t N>
json membersToJson(const Struct& object, const std::array<JsonMember<Struct>, N>& members) {
  json out = json::object();
  writeMembers(object, members, out);
  return out;
}

template <typename Struct, std::size_t N>
Struct membersFromJson(const JsonField& field, const std::array<JsonMember<Struct>, N>& members) {
  Struct object;
  readMembers(field, members, object);
  return object;
}

// Writing

json namedValuesToJson(const NamedValues& values) {
  json object = json::object();
  for (const auto& [name, value] : values) object[name] = numberToJson(value);
  return object;
}

json assignmentsToJson(const Assignments& assignments) {
  json object = json::object();
  for (const auto& [name, value] : assignments) object[name] = value;
  return object;
}

json tolerancesToJson(const Tolerances& t) {
  json metrics = json::object();
  for (const auto& [name, tolerance] : t.metrics)
    metrics[name] = membersToJson(tolerance, kToleranceMembers);
  return {{"metric_default", membersToJson(t.metric_default, kToleranceMembers)},
          {"metrics", std::move(metrics)},
          {"timing", membersToJson(t.timing, kTimingToleranceMembers)}};
}

json figureToJson(const FigureSpec& f) {
  json out = membersToJson(f, kFigureMembers);
  json& panels = out["panels"] = json::array();
  for (const FigureSpec::Panel& p : f.panels) panels.push_back(membersToJson(p, kPanelMembers));
  return out;
}

json convergenceToJson(const Convergence& c) {
  json out = membersToJson(c, kConvergenceMembers);
  json& points = out["points"] = json::array();
  for (const Convergence::Point& p : c.points) {
    json point = membersToJson(p, kPointMembers);
    point["metrics"] = namedValuesToJson(p.metrics);
    points.push_back(std::move(point));
  }
  return out;
}

// Reading

NamedValues readNamedValues(const JsonField& field) {
  NamedValues values;
  field.forEachMember([&](const std::string& name, const JsonField& value) {
    values.emplace_back(name, value.asNumber());
  });
  return values;
}

Assignments readAssignments(const JsonField& field) {
  Assignments assignments;
  field.forEachMember([&](const std::string& name, const JsonField& value) {
    assignments.emplace_back(name, value.asString());
  });
  return assignments;
}

Tolerances readTolerances(const JsonField& f) {
  Tolerances t;
  t.metric_default = membersFromJson(f.at("metric_default"), kToleranceMembers);
  f.at("metrics").forEachMember([&](const std::string& name, const JsonField& tolerance) {
    t.metrics[name] = membersFromJson(tolerance, kToleranceMembers);
  });
  t.timing = membersFromJson(f.at("timing"), kTimingToleranceMembers);
  return t;
}

// The cells are checked here because the report lays the grid out from them: a hand-edited
// file must not place a panel outside its figure.
FigureSpec readFigure(const JsonField& f) {
  FigureSpec figure = membersFromJson(f, kFigureMembers);
  if (figure.columns < 1) f.at("columns").fail("must be 1 or more");
  f.at("panels").forEachElement([&](const JsonField& p) {
    FigureSpec::Panel panel = membersFromJson(p, kPanelMembers);
    if (panel.row < 1) p.at("row").fail("must be 1 or more");
    if (panel.column < 1 || panel.column > figure.columns)
      p.at("column").fail(fmt::format("must be in [1, {}] (the figure's columns)", figure.columns));
    figure.panels.push_back(std::move(panel));
  });
  return figure;
}

Convergence readConvergence(const JsonField& f) {
  Convergence c = membersFromJson(f, kConvergenceMembers);
  f.at("points").forEachElement([&](const JsonField& p) {
    Convergence::Point point = membersFromJson(p, kPointMembers);
    point.metrics = readNamedValues(p.at("metrics"));
    c.points.push_back(std::move(point));
  });
  return c;
}

std::vector<double> readNumbers(const JsonField& field) {
  std::vector<double> numbers;
  field.forEachElement([&](const JsonField& number) { numbers.push_back(number.asNumber()); });
  return numbers;
}

std::optional<double> readOptionalNumber(const JsonField& object, const char* key) {
  const std::optional<JsonField> value = object.find(key);
  return value ? std::optional<double>(value->asNumber()) : std::nullopt;
}

// `frame_rate_fps` and `clock_description` are written for people and derived again on reading.
metrics::PassTimings readPassTimings(const JsonField& f) {
  metrics::PassTimings timings = membersFromJson(f, kPassTimingsMembers);
  if (timings.clock != "gpu" && timings.clock != "cpu")
    f.at("clock").fail(fmt::format("'{}' is neither \"gpu\" nor \"cpu\"", timings.clock));
  f.at("passes").forEachElement([&](const JsonField& p) {
    metrics::PassTiming pass = membersFromJson(p, kPassTimingMembers);
    metrics::TimingSummary& s = pass.reported;
    s.median = p.at("median_ms").asNumber();
    s.first_quartile = p.at("first_quartile_ms").asNumber();
    s.third_quartile = p.at("third_quartile_ms").asNumber();
    s.minimum = p.at("min_ms").asNumber();
    s.maximum = p.at("max_ms").asNumber();
    s.median_absolute_deviation = p.at("mad_ms").asNumber();
    pass.gpu_median_ms = readOptionalNumber(p, "gpu_median_ms");
    pass.cpu_median_ms = readOptionalNumber(p, "cpu_median_ms");
    pass.gpu_commands_per_frame = readOptionalNumber(p, "gpu_commands_per_frame");
    pass.gpu_ms = readNumbers(p.at("gpu_ms"));
    pass.cpu_ms = readNumbers(p.at("cpu_ms"));
    s.count = timings.reportedSamples(pass).size();
    timings.passes.push_back(std::move(pass));
  });
  if (timings.passes.empty()) f.at("passes").fail("has no passes (the first is the frame)");
  return timings;
}

// pixel_sampling was added after version 1: absent means the box filter of older references.
ReferenceUse readReferenceUse(const JsonField& f) {
  ReferenceUse use = membersFromJson(f, kReferenceMembers);
  if (auto sampling = f.find("pixel_sampling")) use.pixel_sampling = sampling->asString();
  return use;
}

json referenceUseToJson(const ReferenceUse& use) {
  json out = membersToJson(use, kReferenceMembers);
  out["pixel_sampling"] = use.pixel_sampling;
  return out;
}

JobResult readJob(const JsonField& f) {
  JobResult j = membersFromJson(f, kJobMembers);
  j.parameters = readAssignments(f.at("parameters"));
  j.scene_parameters = readAssignments(f.at("scene_parameters"));
  j.reference = readReferenceUse(f.at("reference"));
  j.metrics = readNamedValues(f.at("metrics"));
  if (auto full = f.find("full_reference")) j.full_reference = readReferenceUse(*full);
  j.metrics_full = readNamedValues(f.at("metrics_full"));
  if (auto convergence = f.find("convergence")) j.convergence = readConvergence(*convergence);
  if (auto timings = f.find("timings")) j.timings = readPassTimings(*timings);
  j.outputs = membersFromJson(f.at("outputs"), kOutputsMembers);
  // Added after version 1, so optional (docs/results-schema.md, compatibility).
  if (auto timings = f.find("iteration_timings")) j.iteration_timings = readPassTimings(*timings);
  if (auto statistics = f.find("statistics")) j.statistics = readNamedValues(*statistics);
  if (auto file = f.find("scene_file")) j.scene_file = file->asString();
  if (auto repeats = f.find("repeats"))
    repeats->forEachElement(
        [&](const JsonField& repeat) { j.repeats.push_back(readPassTimings(repeat)); });
  if (auto conditions = f.find("conditions"))
    j.conditions = membersFromJson(*conditions, kConditionsMembers);
  if (auto images = f.find("auxiliary_images"))
    images->forEachElement([&](const JsonField& image) {
      j.auxiliary_images.push_back(membersFromJson(image, kAuxiliaryImageMembers));
    });
  if (auto execution = f.find("execution"))
    j.execution = membersFromJson(*execution, kExecutionMembers);
  if (auto failure = f.find("failure")) j.failure = failure->asString();
  // Optional outputs, added after version 1 (absent from older files).
  const JsonField outputs = f.at("outputs");
  if (auto log = outputs.find("log")) j.outputs.log = log->asString();
  if (auto png = outputs.find("thumbnail_png")) j.outputs.thumbnail_png = png->asString();
  if (auto data = outputs.find("viewer_data")) j.outputs.viewer_data = data->asString();
  if (auto data = outputs.find("reference_viewer_data"))
    j.outputs.reference_viewer_data = data->asString();
  if (auto exr = outputs.find("reference_exr")) j.outputs.reference_exr = exr->asString();
  if (auto exr = outputs.find("full_reference_exr")) j.outputs.full_reference_exr = exr->asString();
  if (auto png = outputs.find("disagreement_png")) j.outputs.disagreement_png = png->asString();
  if (auto pixels = f.find("disagreement_pixels"))
    j.disagreement_pixels = static_cast<long long>(pixels->asNumber());
  return j;
}

// The schema name and version at the top of a file: a different name is not our file, a newer
// version needs a newer gibench (kResultsSchemaVersion: adding fields does not bump it).
void checkSchema(const JsonField& top, const char* expected_name) {
  const JsonField name = top.at("schema");
  if (name.asString() != expected_name)
    name.fail(fmt::format("'{}' is not '{}'", name.asString(), expected_name));
  const JsonField version = top.at("schema_version");
  const int number = version.asInt();
  if (number > kResultsSchemaVersion)
    throw InputError(
        fmt::format("{}: schema_version {} is newer than this gibench reads ({}); update gibench",
                    top.source(), number, kResultsSchemaVersion));
  if (number < 1) version.fail(fmt::format("{} is not a schema version", number));
}

json parseFile(const fs::path& file) {
  std::error_code ec;
  if (!fs::exists(file, ec))
    throw InputError(fmt::format("'{}' does not exist; check the path", file.string()));
  std::ifstream stream(file, std::ios::binary);
  if (!stream)
    throw InputError(fmt::format("cannot read '{}'; check its permissions", file.string()));
  try {
    return json::parse(stream);
  } catch (const json::parse_error& e) {
    throw InputError(fmt::format(
        "'{}' is not valid JSON (error at byte {}: truncated or damaged); run the suite again "
        "(`gibench run`) to rewrite it",
        file.string(), e.byte));
  } catch (const json::out_of_range&) {
    // A number beyond double's range (1e999): valid JSON syntax, but no file gibench writes.
    throw InputError(fmt::format(
        "'{}' holds a number beyond the range of a double (damaged); run the suite again "
        "(`gibench run`) to rewrite it",
        file.string()));
  }
}

// Indented for people reading the file; a byte that is not UTF-8 (a path, say) is replaced
// rather than failing the whole run at its end.
std::string dumpJson(const json& document) {
  return document.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace

json passTimingsToJson(const metrics::PassTimings& t) {
  auto optionalNumber = [](const std::optional<double>& v) {
    return v ? numberToJson(*v) : json(nullptr);
  };
  json passes = json::array();
  for (const metrics::PassTiming& p : t.passes) {
    const metrics::TimingSummary& s = p.reported;
    passes.push_back({{"name", p.name},
                      {"path", p.path},
                      {"depth", p.depth},
                      {"median_ms", numberToJson(s.median)},
                      {"first_quartile_ms", numberToJson(s.first_quartile)},
                      {"third_quartile_ms", numberToJson(s.third_quartile)},
                      {"min_ms", numberToJson(s.minimum)},
                      {"max_ms", numberToJson(s.maximum)},
                      {"mad_ms", numberToJson(s.median_absolute_deviation)},
                      {"gpu_median_ms", optionalNumber(p.gpu_median_ms)},
                      {"cpu_median_ms", optionalNumber(p.cpu_median_ms)},
                      {"share", numberToJson(p.share)},
                      {"calls_per_frame", numberToJson(p.calls_per_frame)},
                      {"gpu_commands_per_frame", optionalNumber(p.gpu_commands_per_frame)},
                      {"gpu_ms", p.gpu_ms},
                      {"cpu_ms", p.cpu_ms}});
  }
  return {{"clock", t.clock},
          {"clock_description", t.clockDescription()},
          {"precise", t.precise},
          {"warmup_frames", t.warmup_frames},
          {"measured_frames", t.measured_frames},
          {"frame_rate_fps", optionalNumber(t.frameRateFps())},
          {"passes", std::move(passes)}};
}

json jobToJson(const JobResult& j) {
  json out = membersToJson(j, kJobMembers);
  out["parameters"] = assignmentsToJson(j.parameters);
  out["scene_parameters"] = assignmentsToJson(j.scene_parameters);
  out["reference"] = referenceUseToJson(j.reference);
  out["metrics"] = namedValuesToJson(j.metrics);
  out["full_reference"] = j.full_reference ? referenceUseToJson(*j.full_reference) : json();
  out["metrics_full"] = namedValuesToJson(j.metrics_full);
  out["convergence"] = j.convergence ? convergenceToJson(*j.convergence) : json();
  out["timings"] = j.timings ? passTimingsToJson(*j.timings) : json();
  out["outputs"] = membersToJson(j.outputs, kOutputsMembers);
  out["iteration_timings"] = j.iteration_timings ? passTimingsToJson(*j.iteration_timings) : json();
  out["statistics"] = namedValuesToJson(j.statistics);
  out["scene_file"] = j.scene_file;
  json repeats = json::array();
  for (const metrics::PassTimings& repeat : j.repeats) repeats.push_back(passTimingsToJson(repeat));
  out["repeats"] = std::move(repeats);
  out["conditions"] = membersToJson(j.conditions, kConditionsMembers);
  json images = json::array();
  for (const AuxiliaryImageOutput& image : j.auxiliary_images)
    images.push_back(membersToJson(image, kAuxiliaryImageMembers));
  out["auxiliary_images"] = std::move(images);
  out["execution"] = membersToJson(j.execution, kExecutionMembers);
  out["failure"] = j.failure;
  out["outputs"]["log"] = j.outputs.log;
  out["outputs"]["thumbnail_png"] = j.outputs.thumbnail_png;
  out["outputs"]["viewer_data"] = j.outputs.viewer_data;
  out["outputs"]["reference_viewer_data"] = j.outputs.reference_viewer_data;
  out["outputs"]["reference_exr"] = j.outputs.reference_exr;
  out["outputs"]["full_reference_exr"] = j.outputs.full_reference_exr;
  out["outputs"]["disagreement_png"] = j.outputs.disagreement_png;
  out["disagreement_pixels"] = j.disagreement_pixels;
  return out;
}

json resultsToJson(const RunResults& results) {
  json paper = json::array();
  for (const PaperValue& p : results.paper) {
    json value = membersToJson(p, kPaperValueMembers);
    // Absent when not set: a number shown for comparison only.
    if (p.tolerance) value["tolerance"] = numberToJson(*p.tolerance);
    paper.push_back(std::move(value));
  }
  json charts = json::array();
  for (const ChartSpec& c : results.charts) charts.push_back(membersToJson(c, kChartMembers));
  json figures = json::array();
  for (const FigureSpec& f : results.figures) figures.push_back(figureToJson(f));
  json jobs = json::array();
  for (const JobResult& j : results.jobs) jobs.push_back(jobToJson(j));
  json run = membersToJson(results.run, kRunInfoMembers);
  run["conditions"] = membersToJson(results.run.conditions, kConditionsMembers);
  return {{"schema", kResultsSchemaName},
          {"schema_version", kResultsSchemaVersion},
          {"run", std::move(run)},
          {"tolerances", tolerancesToJson(results.tolerances)},
          {"primary_metric", results.primary_metric},
          {"paper", std::move(paper)},
          {"charts", std::move(charts)},
          {"figures", std::move(figures)},
          {"jobs", std::move(jobs)}};
}

RunResults resultsFromJson(const json& document, const std::string& source) {
  const JsonField top(document, source, kResultsFix);
  checkSchema(top, kResultsSchemaName);
  RunResults results;
  results.schema_version = kResultsSchemaVersion;
  results.run = membersFromJson(top.at("run"), kRunInfoMembers);
  if (auto conditions = top.at("run").find("conditions"))
    results.run.conditions = membersFromJson(*conditions, kConditionsMembers);
  results.tolerances = readTolerances(top.at("tolerances"));
  results.primary_metric = top.at("primary_metric").asString();
  top.at("paper").forEachElement([&](const JsonField& p) {
    PaperValue value = membersFromJson(p, kPaperValueMembers);
    // Added after version 1: optional.
    if (const std::optional<JsonField> tolerance = p.find("tolerance")) {
      value.tolerance = tolerance->asNumber();
      if (!(std::isfinite(*value.tolerance) && *value.tolerance >= 0))
        tolerance->fail("must be a finite number ≥ 0 (relative to the paper's value)");
    }
    results.paper.push_back(std::move(value));
  });
  if (auto charts = top.find("charts"))
    charts->forEachElement(
        [&](const JsonField& c) { results.charts.push_back(membersFromJson(c, kChartMembers)); });
  // Added after version 1: absent from older files.
  if (auto figures = top.find("figures"))
    figures->forEachElement([&](const JsonField& f) { results.figures.push_back(readFigure(f)); });
  top.at("jobs").forEachElement([&](const JsonField& j) { results.jobs.push_back(readJob(j)); });
  return results;
}

JobResult jobFromJson(const json& document, const std::string& source) {
  return readJob(JsonField(document, source, kResultsFix));
}

RunResults readResultsFile(const fs::path& path) {
  std::error_code ec;
  const fs::path file = fs::is_directory(path, ec) ? path / "results.json" : path;
  if (file != path && !fs::exists(file, ec))
    throw InputError(
        fmt::format("'{}' holds no results.json; give a run directory written by "
                    "`gibench run --out DIR` or a results.json file",
                    path.string()));
  return resultsFromJson(parseFile(file), file.string());
}

JobResult readJobFile(const fs::path& path) {
  const json document = parseFile(path);
  const std::string source = path.string();  // outlives the fields, which refer to it
  const JsonField top(document, source, kResultsFix);
  checkSchema(top, kJobSchemaName);
  return readJob(top);
}

metrics::PassTimings readPassTimingsFile(const fs::path& path) {
  const json document = parseFile(path);
  const std::string source = path.string();  // outlives the fields, which refer to it
  return readPassTimings(JsonField(document, source, kResultsFix));
}

void writeResultsFile(const fs::path& path, const RunResults& results) {
  image::writeTextFile(path, dumpJson(resultsToJson(results)));
}

void writeJobFile(const fs::path& path, const JobResult& job) {
  json document = {{"schema", kJobSchemaName}, {"schema_version", kResultsSchemaVersion}};
  document.update(jobToJson(job));
  image::writeTextFile(path, dumpJson(document));
}

}  // namespace gib::results
