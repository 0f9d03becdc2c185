#include "reports/results_json.h"

#include "common/input_error.h"
#include "image/output_files.h"
#include "reports/json_fields.h"
#include "reports/json_number.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;
using detail::JsonField;

constexpr const char* kJobSchemaName = "gibench-job";
constexpr const char* kResultsFix =
    "the file is damaged or was not written by gibench; run the suite again (`gibench run`)";

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

json runInfoToJson(const RunInfo& r) {
  return {{"id", r.id},
          {"suite", r.suite},
          {"suite_description", r.suite_description},
          {"suite_file", r.suite_file},
          {"suite_hash", r.suite_hash},
          {"started", r.started},
          {"finished", r.finished},
          {"gibench_version", r.gibench_version},
          {"git_commit", r.git_commit},
          {"git_dirty", r.git_dirty},
          {"build_type", r.build_type},
          {"host", r.host},
          {"cpu", r.cpu},
          {"cpu_cores", r.cpu_cores},
          {"embree_version", r.embree_version},
          {"gl_vendor", r.gl_vendor},
          {"gl_renderer", r.gl_renderer},
          {"gl_version", r.gl_version},
          {"gl_device", r.gl_device},
          {"parallel_jobs", r.parallel_jobs},
          {"store", r.store},
          {"complete", r.complete}};
}

json toleranceToJson(const Tolerance& t) {
  return {{"absolute", numberToJson(t.absolute)}, {"relative", numberToJson(t.relative)}};
}

json tolerancesToJson(const Tolerances& t) {
  json metrics = json::object();
  for (const auto& [name, tolerance] : t.metrics) metrics[name] = toleranceToJson(tolerance);
  return {{"metric_default", toleranceToJson(t.metric_default)},
          {"metrics", std::move(metrics)},
          {"timing",
           {{"relative", numberToJson(t.timing.relative)},
            {"significance", numberToJson(t.timing.significance)}}}};
}

json paperToJson(const PaperValue& p) {
  return {{"job", p.job},   {"quantity", p.quantity}, {"value", numberToJson(p.value)},
          {"unit", p.unit}, {"source", p.source},     {"note", p.note}};
}

json referenceToJson(const ReferenceUse& r) {
  return {{"key", r.key},
          {"spp", r.spp},
          {"seed", r.seed},
          {"path_class", r.path_class},
          {"store_hit", r.store_hit},
          {"render_seconds", numberToJson(r.render_seconds)}};
}

json convergenceToJson(const Convergence& c) {
  json points = json::array();
  for (const Convergence::Point& p : c.points)
    points.push_back({{"x", numberToJson(p.x)},
                      {"metrics", namedValuesToJson(p.metrics)},
                      {"seconds", numberToJson(p.seconds)}});
  return {{"x_label", c.x_label},
          {"points", std::move(points)},
          {"fit_metric", c.fit_metric},
          {"fit_slope", numberToJson(c.fit_slope)},
          {"fit_intercept", numberToJson(c.fit_intercept)},
          {"fit_slope_ci95", numberToJson(c.fit_slope_ci95)}};
}

