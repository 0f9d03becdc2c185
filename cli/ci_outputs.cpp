#include "cli/ci_outputs.h"

#include "common/input_error.h"
#include "image/output_files.h"
#include "reports/junit_report.h"
#include "reports/markdown_summary.h"
#include "reports/run_comparison.h"

#include <fmt/format.h>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;

void checkFile(const std::string& file, const char* option, const char* extension) {
  if (file.empty()) return;
  std::error_code ec;
  if (fs::is_directory(file, ec))
    throw InputError(fmt::format("{} '{}' is a directory; give a file name ending in {}", option,
                                 file, extension));
  try {
    image::checkOutputFile(file, extension);
  } catch (const InputError& e) {
    // Which option the path came from: a run takes several output paths.
    throw InputError(fmt::format("{}: {}", option, e.what()));
  }
}

}  // namespace

void CiOutputs::addOptions(CLI::App& command) {
  command.add_option("--junit", junit,
                     "also write JUnit XML for CI: one test case per job, failed when it "
                     "regressed against the previous run or a paper value is out of tolerance");
  command.add_option("--summary", summary,
                     "also write a Markdown summary for a pull-request comment: counts, "
                     "regressions, failed jobs, pictures");
}

void CiOutputs::check() const {
  checkFile(junit, "--junit", ".xml");
  checkFile(summary, "--summary", ".md");
}

void CiOutputs::write(const fs::path& run_dir, const results::RunResults& results,
                      const reports::ReportContext& context) const {
  if (!requested()) return;
  const reports::RunComparison comparison(results, context.previous, context.history);
  if (!junit.empty())
    image::writeTextFile(junit,
                         reports::junitReport(results, comparison, run_dir,
                                              context.previous ? &*context.previous : nullptr));
  if (!summary.empty())
    image::writeTextFile(summary, reports::markdownSummary(results, comparison, run_dir));
}

std::vector<std::string> CiOutputs::mergeArguments() const {
  std::vector<std::string> arguments;
  if (!junit.empty()) arguments.insert(arguments.end(), {"--junit", fs::absolute(junit).string()});
  if (!summary.empty())
    arguments.insert(arguments.end(), {"--summary", fs::absolute(summary).string()});
  return arguments;
}

}  // namespace gib::cli
