#include "reports/report_labels.h"

#include "common/join.h"
#include "reports/html_text.h"
#include "reports/number_format.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
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

bool outputPresent(const std::filesystem::path& run_dir, const std::string& path) {
  if (path.empty()) return false;
  const std::filesystem::path file(path);
  std::error_code ec;
  return std::filesystem::is_regular_file(file.is_absolute() ? file : run_dir / file, ec);
}

std::string fileUrl(const std::filesystem::path& path) {
  return "file://" + urlPath(std::filesystem::absolute(path).lexically_normal().generic_string());
}

std::string pixelSamplingText(const std::string& sampling) {
  if (sampling == "center") return "pixel centres";
  if (sampling == "area") return "box-filtered over the pixel";
  return sampling;  // a value newer than this report: shown as recorded
}

std::string referenceLabel(const results::ReferenceUse& use) {
  return fmt::format("{}, {}", use.path_class, pixelSamplingText(use.pixel_sampling));
}

std::string checkpointComparisonText(const results::JobResult& job) {
  // The harness measures a reference job's last checkpoint (the points are sorted by spp).
  if (!job.convergence || job.convergence->x_label != "spp" || job.convergence->points.empty())
    return {};
  return fmt::format("the {}-spp checkpoint against the {}-spp reference",
                     formatNumber(job.convergence->points.back().x), job.reference.spp);
}

bool isSoftwareRasteriser(std::string_view renderer) {
  // Mesa's names: "llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "Software Rasterizer" (swrast).
  static constexpr std::array<std::string_view, 4> kSoftware = {"llvmpipe", "softpipe", "swrast",
                                                                "software rasterizer"};
  std::string lower(renderer);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return std::any_of(kSoftware.begin(), kSoftware.end(),
                     [&](std::string_view name) { return lower.find(name) != std::string::npos; });
}

}  // namespace gib::reports
