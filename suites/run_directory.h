// The directory of one run (`gibench run --out DIR`), and what makes a run resumable:
//
//   DIR/run-state.json          the run's id, suite (name and file), job selection and start,
//                               written when the run starts
//   DIR/jobs/<slug>/            one directory per job: images, timings, and last of all its
//                               result.json (written atomically: its presence means done), or
//                               failed.json (shards and Slurm tasks, which go on); the files of
//                               the jobs are named in suites/job_directory.h
//   DIR/slurm/                  `gibench run --slurm`: task lists, scripts, logs
//   DIR/results.json, results.csv, index.html, report/   written when every job is done
//
// A rerun with the same --out keeps the run's id and skips every job whose result.json records
// the same job hash (the same definition, scene and program version); anything else in a job's
// directory is the debris of an interrupted or failed job and is cleared before the job runs
// again. Several processes may work in one run directory at once (shards, Slurm tasks on a shared
// filesystem): each writes only its own jobs' directories, and the state file is created
// atomically, so the first process's run id is everyone's.
#pragma once

#include "results/results.h"
#include "suites/job_directory.h"
#include "suites/job_expansion.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gib::suites {

// What run-state.json records.
struct RunState {
  std::string run_id;
  std::string suite;                 // its name
  std::filesystem::path suite_file;  // absolute, so that `gibench merge` finds it from anywhere
  std::vector<std::string> only;     // the run's --only patterns (empty: every job)
  std::string started;               // ISO 8601 UTC
};

class RunDirectory {
 public:
  // Opens the run in `dir` for `fresh.suite`, or starts one with `fresh` (id, start, file,
  // selection). Throws gib::InputError when `dir` is a file, holds something other than a gibench
  // run, holds a run of another suite, or cannot be written.
  static RunDirectory open(const std::filesystem::path& dir, const RunState& fresh);
  // The state of the run in `dir`. Throws gib::InputError when `dir` holds no (intact) run.
  static RunState readState(const std::filesystem::path& dir);

  const std::filesystem::path& path() const { return dir_; }
  const std::string& runId() const { return state_.run_id; }
  const std::string& started() const { return state_.started; }
  const RunState& state() const { return state_; }
  bool resumed() const { return resumed_; }

  JobDirectory jobDirectory(const Job& job) const;
  // The job's recorded result when it finished with this `job_hash`.
  std::optional<results::JobResult> finishedJob(const Job& job, const std::string& job_hash) const;
  // An empty directory for the job (the debris of an earlier attempt removed).
  JobDirectory prepareJob(const Job& job) const;
  // Records the finished job (atomically: last of its files).
  void recordJob(const Job& job, const results::JobResult& result) const;
  // Records why the job failed (a shard or Slurm task goes on with its other jobs); a resume runs
  // the job again.
  void recordFailure(const Job& job, const std::string& job_hash, const std::string& error) const;
  // The recorded failure of the job with this `job_hash`, if any.
  std::optional<std::string> failure(const Job& job, const std::string& job_hash) const;

 private:
  std::filesystem::path dir_;
  RunState state_;
  bool resumed_ = false;
};

}  // namespace gib::suites
