// `gibench run`: a suite's jobs rendered, measured and recorded in a run directory
// (suites/run_directory.h), then the run's results.json and results.csv and its row in the
// history database. The harness produces results; the HTML report is written from them by its
// consumer (cli/run_command.cpp, `gibench report`). Resumable: a rerun into the same directory
// skips finished jobs.
#pragma once

#include "results/results.h"
#include "suites/job_expansion.h"
#include "suites/run_directory.h"
#include "suites/suite.h"

#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gib::suites {

// The i-th of n deterministic slices of a suite's jobs (`gibench run --shard i/n`): the jobs whose
// position k (0-based, after --only) has k mod n = i − 1.
struct Shard {
  int index = 1;  // 1-based
  int count = 1;
  bool whole() const { return count == 1; }
};

// "3/8" → {3, 8}. Throws gib::InputError unless 1 ≤ i ≤ n.
Shard parseShard(const std::string& text);

struct RunOptions {
  std::filesystem::path out_dir;
  std::filesystem::path store_root;
  std::filesystem::path history_db;  // empty: the run is not recorded in a history database
  std::string suite_file;            // as given on the command line, recorded in the results
  int parallel_jobs = 1;
  // Glob patterns ('*', '?') over job ids; a job runs when it matches any. Empty: every job.
  std::vector<std::string> only;
  Shard shard;      // of the selected jobs
  std::string job;  // exactly this job id (a Slurm task), when not empty
  // Parts of a run (a shard, a Slurm task) record their jobs, and a job that fails is recorded as
  // failed (failed.json) while the others go on; `gibench merge` assembles the whole. A whole run
  // assembles results.json, the CSV and the history row itself; a job the machine cannot run
  // (gib::EnvironmentError) is recorded as failed there too and the others go on, while bad input
  // or an internal error stops it.
  bool part = false;
  std::string gl_device;  // empty: $GIBENCH_GL_DEVICE, else auto
  bool progress = false;  // progress bars on a terminal
  // `gibench merge`: where the log of a job without a result is kept (its Slurm task's output),
  // if anywhere.
  std::function<std::optional<std::filesystem::path>(const std::filesystem::path& run_dir,
                                                     const std::string& job_id)>
      log_of;
  std::FILE* log = stderr;  // one line per job as it starts and ends
};

struct RunOutcome {
  results::RunResults results;
  std::size_t ran = 0;      // jobs run now
  std::size_t skipped = 0;  // jobs finished by an earlier, interrupted run
  std::size_t failed = 0;   // jobs without a result (a whole run's only by EnvironmentError)
  std::filesystem::path run_dir;
  std::filesystem::path results_file;
  std::int64_t history_row = 0;  // 0 when not recorded
};

// The jobs of `suite` that `only` selects, in suite order. Throws gib::InputError when a pattern
// matches no job.
std::vector<Job> selectJobs(const Suite& suite, const std::vector<std::string>& only);

// The jobs a run of `options` does: --only's, then its shard, or the one named job.
std::vector<Job> selectRunJobs(const Suite& suite, const RunOptions& options);

// The run directory `options.out_dir` opened for the suite: the run in it, or a new one (a fresh
// run id and start). Throws gib::InputError as RunDirectory::open does.
RunDirectory openRunDirectory(const Suite& suite, const RunOptions& options);

// Throws gib::InputError for bad input found before anything is written (an unloadable scene, a
// bad parameter, no GL when a technique job needs it, an unusable --out or store). A part
// (options.part) returns with `results` holding only its own jobs and writes no results.json.
RunOutcome runSuite(const Suite& suite, const RunOptions& options);

// Renders into the store the references of the job `options.job` (a Slurm CPU task, so that the
// job's GPU task finds them there), nothing else.
void obtainReferencesOfJob(const Suite& suite, const RunOptions& options);

// `gibench merge`: assembles the runs in `dirs` (shards of one suite, or one directory that
// several processes worked in) into `options.out_dir` (default: the first): their job directories
// gathered, then results.json, the CSV and, when no job failed, the history row, as a whole run
// writes them. A job with no result is in the results as failed, with its failure record or its
// Slurm task's log. Throws gib::InputError when a directory holds no run or a run of another suite.
RunOutcome mergeRuns(const std::vector<std::filesystem::path>& dirs, const RunOptions& options);

}  // namespace gib::suites