json outputsToJson(const JobOutputs& o) {
  return {{"image", o.image},
          {"image_png", o.image_png},
          {"reference_png", o.reference_png},
          {"difference_png", o.difference_png},
          {"flip_png", o.flip_png},
          {"timings_json", o.timings_json}};
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

RunInfo readRunInfo(const JsonField& f) {
  RunInfo r;
  r.id = f.at("id").asString();
  r.suite = f.at("suite").asString();
  r.suite_description = f.at("suite_description").asString();
  r.suite_file = f.at("suite_file").asString();
  r.suite_hash = f.at("suite_hash").asString();
  r.started = f.at("started").asString();
  r.finished = f.at("finished").asString();
  r.gibench_version = f.at("gibench_version").asString();
  r.git_commit = f.at("git_commit").asString();
  r.git_dirty = f.at("git_dirty").asBool();
  r.build_type = f.at("build_type").asString();
  r.host = f.at("host").asString();
  r.cpu = f.at("cpu").asString();
  r.cpu_cores = f.at("cpu_cores").asInt();
  r.embree_version = f.at("embree_version").asString();
  r.gl_vendor = f.at("gl_vendor").asString();
  r.gl_renderer = f.at("gl_renderer").asString();
  r.gl_version = f.at("gl_version").asString();
  r.gl_device = f.at("gl_device").asString();
  r.parallel_jobs = f.at("parallel_jobs").asInt();
  r.store = f.at("store").asString();
  r.complete = f.at("complete").asBool();
  return r;
}

Tolerance readTolerance(const JsonField& f) {
  return {f.at("absolute").asNumber(), f.at("relative").asNumber()};
}

Tolerances readTolerances(const JsonField& f) {
  Tolerances t;
  t.metric_default = readTolerance(f.at("metric_default"));
  f.at("metrics").forEachMember([&](const std::string& name, const JsonField& tolerance) {
    t.metrics[name] = readTolerance(tolerance);
  });
  const JsonField timing = f.at("timing");
  t.timing = {timing.at("relative").asNumber(), timing.at("significance").asNumber()};
  return t;
}

PaperValue readPaperValue(const JsonField& f) {
  return {f.at("job").asString(),  f.at("quantity").asString(), f.at("value").asNumber(),
          f.at("unit").asString(), f.at("source").asString(),   f.at("note").asString()};
}

ReferenceUse readReference(const JsonField& f) {
  ReferenceUse r;
  r.key = f.at("key").asString();
  r.spp = f.at("spp").asInt();
  r.seed = f.at("seed").asUnsigned();
  r.path_class = f.at("path_class").asString();
  r.store_hit = f.at("store_hit").asBool();
  r.render_seconds = f.at("render_seconds").asNumber();
  return r;
}

Convergence readConvergence(const JsonField& f) {
  Convergence c;
  c.x_label = f.at("x_label").asString();
  f.at("points").forEachElement([&](const JsonField& p) {
    c.points.push_back(
        {p.at("x").asNumber(), readNamedValues(p.at("metrics")), p.at("seconds").asNumber()});
  });
  c.fit_metric = f.at("fit_metric").asString();
  c.fit_slope = f.at("fit_slope").asNumber();
  c.fit_intercept = f.at("fit_intercept").asNumber();
  c.fit_slope_ci95 = f.at("fit_slope_ci95").asNumber();
  return c;
}

JobOutputs readOutputs(const JsonField& f) {
  return {f.at("image").asString(),         f.at("image_png").asString(),
          f.at("reference_png").asString(), f.at("difference_png").asString(),
          f.at("flip_png").asString(),      f.at("timings_json").asString()};
}

// The timings object is metrics::passTimingsJson, kept whole; checked as far as JobResult's
// accessors (frameMedianMs, frameSamplesMs) and the report rely on it.
void checkTimings(const JsonField& f) {
  f.at("clock").asString();
  f.at("passes").forEachElement([](const JsonField& pass) {
    pass.at("name").asString();
    pass.at("median_ms").asNumber();
    for (const char* clock : {"gpu_ms", "cpu_ms"})
      if (auto samples = pass.find(clock))
        samples->forEachElement([](const JsonField& sample) { sample.asNumber(); });
  });
}

JobResult readJob(const JsonField& f) {
  JobResult j;
  j.id = f.at("id").asString();
  j.slug = f.at("slug").asString();
  j.case_name = f.at("case").asString();
  j.scene = f.at("scene").asString();
  j.scene_hash = f.at("scene_hash").asString();
  j.technique = f.at("technique").asString();
  j.parameters = readAssignments(f.at("parameters"));
  j.scene_parameters = readAssignments(f.at("scene_parameters"));
  j.width = f.at("width").asInt();
  j.height = f.at("height").asInt();
  j.path_class = f.at("path_class").asString();
  j.reference = readReference(f.at("reference"));
  j.metrics = readNamedValues(f.at("metrics"));
  if (auto full = f.find("full_reference")) j.full_reference = readReference(*full);
  j.metrics_full = readNamedValues(f.at("metrics_full"));
  if (auto convergence = f.find("convergence")) j.convergence = readConvergence(*convergence);
  if (auto timings = f.find("timings")) {
    checkTimings(*timings);
    j.timings = timings->json();
  }
  j.upload_ms = f.at("upload_ms").asNumber();
  j.prepare_ms = f.at("prepare_ms").asNumber();
  j.iterate_ms = f.at("iterate_ms").asNumber();
  j.iterations = f.at("iterations").asInt();
  j.outputs = readOutputs(f.at("outputs"));
  j.seconds = f.at("seconds").asNumber();
  j.job_hash = f.at("job_hash").asString();
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
  }
}

