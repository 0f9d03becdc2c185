#include "suites/slurm_submission.h"

#include "common/input_error.h"
#include "common/subprocess.h"
#include "image/output_files.h"
#include "reference/reference_store.h"
#include "suites/job_execution.h"
#include "suites/run_directory.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

namespace gib::suites {

namespace {

namespace fs = std::filesystem;

constexpr const char* kRunLine = "run ";
constexpr const char* kReferencesLine = "references ";

// The first line of a program's complaint, for a one-line error.
std::string firstLine(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? "no message" : line;
}

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
  return false;
}

ProgramResult runSlurmCommand(const std::vector<std::string>& argv, const fs::path& work_dir) {
  try {
    return runProgram(argv, work_dir);
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("cannot run `{}` ({}); check the Slurm client installation",
                                 argv.front(), e.what()));
  }
}

void checkPartition(const std::string& partition, const char* option, const fs::path& work_dir) {
  if (partition.empty()) return;
  const ProgramResult result =
      runSlurmCommand({"scontrol", "show", "partition", partition}, work_dir);
  if (result.exit_code != 0)
    throw InputError(
        fmt::format("Slurm has no partition '{}' ({}: {}); list the partitions with "
                    "`sinfo -s`",
                    partition, option, firstLine(result.err + result.out)));
}

// A word the shell reads back unchanged: 'it'\''s'.
std::string shellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// Every job in Slurm's queue by its array job id (a plain job's own id), with the reason it waits
// ("None" when running). One query of the whole queue rather than `squeue -j IDS`: that fails as a
// whole once one of the ids has left the controller's memory (MinJobAge), as finished jobs do.
std::map<std::string, std::string> queuedJobs(const fs::path& work_dir) {
  const ProgramResult queue = runSlurmCommand({"squeue", "-h", "-o", "%F %r"}, work_dir);
  if (queue.exit_code != 0)
    throw InputError(fmt::format("squeue failed ({}); check that the Slurm controller runs",
                                 firstLine(queue.err + queue.out)));
  std::map<std::string, std::string> jobs;
  std::istringstream lines(queue.out);
  for (std::string id, reason; lines >> id && std::getline(lines, reason);) jobs[id] += reason;
  return jobs;
}

