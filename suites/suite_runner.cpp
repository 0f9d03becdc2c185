#include "suites/suite_runner.h"

#include "common/content_hash.h"
#include "common/input_error.h"
#include "image/exr_io.h"
#include "image/output_files.h"
#include "realtime/gl/context.h"
#include "reference/reference_store.h"
#include "results/history_db.h"
#include "results/results_csv.h"
#include "results/results_json.h"
#include "suites/job_execution.h"
#include "suites/run_conditions.h"
#include "suites/run_directory.h"
#include "suites/run_environment.h"

#include <fmt/format.h>
#include <fnmatch.h>
#include <unistd.h>

#include <atomic>
#include <exception>
#include <fstream>
#include <iterator>
#include <mutex>
#include <optional>
#include <random>
#include <sstream>
#include <thread>

namespace gib::suites {

namespace {

namespace fs = std::filesystem;

bool matchesAny(const std::string& id, const std::vector<std::string>& patterns) {
  for (const std::string& pattern : patterns)
    if (fnmatch(pattern.c_str(), id.c_str(), 0) == 0) return true;
  return false;
}

std::string fileHash(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ContentHasher hasher;
  hasher.addString(bytes);
  return hasher.hexDigest();
}

// "20261122-100405-smoke-1a2b3c4d": sortable by start, unique across hosts and processes.
std::string newRunId(const std::string& suite, const results::RunInfo& info) {
  ContentHasher hasher;
  hasher.addString(info.started);
  hasher.addString(info.host);
  hasher.addU64(std::uint64_t(getpid()));
  hasher.addU64(std::random_device{}());
  std::string stamp = info.started;  // 2026-11-22T10:04:05Z
  std::string compact;
  for (char c : stamp)
    if (std::isdigit(static_cast<unsigned char>(c))) compact += c;
  return fmt::format("{}-{}-{}-{}", compact.substr(0, 8), compact.substr(8), suite,
                     hasher.hexDigest().substr(0, 8));
}

// Finds the problems that would otherwise stop the run half way: a store or database that cannot
// be written, no GL for the technique jobs.
void checkResources(const RunOptions& options, const std::vector<PreparedJob>& jobs) {
  std::error_code ec;
  fs::create_directories(options.store_root, ec);
  if (ec || access(options.store_root.c_str(), W_OK) != 0)
    throw InputError(
        fmt::format("cannot write the reference store '{}'{}; choose another with "
                    "--store DIR",
                    options.store_root.string(), ec ? " (" + ec.message() + ")" : ""));
  if (!options.history_db.empty()) results::HistoryDatabase::open(options.history_db);
  for (const PreparedJob& job : jobs)
    if (job.technique) {
      rt::gl::ContextOptions gl;
      gl.device = options.gl_device;
      rt::gl::Context::create(gl);  // throws InputError naming what is missing
      return;
    }
}

// The GL implementation of a technique job finished earlier, from its image's metadata.
std::optional<rt::gl::GlIdentity> glOfRecordedJob(const fs::path& run_dir,
                                                  const results::JobResult& job) {
  if (job.outputs.timings_json.empty() || job.outputs.image.empty()) return std::nullopt;
  try {
    const image::ExrFile file = image::readExr(run_dir / job.outputs.image);
    auto get = [&](const char* key) {
      auto it = file.metadata.find(key);
      return it == file.metadata.end() ? std::string() : it->second;
    };
    return rt::gl::GlIdentity{get("gibench/gl_device"), get("gibench/gl_vendor"),
                              get("gibench/gl_renderer"), get("gibench/gl_version")};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::string primaryMetric(const std::vector<results::JobResult>& jobs) {
  std::string first;
  for (const results::JobResult& job : jobs)
    for (const auto& [name, value] : job.metrics) {
      if (name == "relmse") return name;
      if (first.empty()) first = name;
    }
  return first;
}

std::string summaryOf(const results::JobResult& job, const std::string& metric) {
  std::string text = fmt::format("done in {:.1f} s", job.seconds);
  if (const std::optional<double> value = job.metric(metric))
    text += fmt::format(", {} {:.4g}", metric, *value);
  if (const std::optional<double> frame = job.frameMedianMs())
    text += fmt::format(", frame {:.2f} ms", *frame);
  return text;
}

// Runs the pending jobs on `workers` threads; the first failure stops the hand-out of new tasks
// and is rethrown once the running ones have ended (the finished jobs' results are kept for a
// resume). A job of `repeats` > 1 is several tasks: its first run (images, metrics, timings) and
// each further timed run. Repeats are interleaved across jobs (every job's first run, then every
// job's second, …), so that a drift of the machine spreads over all jobs rather than one; a job is
// recorded when its last task ends.
class JobScheduler {
 public:
  JobScheduler(const std::vector<PreparedJob>& jobs, const RunDirectory& dir,
               const RunOptions& options, ref::ReferenceStore& store,
               std::vector<std::optional<results::JobResult>>& results)
      : jobs_(jobs),
        dir_(dir),
        options_(options),
        store_(store),
        results_(results),
        states_(jobs.size()) {}

  void run(const std::vector<std::size_t>& pending) {
    std::vector<Task> tasks;
    int most = 1;
    for (std::size_t index : pending) {
      states_[index].timings.resize(std::size_t(repeatsOf(index)));
      states_[index].remaining = repeatsOf(index);
      most = std::max(most, repeatsOf(index));
    }
    for (int repeat = 0; repeat < most; ++repeat)
      for (std::size_t index : pending)
        if (repeat < repeatsOf(index)) tasks.push_back({index, repeat});

    std::atomic<std::size_t> next{0};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto worker = [&] {
      for (std::size_t k; (k = next.fetch_add(1)) < tasks.size();) {
        {
          std::lock_guard lock(failure_mutex);
          if (failure) return;
        }
        try {
          runTask(tasks[k]);
        } catch (...) {
          std::lock_guard lock(failure_mutex);
          if (!failure) failure = std::current_exception();
          return;
        }
      }
    };
    const int count = std::max(1, std::min<int>(options_.parallel_jobs, int(tasks.size())));
    std::vector<std::thread> threads;
    for (int i = 1; i < count; ++i) threads.emplace_back(worker);
    worker();
    for (std::thread& thread : threads) thread.join();
    if (failure) std::rethrow_exception(failure);
  }

  std::optional<rt::gl::GlIdentity> gl() const { return gl_; }

 private:
  struct Task {
    std::size_t job;
    int repeat;  // 0: the full first run
  };
  // A job's progress over its tasks.
  struct JobState {
    std::optional<results::JobResult> result;                  // from the first run
    std::vector<std::optional<metrics::PassTimings>> timings;  // of each repeat
    int remaining = 0;
    ConditionsSample before;
    fs::path dir;
  };

  int repeatsOf(std::size_t index) const {
    return jobs_[index].technique ? jobs_[index].job->settings.repeats : 1;
  }

  void log(const std::string& line) {
    std::lock_guard lock(log_mutex_);
    fmt::print(options_.log, "{}\n", line);
    std::fflush(options_.log);
  }

  JobEnvironment environment(const std::string& prefix) {
    JobEnvironment env;
    env.store = &store_;
    env.run_dir = dir_.path();
    env.gl.device = options_.gl_device;
    env.gl.debug = rt::gl::debugOutputByDefault();
    env.progress = options_.progress && options_.parallel_jobs == 1;
    env.note = [this, prefix](const std::string& note) { log(prefix + ": " + note); };
    return env;
  }

  void runTask(const Task& task) {
    const PreparedJob& job = jobs_[task.job];
    const int repeats = repeatsOf(task.job);
    std::string prefix = fmt::format("[{}/{}] {}", task.job + 1, jobs_.size(), job.job->id);
    if (repeats > 1) prefix += fmt::format(" (run {}/{})", task.repeat + 1, repeats);
    JobState& state = states_[task.job];
    const JobEnvironment env = environment(prefix);
    if (task.repeat == 0) {
      {
        std::lock_guard lock(state_mutex_);
        state.before = sampleConditions();
      }
      log(prefix + ": started");
      rt::gl::GlIdentity gl;
      const fs::path job_dir = dir_.prepareJob(*job.job);
      results::JobResult result = executeJob(job, env, job_dir, &gl);
      std::lock_guard lock(state_mutex_);
      if (job.technique && !gl_) gl_ = gl;
      if (result.timings) state.timings[0] = result.timings;
      state.result = std::move(result);
      state.dir = job_dir;
    } else {
      log(prefix + ": timing again");
      metrics::PassTimings timings = repeatTechniqueJob(job, env);
      std::lock_guard lock(state_mutex_);
      state.timings[std::size_t(task.repeat)] = std::move(timings);
    }
    bool last = false;
    {
      std::lock_guard lock(state_mutex_);
      last = --state.remaining == 0;
    }
    if (last) finish(task.job);
  }

  // Every task of the job has ended: its repeats and conditions join the first run's result,
  // which is recorded (the resume point) and logged.
  void finish(std::size_t index) {
    const PreparedJob& job = jobs_[index];
    JobState& state = states_[index];
    results::JobResult result = std::move(*state.result);
    if (state.timings.size() > 1) {
      std::vector<metrics::PassTimings> repeats;
      for (std::optional<metrics::PassTimings>& timings : state.timings)
        repeats.push_back(std::move(*timings));
      recordRepeats(result, std::move(repeats));
      image::writeTextFile(dir_.path() / result.outputs.timings_json,
                           results::passTimingsToJson(*result.timings).dump(2) + "\n");
    }
    result.conditions = conditionsBetween(state.before, sampleConditions());
    dir_.recordJob(*job.job, result);
    log(fmt::format("[{}/{}] {}: {}", index + 1, jobs_.size(), job.job->id,
                    summaryOf(result, primaryMetric({result}))));
    std::lock_guard lock(state_mutex_);
    results_[index] = std::move(result);
  }

  const std::vector<PreparedJob>& jobs_;
  const RunDirectory& dir_;
  const RunOptions& options_;
  ref::ReferenceStore& store_;
  std::vector<std::optional<results::JobResult>>& results_;
  std::vector<JobState> states_;
  std::mutex log_mutex_, state_mutex_;
  std::optional<rt::gl::GlIdentity> gl_;
};

}  // namespace

std::vector<Job> selectJobs(const Suite& suite, const std::vector<std::string>& only) {
  std::vector<Job> all = expandSuite(suite);
  if (only.empty()) return all;
  for (const std::string& pattern : only)
    if (std::none_of(all.begin(), all.end(), [&](const Job& job) {
          return fnmatch(pattern.c_str(), job.id.c_str(), 0) == 0;
        }))
      throw InputError(
          fmt::format("--only '{}' matches no job of suite '{}'; list its jobs with "
                      "`gibench run {} --list`",
                      pattern, suite.name, suite.file.string()));
  std::vector<Job> selected;
  for (Job& job : all)
    if (matchesAny(job.id, only)) selected.push_back(std::move(job));
  return selected;
}

RunOutcome runSuite(const Suite& suite, const RunOptions& options) {
  if (options.parallel_jobs < 1)
    throw InputError(fmt::format("--jobs {} runs nothing; give 1 or more", options.parallel_jobs));
  const std::vector<Job> jobs = selectJobs(suite, options.only);
  std::vector<PreparedJob> prepared;
  for (const Job& job : jobs) prepared.push_back(prepareJob(job));
  checkResources(options, prepared);

  const ConditionsSample before = sampleConditions();
  results::RunInfo info = describeEnvironment();
  info.started = utcTimestamp();
  info.id = newRunId(suite.name, info);
  const RunDirectory dir = RunDirectory::open(options.out_dir, suite.name, info);
  info.id = dir.runId();
  info.started = dir.started();
  fmt::print(options.log, "{} run {} of suite '{}' ({} jobs) in {}\n",
             dir.resumed() ? "resuming" : "starting", info.id, suite.name, jobs.size(),
             dir.path().string());
  if (options.parallel_jobs > 1)
    fmt::print(options.log,
               "note: {} jobs at a time share the CPU, so their timings are not comparable with "
               "a run of --jobs 1\n",
               options.parallel_jobs);

  RunOutcome outcome;
  std::vector<std::optional<results::JobResult>> results(jobs.size());
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    results[i] = dir.finishedJob(jobs[i], prepared[i].hash);
    if (results[i])
      fmt::print(options.log, "[{}/{}] {}: finished by an earlier attempt, skipped\n", i + 1,
                 jobs.size(), jobs[i].id);
    else
      pending.push_back(i);
  }
  outcome.skipped = jobs.size() - pending.size();
  outcome.ran = pending.size();

  ref::ReferenceStore store(options.store_root);
  JobScheduler scheduler(prepared, dir, options, store, results);
  scheduler.run(pending);

  results::RunResults& run = outcome.results;
  for (std::optional<results::JobResult>& result : results) run.jobs.push_back(std::move(*result));
  std::optional<rt::gl::GlIdentity> gl = scheduler.gl();
  for (std::size_t i = 0; !gl && i < run.jobs.size(); ++i)
    gl = glOfRecordedJob(dir.path(), run.jobs[i]);
  if (gl) {
    info.gl_vendor = gl->vendor;
    info.gl_renderer = gl->renderer;
    info.gl_version = gl->version;
    info.gl_device = gl->device;
  }
  info.suite = suite.name;
  info.suite_description = suite.description;
  info.suite_file = options.suite_file;
  info.suite_hash = fileHash(suite.file);
  info.parallel_jobs = options.parallel_jobs;
  info.store = options.store_root.string();
  info.complete = options.only.empty();
  info.finished = utcTimestamp();
  info.conditions = conditionsBetween(before, sampleConditions());
  run.run = info;
  run.tolerances = suite.tolerances;
  for (const results::PaperValue& value : suite.paper)
    if (run.findJob(value.job)) run.paper.push_back(value);
  run.charts = suite.charts;
  run.primary_metric = primaryMetric(run.jobs);

  outcome.run_dir = dir.path();
  outcome.results_file = dir.path() / "results.json";
  results::writeResultsFile(outcome.results_file, run);
  image::writeTextFile(dir.path() / "results.csv", results::resultsCsv(run));
  if (!options.history_db.empty())
    outcome.history_row = results::HistoryDatabase::open(options.history_db).append(run);
  return outcome;
}

}  // namespace gib::suites
