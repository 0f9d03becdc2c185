// `--junit FILE` and `--summary FILE`: a run's verdicts for CI (reports/junit_report.h) and for a
// pull-request comment (reports/markdown_summary.h), written beside the HTML report by
// `gibench run`, `gibench merge` and `gibench report` from the same comparison with the suite's
// previous run.
#pragma once

#include "reports/html_report.h"
#include "results/results.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace gib::cli {

struct CiOutputs {
  std::string junit;    // empty: not asked for
  std::string summary;  // empty: not asked for

  // Adds --junit and --summary to the command.
  void addOptions(CLI::App& command);
  bool requested() const { return !junit.empty() || !summary.empty(); }
  // Bad paths before any work is done (a missing or unwritable directory, a name not ending in
  // .xml or .md, a directory): gib::InputError, so that nothing is written.
  void check() const;
  // Writes the requested files, each atomically, judged as the report of `run_dir` was (with
  // `context`).
  void write(const std::filesystem::path& run_dir, const results::RunResults& results,
             const reports::ReportContext& context) const;
  // The same options with absolute paths, for a `gibench merge` run elsewhere (a Slurm job).
  std::vector<std::string> mergeArguments() const;
};

}  // namespace gib::cli
