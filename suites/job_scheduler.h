// The order, concurrency and failure policy of a run's jobs (`gibench run --jobs N`), apart from
// what a job does: the runner (suites/suite_runner.h) gives it the work as callables, so that the
// policy can be run, and tested, on jobs that render nothing.
//
// A job of `repeats` > 1 is several tasks: its first run (images, metrics, timings) and each
// further timed run. Repeats are interleaved across jobs (every job's first run, then every job's
// second, …), so that a drift of the machine spreads over all jobs rather than one; a job is
// recorded when its last task ends. Tasks run on up to N threads, handed out in that order.
//
// A job that throws gib::EnvironmentError (the machine could not run it), or any exception in a
// part of a run (a shard, a Slurm task), is recorded as failed once, its remaining tasks are
// skipped, and the other jobs go on. Any other exception stops the hand-out of new tasks and is
// rethrown once the running ones have ended; the jobs recorded by then keep their results (the
// resume point).
//
// The log gets one line as a job starts ("[2/5] <id>: started"), as each further run starts
// ("[2/5] <id> (run 2/3): timing again"), as it fails ("[2/5] <id>: failed: <error>") and as it
// is recorded ("[2/5] <id>: done in 3.2 s, relmse 0.0123, frame 4.56 ms"), and the jobs' own
// notes under the same prefix; positions count every job of the run, run now or not.
#pragma once

#include "metrics/pass_timing_summary.h"
#include "results/results.h"
#include "suites/run_conditions.h"

#include <cstddef>
#include <cstdio>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace gib::suites {

// What the scheduler knows of a job.
struct ScheduledJob {
  std::string id;
  int repeats = 1;  // timed runs: the first and repeats − 1 more
};

// Writes one line to the run's log under the prefix of the calling task.
using JobNote = std::function<void(const std::string&)>;

// The work of the jobs, by their index in the run's list. Called from the scheduler's threads,
// up to N at once (each for a different task).
struct JobWork {
  // A job's first run: its result, with its images, metrics and timings.
  std::function<results::JobResult(std::size_t job, const JobNote& note)> first_run;
  // One further timed run of a job whose repeats > 1.
  std::function<metrics::PassTimings(std::size_t job, const JobNote& note)> repeat_run;
  // Records a job all of whose runs ended (its repeats and conditions joined in): the resume point.
  std::function<void(std::size_t job, const results::JobResult& result)> record;
  // Records why a job failed.
  std::function<void(std::size_t job, const std::string& error)> record_failure;
};

struct SchedulerOptions {
  int parallel_jobs = 1;  // N
  bool part = false;      // a shard or Slurm task: every failure is recorded and the others go on
  std::FILE* log = stderr;
};

class JobScheduler {
 public:
  JobScheduler(std::vector<ScheduledJob> jobs, JobWork work, SchedulerOptions options);

  // Runs the jobs at the indices `pending` (in that order) and puts each recorded job's result at
  // its index of `results` (jobs.size() long), leaving the others as they are. Throws the first
  // failure that stops the run.
  void run(const std::vector<std::size_t>& pending,
           std::vector<std::optional<results::JobResult>>& results);

  // The jobs recorded as failed.
  std::size_t failed() const { return failed_; }

 private:
  struct Task {
    std::size_t job;
    int repeat;  // 0: the first run
  };
  // A job's progress over its tasks.
  struct JobState {
    std::optional<results::JobResult> result;                  // from the first run
    std::vector<std::optional<metrics::PassTimings>> timings;  // of each repeat
    int remaining = 0;
    bool failed = false;  // its other tasks are skipped
    ConditionsSample before;
  };

  void runTask(const Task& task);
  void recordFailure(std::size_t job, const std::exception_ptr& error);
  void finish(std::size_t job);
  void log(const std::string& line);

  std::vector<ScheduledJob> jobs_;
  JobWork work_;
  SchedulerOptions options_;
  std::vector<JobState> states_;
  std::vector<std::optional<results::JobResult>>* results_ = nullptr;
  std::mutex log_mutex_, state_mutex_;
  std::size_t failed_ = 0;
};

// Puts every repeat's timings into `result` (JobResult::repeats, in run order) and makes
// `result.timings` the repeat of the median frame time (the lower one of an even count). One
// repeat leaves `result` as it is.
void recordRepeats(results::JobResult& result, std::vector<metrics::PassTimings> repeats);

}  // namespace gib::suites
