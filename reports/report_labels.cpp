#include "reports/report_labels.h"

#include "common/join.h"
#include "reports/html_text.h"

#include <filesystem>

namespace gib::reports {

std::string sweepLabel(const results::JobResult& job) {
  const std::size_t slash = job.id.find('/');
  return slash == std::string::npos ? std::string() : job.id.substr(slash + 1);
}

std::string shortCommit(const results::RunInfo& run) {
  if (run.git_commit.empty()) return "?";
  return run.git_commit.substr(0, 7) + (run.git_dirty ? "*" : "");
}

std::string formatAssignments(const results::Assignments& assignments) {
  return joinNames(assignments, ", ",
                   [](const auto& pair) { return pair.first + "=" + pair.second; });
}

std::string jobPageFile(const results::JobResult& job) {
  return "report/" + job.slug + ".html";
}

std::string outputHref(const std::string& path, int depth) {
  if (std::filesystem::path(path).is_absolute()) return urlPath(path);
  std::string up;
  for (int i = 0; i < depth; ++i) up += "../";
  return up + urlPath(path);
}

}  // namespace gib::reports