// The Slurm job ids of every earlier submission of the run (from their submission.json).
std::vector<std::string> earlierJobIds(const fs::path& slurm_dir) {
  std::vector<std::string> ids;
  std::error_code ec;
  for (fs::directory_iterator it(slurm_dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::ifstream in(it->path() / "submission.json");
    const nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (!json.is_object()) continue;
    for (const char* key : {"cpu_array", "gpu_array", "merge_job"})
      if (json.contains(key) && json[key].is_string() && !json[key].get<std::string>().empty())
        ids.push_back(json[key]);
  }
  return ids;
}

// The next submission number: one more than the highest DIR/slurm/<n>.
int nextSubmissionNumber(const fs::path& slurm_dir) {
  int highest = 0;
  std::error_code ec;
  for (fs::directory_iterator it(slurm_dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!name.empty() && name.find_first_not_of("0123456789") == std::string::npos)
      highest = std::max(highest, std::atoi(name.c_str()));
  }
  return highest + 1;
}

// The task lists: the CPU array's (pending reference jobs, then one task per missing reference
// key of the pending technique jobs) and the GPU array's (the pending technique jobs).
struct TaskLists {
  std::vector<std::string> cpu, gpu;
};

TaskLists planTasks(const std::vector<PreparedJob>& pending, const ref::ReferenceStore& store) {
  TaskLists lists;
  std::set<std::string> covered;  // keys a CPU task renders or the store has
  for (const PreparedJob& job : pending)
    if (!job.technique) {
      lists.cpu.push_back(kRunLine + job.job->id);
      for (const ref::ReferenceSpec& spec : jobReferences(job))
        covered.insert(ref::referenceKey(job.scene, spec));
    }
  for (const PreparedJob& job : pending) {
    if (!job.technique) continue;
    lists.gpu.push_back(kRunLine + job.job->id);
    bool missing = false;
    for (const ref::ReferenceSpec& spec : jobReferences(job)) {
      const std::string key = ref::referenceKey(job.scene, spec);
      if (!store.contains(key) && covered.insert(key).second) missing = true;
    }
    if (missing) lists.cpu.push_back(kReferencesLine + job.job->id);
  }
  return lists;
}

void writeLines(const fs::path& file, const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  image::writeTextFile(file, text);
}

void writeScript(const fs::path& file, const std::string& body) {
  image::writeTextFile(file, "#!/bin/sh\n" + body);
  fs::permissions(file, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                            fs::perms::others_read | fs::perms::others_exec);
}

// The job id sbatch --parsable prints ("123" or "123;cluster").
std::string parsedJobId(const std::string& out) {
  std::string id = out.substr(0, out.find_first_of(";\n"));
  if (id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
    throw InputError(
        fmt::format("sbatch printed '{}', not a job id; check the Slurm client", firstLine(out)));
  return id;
}

class Submitter {
 public:
  Submitter(fs::path work_dir, std::string submitted_at)
      : work_dir_(std::move(work_dir)), submitted_at_(std::move(submitted_at)) {}

  // Submits a batch job; on refusal cancels what this submission submitted before and throws.
  std::string submit(const std::vector<std::string>& options, const std::string& what) {
    std::vector<std::string> argv = {"sbatch", "--parsable",
                                     "--export=ALL,GIBENCH_SUBMITTED_AT=" + submitted_at_};
    argv.insert(argv.end(), options.begin(), options.end());
    ++calls_;
    const ProgramResult result = runSlurmCommand(argv, work_dir_);
    if (result.exit_code != 0) {
      std::string cancelled;
      if (!submitted_.empty()) {
        std::vector<std::string> scancel = {"scancel"};
        scancel.insert(scancel.end(), submitted_.begin(), submitted_.end());
        runSlurmCommand(scancel, work_dir_);
        cancelled = fmt::format("; the jobs already submitted ({}) were cancelled",
                                fmt::join(submitted_, ", "));
      }
      throw InputError(fmt::format("sbatch refused the {} ({}){}", what,
                                   firstLine(result.err + result.out), cancelled));
    }
    submitted_.push_back(parsedJobId(result.out));
    return submitted_.back();
  }
  int calls() const { return calls_; }

 private:
  fs::path work_dir_;
  std::string submitted_at_;
  std::vector<std::string> submitted_;
  int calls_ = 0;
};

std::vector<std::string> arrayOptions(const std::string& name, std::size_t tasks,
                                      const fs::path& log_pattern, const std::string& partition,
                                      const std::vector<std::string>& extra) {
  std::vector<std::string> options = {"--job-name=" + name, fmt::format("--array=0-{}", tasks - 1),
                                      "--output=" + log_pattern.string()};
  if (!partition.empty()) options.push_back("--partition=" + partition);
  options.insert(options.end(), extra.begin(), extra.end());
  return options;
}

}  // namespace

SlurmSubmission submitToSlurm(const Suite& suite, const RunOptions& options,
                              const SlurmOptions& slurm) {
  // Bad input first: nothing is written or submitted until all of it has been checked.
  for (const char* program : {"sbatch", "squeue", "scontrol"})
    if (!onPath(program))
      throw InputError(fmt::format(
          "--slurm needs Slurm's `{}` on PATH; install the Slurm client (Debian: slurm-client) "
          "or start a one-node cluster with scripts/slurm-local.sh start",
          program));
  const fs::path work_dir = fs::temp_directory_path();
  checkPartition(slurm.partition_cpu, "--partition-cpu", work_dir);
  checkPartition(slurm.partition_gpu, "--partition-gpu", work_dir);
  const std::vector<Job> jobs = selectRunJobs(suite, options);
  std::vector<PreparedJob> prepared;
  for (const Job& job : jobs) prepared.push_back(prepareJob(job));
  std::error_code ec;
  const bool existing = fs::exists(options.out_dir / "run-state.json", ec);
  if (existing && !slurm.resume)
    throw InputError(
        fmt::format("'{}' holds a run already; add --resume to submit its "
                    "unfinished jobs, or choose another --out",
                    options.out_dir.string()));
  const fs::path slurm_dir = options.out_dir / "slurm";
  if (existing) {
    const std::map<std::string, std::string> queued = queuedJobs(work_dir);
    for (const std::string& id : earlierJobIds(slurm_dir))
      if (queued.count(id))
        throw InputError(fmt::format(
            "'{}' still has Slurm job {} queued or running; wait for it or scancel it, then "
            "resume",
            options.out_dir.string(), id));
  }
  const RunDirectory dir = openRunDirectory(suite, options);

  SlurmSubmission submission;
  submission.run_id = dir.runId();
  std::vector<PreparedJob> pending;
  for (const PreparedJob& job : prepared) {
    if (dir.finishedJob(*job.job, job.hash))
      ++submission.finished_earlier;
    else
      pending.push_back(job);
  }
  const ref::ReferenceStore store(options.store_root);
  const TaskLists lists = planTasks(pending, store);

  submission.number = nextSubmissionNumber(slurm_dir);
  submission.dir = fs::absolute(slurm_dir / std::to_string(submission.number));
  fs::create_directories(submission.dir / "logs", ec);
  if (ec)
    throw InputError(fmt::format("cannot create '{}' ({}); choose another --out",
                                 submission.dir.string(), ec.message()));
  writeLines(submission.dir / "cpu.tasks", lists.cpu);
  writeLines(submission.dir / "gpu.tasks", lists.gpu);

  const std::string gibench = shellQuoted(currentExecutable().string());
  const std::string run_dir = shellQuoted(fs::absolute(options.out_dir).string());
  const std::string store_dir = shellQuoted(fs::absolute(options.store_root).string());
  std::string task_options;
  if (!options.gl_device.empty()) task_options += " --gl-device " + shellQuoted(options.gl_device);
  writeScript(submission.dir / "task.sh",
              fmt::format("# One task of a GI Bench Slurm run: line $SLURM_ARRAY_TASK_ID of the "
                          "task list $1.\nexec {} run {} --out {} --store {} --no-history{} "
                          "--task-list \"$1\" --task-index \"$SLURM_ARRAY_TASK_ID\"\n",
                          gibench, shellQuoted(fs::absolute(suite.file).string()), run_dir,
                          store_dir, task_options));
  std::string merge_options = " --no-history";
  if (!options.history_db.empty())
    merge_options = " --db " + shellQuoted(fs::absolute(options.history_db).string());
  for (const std::string& argument : slurm.merge_arguments) {
    merge_options += ' ';  // appended apart: GCC 12's -Wrestrict misfires on " " + string
    merge_options += shellQuoted(argument);
  }
  const fs::path status_file = submission.dir / "merge.status";
  writeScript(
      submission.dir / "merge.sh",
      fmt::format("# The merge of a GI Bench Slurm run: results, history row, report.\n"
                  "{} merge {} --store {}{}\nstatus=$?\necho $status > {}\nexit $status\n",
                  gibench, run_dir, store_dir, merge_options, shellQuoted(status_file.string())));

  const auto now = std::chrono::system_clock::now().time_since_epoch();
  Submitter submitter(submission.dir,
                      fmt::format("{:.3f}", std::chrono::duration<double>(now).count()));
  const std::string name = "gibench-" + suite.name;
  const std::string task_script = (submission.dir / "task.sh").string();
  std::vector<std::string> after;
  if (!lists.cpu.empty()) {
    std::vector<std::string> cpu =
        arrayOptions(name + "-cpu", lists.cpu.size(), submission.dir / "logs" / "cpu-%a.log",
                     slurm.partition_cpu, slurm.sbatch_args);
    cpu.push_back(task_script);
    cpu.push_back((submission.dir / "cpu.tasks").string());
    submission.cpu_array = submitter.submit(cpu, "reference array");
    submission.cpu_tasks = lists.cpu.size();
    after.push_back(submission.cpu_array);
  }
  if (!lists.gpu.empty()) {
    std::vector<std::string> extra = slurm.sbatch_args;
    extra.insert(extra.end(), slurm.gpu_sbatch_args.begin(), slurm.gpu_sbatch_args.end());
    if (!submission.cpu_array.empty())
      extra.push_back("--dependency=afterany:" + submission.cpu_array);
    std::vector<std::string> gpu =
        arrayOptions(name + "-gpu", lists.gpu.size(), submission.dir / "logs" / "gpu-%a.log",
                     slurm.partition_gpu, extra);
    gpu.push_back(task_script);
    gpu.push_back((submission.dir / "gpu.tasks").string());
    submission.gpu_array = submitter.submit(gpu, "technique array");
    submission.gpu_tasks = lists.gpu.size();
    after.push_back(submission.gpu_array);
  }
  std::vector<std::string> merge = {"--job-name=" + name + "-merge",
                                    "--output=" + (submission.dir / "logs" / "merge.log").string()};
  if (!slurm.partition_cpu.empty()) merge.push_back("--partition=" + slurm.partition_cpu);
  merge.insert(merge.end(), slurm.sbatch_args.begin(), slurm.sbatch_args.end());
  if (!after.empty())
    merge.push_back(fmt::format("--dependency=afterany:{}", fmt::join(after, ":")));
  merge.push_back((submission.dir / "merge.sh").string());
  submission.merge_job = submitter.submit(merge, "merge job");
  submission.sbatch_calls = submitter.calls();

  const nlohmann::ordered_json record = {{"run_id", submission.run_id},
                                         {"cpu_array", submission.cpu_array},
                                         {"cpu_tasks", submission.cpu_tasks},
                                         {"gpu_array", submission.gpu_array},
                                         {"gpu_tasks", submission.gpu_tasks},
                                         {"merge_job", submission.merge_job},
                                         {"sbatch_calls", submission.sbatch_calls}};
  image::writeTextFile(submission.dir / "submission.json", record.dump(2) + "\n");
  return submission;
}

int waitForMerge(const SlurmSubmission& submission, std::FILE* log) {
  fmt::print(log, "waiting for the merge job {} (after the arrays {}{})\n", submission.merge_job,
             submission.cpu_array.empty() ? "-" : submission.cpu_array,
             submission.gpu_array.empty() ? "" : " and " + submission.gpu_array);
  std::fflush(log);
  const fs::path status_file = submission.dir / "merge.status";
  for (;;) {
    std::ifstream in(status_file);
    int status = 0;
    if (in >> status) return status;
    const std::map<std::string, std::string> queued = queuedJobs(submission.dir);
    // A task whose launch failed is held by Slurm and never ends by itself.
    for (const std::string& id :
         {submission.cpu_array, submission.gpu_array, submission.merge_job}) {
      auto it = queued.find(id);
      if (!id.empty() && it != queued.end() && it->second.find("held") != std::string::npos) {
        fmt::print(log,
                   "Slurm holds job {} ({}); see the slurmd log, then scancel the run's jobs\n", id,
                   it->second);
        return 1;
      }
    }
    // Gone from the queue: its status file is written by now, or never will be.
    if (!queued.count(submission.merge_job)) {
      std::ifstream again(status_file);
      if (again >> status) return status;
      fmt::print(log, "the merge job {} ended without a status (cancelled?); see {}\n",
                 submission.merge_job, (submission.dir / "logs" / "merge.log").string());
      return 1;
    }
    std::this_thread::sleep_for(std::chrono::seconds(1));
  }
}

SlurmTask readSlurmTask(const fs::path& file, int index) {
  std::ifstream in(file);
  if (!in)
    throw InputError(
        fmt::format("cannot read the task list '{}'; check --task-list", file.string()));
  std::string line;
  for (int i = 0; i <= index && std::getline(in, line);) ++i;
  if (index < 0 || !in)
    throw InputError(
        fmt::format("the task list '{}' has no line {}; check --task-index", file.string(), index));
  SlurmTask task;
  if (line.rfind(kRunLine, 0) == 0) {
    task.job = line.substr(std::string(kRunLine).size());
  } else if (line.rfind(kReferencesLine, 0) == 0) {
    task.references_only = true;
    task.job = line.substr(std::string(kReferencesLine).size());
  } else {
    throw InputError(
        fmt::format("line {} of the task list '{}' is neither 'run' nor "
                    "'references'; the list was not written by gibench",
                    index, file.string()));
  }
  return task;
}

std::optional<fs::path> slurmLogOf(const fs::path& run_dir, const std::string& job_id) {
  const fs::path slurm_dir = run_dir / "slurm";
  // The latest submission that had a task for the job.
  for (int n = nextSubmissionNumber(slurm_dir) - 1; n >= 1; --n)
    for (const char* array : {"gpu", "cpu"}) {
      std::ifstream in(slurm_dir / std::to_string(n) / fmt::format("{}.tasks", array));
      int index = 0;
      for (std::string line; std::getline(in, line); ++index)
        if (line == kRunLine + job_id) {
          const fs::path log =
              slurm_dir / std::to_string(n) / "logs" / fmt::format("{}-{}.log", array, index);
          std::error_code ec;
          if (fs::exists(log, ec)) return log;
          return std::nullopt;
        }
    }
  return std::nullopt;
}

}  // namespace gib::suites
