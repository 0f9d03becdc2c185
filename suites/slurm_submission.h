// `gibench run SUITE --slurm`: a suite run as Slurm job arrays (docs/harness.md, "Runs on many
// machines").
//
// One submission writes, under DIR/slurm/<n>/ (n = 1, then 2, … for each --resume):
//   cpu.tasks, gpu.tasks    one task per line: "run <job id>" or "references <job id>"
//   task.sh, merge.sh       the batch scripts (the gibench binary, suite, run and store by path)
//   logs/cpu-<i>.log, logs/gpu-<i>.log, logs/merge.log   each task's output
//   submission.json         the Slurm job ids, written after the last sbatch
//   merge.status            the merge job's exit status, written by merge.sh
// and submits three jobs: an array of CPU tasks (the suite's reference jobs, and the references
// of its technique jobs that the store lacks, one task per distinct key), an array of technique
// jobs that starts after it (--dependency=afterany), so that every technique finds its references
// in the store and renders none, and a merge job after both (`gibench merge`). Each task runs one
// job through the run directory's resumable machinery; a failed job is recorded and shows in the
// merged results. Assumes a filesystem shared by the submitting host and the nodes, with the
// gibench binary, the suite, the run directory and the store at the same paths on all of them.
#pragma once

#include "suites/suite.h"
#include "suites/suite_runner.h"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gib::suites {

struct SlurmOptions {
  std::string partition_cpu;                 // empty: Slurm's default partition
  std::string partition_gpu;                 // empty: Slurm's default partition
  std::vector<std::string> sbatch_args;      // added to every sbatch call
  std::vector<std::string> gpu_sbatch_args;  // added to the technique array's ("--gres=gpu:1")
  bool resume = false;                       // submit the unfinished jobs of the run in --out
  // Added to the merge job's `gibench merge` ("--junit", "/abs/run.xml"): options that a local
  // run applies when it writes its report. Paths must be absolute: the job runs elsewhere.
  std::vector<std::string> merge_arguments;
};

struct SlurmSubmission {
  int number = 0;  // n of DIR/slurm/<n>
  std::filesystem::path dir;
  std::string cpu_array, gpu_array, merge_job;  // Slurm job ids; empty when not submitted
  std::size_t cpu_tasks = 0, gpu_tasks = 0;
  std::size_t finished_earlier = 0;  // jobs with a result before this submission (--resume)
  int sbatch_calls = 0;
  std::string run_id;
};

// Checks everything a submission needs before it submits anything (sbatch on PATH, the
// partitions, the suite's jobs, the run directory, no earlier tasks of the run still queued), then
// writes the task lists and scripts and submits. Throws gib::InputError (nothing submitted, or
// what was submitted cancelled again).
SlurmSubmission submitToSlurm(const Suite& suite, const RunOptions& options,
                              const SlurmOptions& slurm);

// Blocks until the submission's merge job has ended, then returns its exit status (1 when it
// ended without writing one: cancelled or killed), saying what it waits for on `log`.
int waitForMerge(const SlurmSubmission& submission, std::FILE* log);

// One line of a task list.
struct SlurmTask {
  bool references_only = false;  // "references <job id>": render the job's references only
  std::string job;
};
// Line `index` (0-based, as $SLURM_ARRAY_TASK_ID) of the task list `file`. Throws gib::InputError.
SlurmTask readSlurmTask(const std::filesystem::path& file, int index);

// The output file of the Slurm task that last ran `job_id` in `run_dir`, when it exists.
std::optional<std::filesystem::path> slurmLogOf(const std::filesystem::path& run_dir,
                                                const std::string& job_id);

}  // namespace gib::suites
