// gibench run SUITE.toml [--out DIR] [--store DIR] [--db FILE | --no-history] [--jobs N]
//                        [--only PATTERN ...] [--list] [--gl-device D] [--trend-runs N]
//                        [--junit FILE.xml] [--summary FILE.md]
//                        [--shard I/N | --slurm [--partition-cpu P] [--partition-gpu P]
//                         [--sbatch-arg ARG ...] [--gpu-sbatch-arg ARG ...] [--resume] [--wait]]
#include "cli/ci_outputs.h"
#include "cli/commands.h"
#include "cli/run_summary.h"
#include "common/cache_paths.h"
#include "common/input_error.h"
#include "common/progress.h"
#include "reports/report_labels.h"
#include "suites/run_environment.h"
#include "suites/slurm_submission.h"
#include "suites/suite_file.h"
#include "suites/suite_runner.h"

#include <fmt/format.h>

#include <algorithm>
#include <memory>

namespace gib::cli {

namespace {

namespace fs = std::filesystem;

struct RunCommandOptions {
  std::string suite;
  std::string out;
  std::string store;
  std::string db;
  bool no_history = false;
  int jobs = 1;
  std::vector<std::string> only;
  bool list = false;
  std::string gl_device;
  int trend_runs = 20;
  CiOutputs ci;
  std::string shard;
  bool slurm = false;
  suites::SlurmOptions slurm_options;
  bool wait = false;
  // A Slurm task (written into its batch script by --slurm, not typed by people).
  std::string task_list;
  int task_index = -1;
};

// "runs/smoke-20261122-100405": a new directory per run unless --out names one (to resume).
fs::path defaultOutDir(const std::string& suite) {
  std::string stamp;
  for (char c : suites::utcTimestamp())
    if (std::isdigit(static_cast<unsigned char>(c))) stamp += c;
  return fs::path("runs") / fmt::format("{}-{}-{}", suite, stamp.substr(0, 8), stamp.substr(8));
}

void checkModes(const RunCommandOptions& o) {
  if (o.trend_runs < 2)
    throw InputError(fmt::format("--trend-runs {} draws no trend; give 2 or more", o.trend_runs));
  if (o.no_history && !o.db.empty())
    throw InputError("--db and --no-history contradict each other; give one of them");
  if (o.slurm && !o.shard.empty())
    throw InputError("--slurm and --shard contradict each other: Slurm makes its own tasks");
  const bool slurm_only =
      o.wait || o.slurm_options.resume || !o.slurm_options.partition_cpu.empty() ||
      !o.slurm_options.partition_gpu.empty() || !o.slurm_options.sbatch_args.empty() ||
      !o.slurm_options.gpu_sbatch_args.empty();
  if (slurm_only && !o.slurm)
    throw InputError("--wait, --resume, --partition-* and --*sbatch-arg go with --slurm; add it");
  if (o.slurm && o.out.empty() && o.slurm_options.resume)
    throw InputError("--resume needs the run to resume: give its directory with --out");
  if (!o.task_list.empty() && (o.slurm || !o.shard.empty() || o.task_index < 0))
    throw InputError("--task-list is for a Slurm task: give it with --task-index and nothing else");
  if (o.ci.requested() && (!o.shard.empty() || !o.task_list.empty()))
    throw InputError(
        "--junit and --summary describe a whole run, and a --shard part is not one; give them to "
        "`gibench merge` once every shard has run");
  o.ci.check();
}

// A Slurm task: one line of a task list, run as a part of the run in --out.
int runSlurmTask(const suites::Suite& suite, suites::RunOptions options,
                 const RunCommandOptions& o) {
  const suites::SlurmTask task = suites::readSlurmTask(o.task_list, o.task_index);
  options.job = task.job;
  options.part = true;
  options.history_db.clear();
  if (task.references_only) {
    suites::obtainReferencesOfJob(suite, options);
    return 0;
  }
  return suites::runSuite(suite, options).failed == 0 ? 0 : 1;
}

int submitSlurm(const suites::Suite& suite, const suites::RunOptions& options,
                const RunCommandOptions& o) {
  // The merge job writes the CI outputs, as it writes the report.
  suites::SlurmOptions slurm = o.slurm_options;
  slurm.merge_arguments = o.ci.mergeArguments();
  const suites::SlurmSubmission submission = suites::submitToSlurm(suite, options, slurm);
  fmt::print("run        {} of suite '{}' in {}\n", submission.run_id, suite.name,
             options.out_dir.string());
  if (submission.finished_earlier > 0)
    fmt::print("jobs       {} finished earlier, not submitted\n", submission.finished_earlier);
  if (!submission.cpu_array.empty())
    fmt::print("slurm      {} reference array ({} tasks)\n", submission.cpu_array,
               submission.cpu_tasks);
  if (!submission.gpu_array.empty())
    fmt::print("slurm      {} technique array ({} tasks)\n", submission.gpu_array,
               submission.gpu_tasks);
  fmt::print("slurm      {} merge job\n", submission.merge_job);
  fmt::print("logs       {}\n", (submission.dir / "logs").string());
  std::fflush(stdout);
  if (!o.wait) return 0;
  const int status = suites::waitForMerge(submission, stderr);
  const fs::path report = options.out_dir / "index.html";
  fmt::print("merged     exit status {}; report {}\n", status, report.string());
  fmt::print("open       {}\n", reports::fileUrl(report));
  return status;
}

int runRun(const RunCommandOptions& o) {
  const suites::Suite suite = suites::loadSuiteFile(o.suite);
  if (o.list) {
    for (const suites::Job& job : suites::selectJobs(suite, o.only)) fmt::print("{}\n", job.id);
    return 0;
  }
  checkModes(o);
  suites::RunOptions options;
  options.suite_file = o.suite;
  options.out_dir = o.out.empty() ? defaultOutDir(suite.name) : fs::path(o.out);
  options.store_root = o.store.empty() ? defaultStoreRoot() : fs::path(o.store);
  if (!o.no_history)
    options.history_db = o.db.empty() ? historyDatabasePath(options.store_root) : fs::path(o.db);
  options.parallel_jobs = o.jobs;
  options.only = o.only;
  options.gl_device = o.gl_device;
  options.progress = ProgressBar::stderrIsTerminal();
  if (!o.task_list.empty()) return runSlurmTask(suite, options, o);
  if (o.slurm) return submitSlurm(suite, options, o);
  if (!o.shard.empty()) {
    options.shard = suites::parseShard(o.shard);
    options.part = true;
    const suites::RunOutcome outcome = suites::runSuite(suite, options);
    fmt::print("shard      {}/{}: {} jobs run, {} finished earlier, {} failed\n",
               options.shard.index, options.shard.count, outcome.ran - outcome.failed,
               outcome.skipped, outcome.failed);
    fmt::print("merge      gibench merge {} (once every shard has run)\n",
               outcome.run_dir.string());
    return outcome.failed == 0 ? 0 : 1;
  }
  const suites::RunOutcome outcome = suites::runSuite(suite, options);
  const fs::path report = writeRunReport(outcome, options, o.trend_runs, o.ci);
  printRunSummary(outcome, report, o.ci);
  // Last, where a reader looks: the address a browser opens (a bare path loses a "#…" view).
  fmt::print("open       {}\n", reports::fileUrl(report));
  if (outcome.failed == 0) return 0;
  // Jobs this machine could not run: the others were measured and reported; one line and exit
  // code 1, as for any environment error.
  const auto first = std::find_if(outcome.results.jobs.begin(), outcome.results.jobs.end(),
                                  [](const results::JobResult& job) { return job.failed(); });
  fmt::print(stderr, "gibench: {} of {} jobs failed (first, {}: {}); the report shows them\n",
             outcome.failed, outcome.results.jobs.size(), first->id, first->failure);
  return 1;
}

}  // namespace

CommandRunner addRunCommand(CLI::App& app) {
  auto o = std::make_shared<RunCommandOptions>();
  CLI::App* run = app.add_subcommand(
      "run", "Run a suite: render, measure and record every job; write results and a report");
  run->add_option("suite", o->suite, "suite file (suites/smoke.toml, suites/nightly.toml, …)")
      ->required();
  run->add_option("--out", o->out,
                  "run directory (default runs/<suite>-<date>-<time>); give an interrupted "
                  "run's directory to resume it");
  run->add_option("--store", o->store,
                  "reference store (default $GIBENCH_STORE or ~/.cache/gibench)");
  run->add_option("--db", o->db, "history database (default <store>/history.sqlite)");
  run->add_flag("--no-history", o->no_history, "do not record the run in a history database");
  run->add_option("--jobs", o->jobs, "jobs at a time (timings are only comparable at 1)");
  run->add_option("--only", o->only, "run only the jobs whose id matches a glob pattern");
  run->add_flag("--list", o->list, "print the job ids (after --only) and exit");
  run->add_option("--gl-device", o->gl_device, "auto | surfaceless | N (EGL device index)");
  run->add_option("--trend-runs", o->trend_runs, "runs shown in the report's trend charts");
  o->ci.addOptions(*run);  // with --slurm, the merge job writes them
  run->add_option("--shard", o->shard,
                  "run only the i-th of n slices of the jobs (I/N); `gibench merge` assembles "
                  "the shards");
  run->add_flag("--slurm", o->slurm,
                "submit the suite to Slurm as job arrays (references, techniques) and a merge "
                "job; prints the job ids and returns");
  run->add_option("--partition-cpu", o->slurm_options.partition_cpu,
                  "Slurm partition of the reference tasks and the merge (default: Slurm's)");
  run->add_option("--partition-gpu", o->slurm_options.partition_gpu,
                  "Slurm partition of the technique tasks (default: Slurm's)");
  run->add_option("--sbatch-arg", o->slurm_options.sbatch_args,
                  "an sbatch option for every job (e.g. --sbatch-arg=--exclusive)")
      ->allow_extra_args(false);
  run->add_option("--gpu-sbatch-arg", o->slurm_options.gpu_sbatch_args,
                  "an sbatch option for the technique tasks (e.g. --gpu-sbatch-arg=--gres=gpu:1)")
      ->allow_extra_args(false);
  run->add_flag("--resume", o->slurm_options.resume,
                "with --slurm and --out: submit only the jobs without a result");
  run->add_flag("--wait", o->wait, "with --slurm: wait for the merge job and exit with its status");
  run->add_option("--task-list", o->task_list)->group("");  // a Slurm task's own options
  run->add_option("--task-index", o->task_index)->group("");
  return [o] { return runRun(*o); };
}

}  // namespace gib::cli
