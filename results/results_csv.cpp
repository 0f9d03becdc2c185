#include "results/results_csv.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace gib::results {

namespace {

std::string quoteField(const std::string& field) {
  if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
  std::string quoted = "\"";
  for (char c : field) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

// Shortest text that reads back as the same double; the non-finite ones as results.json has them.
std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return fmt::format("{}", value);
}

std::string joinAssignments(const Assignments& assignments) {
  std::string joined;
  for (const auto& [key, value] : assignments)
    joined += (joined.empty() ? "" : ";") + key + "=" + value;
  return joined;
}

// Metric value names of every job, in first-seen order.
std::vector<std::string> metricColumns(const RunResults& results, NamedValues JobResult::*values) {
  std::vector<std::string> names;
  for (const JobResult& job : results.jobs)
    for (const auto& [name, value] : job.*values)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

void appendRow(const std::vector<std::string>& fields, std::string& out) {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) out += ',';
    out += quoteField(fields[i]);
  }
  out += "\r\n";
}

}  // namespace

std::string resultsCsv(const RunResults& results) {
  const std::vector<std::string> metrics = metricColumns(results, &JobResult::metrics);
  const std::vector<std::string> full = metricColumns(results, &JobResult::metrics_full);

  std::vector<std::string> header = {"run_id", "git_commit", "job",        "case",
                                     "scene",  "technique",  "parameters", "scene_parameters",
                                     "width",  "height",     "path_class", "reference_key",
                                     "spp"};
  header.insert(header.end(), metrics.begin(), metrics.end());
  for (const std::string& name : full) header.push_back("full_" + name);
  for (const char* name : {"frame_median_ms", "upload_ms", "prepare_ms", "seconds"})
    header.push_back(name);

  std::string out;
  appendRow(header, out);
  for (const JobResult& job : results.jobs) {
    std::vector<std::string> row = {results.run.id,
                                    results.run.git_commit,
                                    job.id,
                                    job.case_name,
                                    job.scene,
                                    job.technique,
                                    joinAssignments(job.parameters),
                                    joinAssignments(job.scene_parameters),
                                    std::to_string(job.width),
                                    std::to_string(job.height),
                                    job.path_class,
                                    job.reference.key,
                                    std::to_string(job.reference.spp)};
    auto cell = [](std::optional<double> value) {
      return value ? formatNumber(*value) : std::string();
    };
    for (const std::string& name : metrics) row.push_back(cell(findValue(job.metrics, name)));
    for (const std::string& name : full) row.push_back(cell(findValue(job.metrics_full, name)));
    row.push_back(cell(job.frameMedianMs()));
    for (double value : {job.upload_ms, job.prepare_ms, job.seconds})
      row.push_back(formatNumber(value));
    appendRow(row, out);
  }
  return out;
}

}  // namespace gib::results
