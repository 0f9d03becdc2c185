// The directory of one run (`gibench run --out DIR`), and what makes a run resumable:
//
//   DIR/run-state.json          the run's id, suite and start, written when the run starts
//   DIR/jobs/<slug>/            one directory per job: images, timings, and last of all
//   DIR/jobs/<slug>/result.json   the job's result, written atomically: its presence means done
//   DIR/results.json, results.csv, index.html, report/   written when every job is done
//
// A rerun with the same --out keeps the run's id and skips every job whose result.json records
// the same job hash (the same definition, scene and program version); anything else in a job's
// directory is the debris of an interrupted job and is cleared before the job runs again.
#pragma once

#include "results/results.h"
#include "suites/job_expansion.h"

#include <filesystem>
#include <optional>
#include <string>

namespace gib::suites {

class RunDirectory {
 public:
  // Opens the run in `dir` for `suite`, or starts one with `fresh` (its id and start time).
  // Throws gib::InputError when `dir` is a file, holds something other than a gibench run, holds
  // a run of another suite, or cannot be written.
  static RunDirectory open(const std::filesystem::path& dir, const std::string& suite,
                           const results::RunInfo& fresh);

  const std::filesystem::path& path() const { return dir_; }
  const std::string& runId() const { return run_id_; }
  const std::string& started() const { return started_; }
  bool resumed() const { return resumed_; }

  std::filesystem::path jobDirectory(const Job& job) const;
  // The job's recorded result when it finished with this `job_hash`.
  std::optional<results::JobResult> finishedJob(const Job& job, const std::string& job_hash) const;
  // An empty directory for the job (the debris of an earlier attempt removed).
  std::filesystem::path prepareJob(const Job& job) const;
  // Records the finished job (atomically: last of its files).
  void recordJob(const Job& job, const results::JobResult& result) const;

 private:
  std::filesystem::path dir_;
  std::string run_id_;
  std::string started_;
  bool resumed_ = false;
};

}  // namespace gib::suites
