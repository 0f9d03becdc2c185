// `gibench run`: a suite's jobs rendered, measured and recorded in a run directory
// (suites/run_directory.h), then the run's results.json and results.csv and its row in the
// history database. The harness produces results; the HTML report is written from them by its
// consumer (cli/run_command.cpp, `gibench report`). Resumable: a rerun into the same directory
// skips finished jobs.
#pragma once

#include "results/results.h"
#include "suites/job_expansion.h"
#include "suites/suite.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace gib::suites {

struct RunOptions {
  std::filesystem::path out_dir;
  std::filesystem::path store_root;
  std::filesystem::path history_db;  // empty: the run is not recorded in a history database
  std::string suite_file;            // as given on the command line, recorded in the results
  int parallel_jobs = 1;
  // Glob patterns ('*', '?') over job ids; a job runs when it matches any. Empty: every job.
  std::vector<std::string> only;
  std::string gl_device;    // empty: $GIBENCH_GL_DEVICE, else auto
  bool progress = false;    // progress bars on a terminal
  std::FILE* log = stderr;  // one line per job as it starts and ends
};

struct RunOutcome {
  results::RunResults results;
  std::size_t ran = 0;      // jobs run now
  std::size_t skipped = 0;  // jobs finished by an earlier, interrupted run
  std::filesystem::path run_dir;
  std::filesystem::path results_file;
  std::int64_t history_row = 0;  // 0 when not recorded
};

// The jobs of `suite` that `only` selects, in suite order. Throws gib::InputError when a pattern
// matches no job.
std::vector<Job> selectJobs(const Suite& suite, const std::vector<std::string>& only);

// Throws gib::InputError for bad input found before anything is written (an unloadable scene, a
// bad parameter, no GL when a technique job needs it, an unusable --out or store).
RunOutcome runSuite(const Suite& suite, const RunOptions& options);

}  // namespace gib::suites
