#include "reports/report_labels.h"

#include "common/join.h"
#include "reports/html_text.h"

#include <fmt/format.h>

#include <filesystem>
#include <vector>

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

std::string conditionsText(const results::RunConditions& c) {
  std::vector<std::string> parts;
  if (c.load_before >= 0)
    parts.push_back(
        c.load_after >= 0
            ? fmt::format("load {:.2f} → {:.2f} (1-minute average)", c.load_before, c.load_after)
            : fmt::format("load {:.2f} (1-minute average)", c.load_before));
  if (!c.governor.empty()) parts.push_back("CPU governor " + c.governor);
  if (c.other_gibench == 0) parts.push_back("no other gibench process");
  if (c.other_gibench > 0)
    parts.push_back(fmt::format("{} other gibench process{} running: timings share the machine",
                                c.other_gibench, c.other_gibench == 1 ? "" : "es"));
  return parts.empty() ? std::string("not recorded") : joinNames(parts, ", ");
}

std::string outputHref(const std::string& path, int depth) {
  if (std::filesystem::path(path).is_absolute()) return urlPath(path);
  std::string up;
  for (int i = 0; i < depth; ++i) up += "../";
  return up + urlPath(path);
}

}  // namespace gib::reports