// Indented for people reading the file; a byte that is not UTF-8 (a path, say) is replaced
// rather than failing the whole run at its end.
std::string dumpJson(const json& document) {
  return document.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace

json jobToJson(const JobResult& j) {
  return {{"id", j.id},
          {"slug", j.slug},
          {"case", j.case_name},
          {"scene", j.scene},
          {"scene_hash", j.scene_hash},
          {"technique", j.technique},
          {"parameters", assignmentsToJson(j.parameters)},
          {"scene_parameters", assignmentsToJson(j.scene_parameters)},
          {"width", j.width},
          {"height", j.height},
          {"path_class", j.path_class},
          {"reference", referenceToJson(j.reference)},
          {"metrics", namedValuesToJson(j.metrics)},
          {"full_reference", j.full_reference ? referenceToJson(*j.full_reference) : json()},
          {"metrics_full", namedValuesToJson(j.metrics_full)},
          {"convergence", j.convergence ? convergenceToJson(*j.convergence) : json()},
          {"timings", j.timings},
          {"upload_ms", numberToJson(j.upload_ms)},
          {"prepare_ms", numberToJson(j.prepare_ms)},
          {"iterate_ms", numberToJson(j.iterate_ms)},
          {"iterations", j.iterations},
          {"outputs", outputsToJson(j.outputs)},
          {"seconds", numberToJson(j.seconds)},
          {"job_hash", j.job_hash}};
}

json resultsToJson(const RunResults& results) {
  json paper = json::array();
  for (const PaperValue& p : results.paper) paper.push_back(paperToJson(p));
  json jobs = json::array();
  for (const JobResult& j : results.jobs) jobs.push_back(jobToJson(j));
  return {{"schema", kResultsSchemaName},
          {"schema_version", kResultsSchemaVersion},
          {"run", runInfoToJson(results.run)},
          {"tolerances", tolerancesToJson(results.tolerances)},
          {"primary_metric", results.primary_metric},
          {"paper", std::move(paper)},
          {"jobs", std::move(jobs)}};
}

RunResults resultsFromJson(const json& document, const std::string& source) {
  const JsonField top(document, source, kResultsFix);
  checkSchema(top, kResultsSchemaName);
  RunResults results;
  results.schema_version = kResultsSchemaVersion;
  results.run = readRunInfo(top.at("run"));
  results.tolerances = readTolerances(top.at("tolerances"));
  results.primary_metric = top.at("primary_metric").asString();
  top.at("paper").forEachElement(
      [&](const JsonField& p) { results.paper.push_back(readPaperValue(p)); });
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

void writeResultsFile(const fs::path& path, const RunResults& results) {
  image::writeTextFile(path, dumpJson(resultsToJson(results)));
}

void writeJobFile(const fs::path& path, const JobResult& job) {
  json document = {{"schema", kJobSchemaName}, {"schema_version", kResultsSchemaVersion}};
  document.update(jobToJson(job));
  image::writeTextFile(path, dumpJson(document));
}

}  // namespace gib::reports
