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
#include "suites/job_scheduler.h"
#include "suites/primary_metric.h"
#include "suites/run_conditions.h"
#include "suites/run_directory.h"
#include "suites/run_environment.h"
#include "suites/suite_file.h"

#include <fmt/format.h>
#include <fnmatch.h>
#include <unistd.h>

#include <algorithm>
#include <exception>
#include <fstream>
#include <iterator>
#include <mutex>
#include <optional>
#include <random>
#include <sstream>

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
  // A part records a job that cannot get its GL as failed, and goes on with the others.
  if (options.part) return;
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

// A run's jobs as the scheduler runs them: each executed into its directory of the run
// (suites/job_execution.h) and recorded there, a failure recorded beside it.
class RunJobs {
 public:
  RunJobs(const std::vector<PreparedJob>& jobs, const RunDirectory& dir, const RunOptions& options,
          ref::ReferenceStore& store)
      : jobs_(jobs), dir_(dir), options_(options), store_(store) {}

  // A technique job is timed `repeats` times, a reference job once.
  std::vector<ScheduledJob> schedule() const {
    std::vector<ScheduledJob> scheduled;
    for (const PreparedJob& job : jobs_)
      scheduled.push_back({job.job->id, job.technique ? job.job->settings.repeats : 1});
    return scheduled;
  }

  JobWork work() {
    JobWork work;
    work.first_run = [this](std::size_t index, const JobNote& note) {
      return firstRun(index, note);
    };
    work.repeat_run = [this](std::size_t index, const JobNote& note) {
      return repeatTechniqueJob(jobs_[index], environment(note));
    };
    work.record = [this](std::size_t index, const results::JobResult& result) {
      record(index, result);
    };
    work.record_failure = [this](std::size_t index, const std::string& error) {
      dir_.recordFailure(*jobs_[index].job, jobs_[index].hash, error);
    };
    return work;
  }

  // The GL implementation of the first technique job that ran, if any.
  std::optional<rt::gl::GlIdentity> gl() const { return gl_; }

 private:
  JobEnvironment environment(const JobNote& note) const {
    JobEnvironment env;
    env.store = &store_;
    env.gl.device = options_.gl_device;
    env.gl.debug = rt::gl::debugOutputByDefault();
    env.progress = options_.progress && options_.parallel_jobs == 1;
    env.note = note;
    return env;
  }

  results::JobResult firstRun(std::size_t index, const JobNote& note) {
    const PreparedJob& job = jobs_[index];
    rt::gl::GlIdentity gl;
    results::JobExecution execution = describeJobExecution();  // at the start: its queue wait
    const JobDirectory files = dir_.prepareJob(*job.job);
    results::JobResult result = executeJob(job, environment(note), files, &gl);
    if (job.technique) execution.gl_renderer = gl.renderer;
    result.execution = std::move(execution);
    if (job.technique) {
      std::lock_guard lock(gl_mutex_);
      if (!gl_) gl_ = gl;
    }
    return result;
  }

  void record(std::size_t index, const results::JobResult& result) {
    const Job& job = *jobs_[index].job;
    // The repeat of the median frame time stands for the job: its timings replace the first run's.
    if (!result.repeats.empty())
      image::writeTextFile(dir_.jobDirectory(job).timings_json,
                           results::passTimingsToJson(*result.timings).dump(2) + "\n");
    dir_.recordJob(job, result);
  }

  const std::vector<PreparedJob>& jobs_;
  const RunDirectory& dir_;
  const RunOptions& options_;
  ref::ReferenceStore& store_;
  std::mutex gl_mutex_;
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

Shard parseShard(const std::string& text) {
  Shard shard;
  char slash = 0, rest = 0;
  std::istringstream in(text);
  if (!(in >> shard.index >> slash >> shard.count) || slash != '/' || (in >> rest) ||
      shard.count < 1 || shard.index < 1 || shard.index > shard.count)
    throw InputError(fmt::format(
        "--shard '{}' is not a slice; give i/n with 1 <= i <= n (e.g. --shard 2/4)", text));
  return shard;
}

std::vector<Job> selectRunJobs(const Suite& suite, const RunOptions& options) {
  std::vector<Job> selected = selectJobs(suite, options.only);
  if (!options.job.empty()) {
    for (Job& job : selected)
      if (job.id == options.job) return {std::move(job)};
    throw InputError(
        fmt::format("suite '{}' has no job '{}'; list its jobs with `gibench run {} "
                    "--list`",
                    suite.name, options.job, suite.file.string()));
  }
  std::vector<Job> slice;
  for (std::size_t k = 0; k < selected.size(); ++k)
    if (int(k % std::size_t(options.shard.count)) == options.shard.index - 1)
      slice.push_back(std::move(selected[k]));
  return slice;
}

namespace {

// The run's state for a fresh run directory.
RunState freshState(const Suite& suite, const RunOptions& options, const results::RunInfo& info) {
  RunState state;
  state.run_id = info.id;
  state.suite = suite.name;
  state.suite_file = fs::absolute(suite.file);
  state.only = options.only;
  state.started = info.started;
  return state;
}

// After the jobs: the run's description, results.json, the CSV and, when every job has its
// result, the history row.
RunOutcome assembleRun(const Suite& suite, const RunOptions& options, const RunDirectory& dir,
                       std::vector<results::JobResult> jobs, std::optional<rt::gl::GlIdentity> gl,
                       const ConditionsSample& before, RunOutcome outcome) {
  results::RunInfo info = describeEnvironment();
  info.id = dir.runId();
  info.started = dir.started();
  results::RunResults& run = outcome.results;
  run.jobs = std::move(jobs);
  for (std::size_t i = 0; !gl && i < run.jobs.size(); ++i)
    if (!run.jobs[i].failed()) gl = glOfRecordedJob(dir.path(), run.jobs[i]);
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
  info.complete = dir.state().only.empty();
  info.finished = utcTimestamp();
  info.conditions = conditionsBetween(before, sampleConditions());
  run.run = info;
  run.tolerances = suite.tolerances;
  for (const results::PaperValue& value : suite.paper)
    if (run.findJob(value.job)) run.paper.push_back(value);
  run.charts = suite.charts;
  run.figures = suite.figures;
  run.primary_metric = primaryMetric(run.jobs);
  outcome.failed = std::size_t(
      std::count_if(run.jobs.begin(), run.jobs.end(), [](const auto& j) { return j.failed(); }));

  outcome.run_dir = dir.path();
  outcome.results_file = dir.path() / "results.json";
  results::writeResultsFile(outcome.results_file, run);
  image::writeTextFile(dir.path() / "results.csv", results::resultsCsv(run));
  // A run with failed jobs is not history: its gaps would read as changes in the trends.
  if (!options.history_db.empty() && outcome.failed == 0)
    outcome.history_row = results::HistoryDatabase::open(options.history_db).append(run);
  return outcome;
}

}  // namespace

RunDirectory openRunDirectory(const Suite& suite, const RunOptions& options) {
  results::RunInfo info = describeEnvironment();
  info.started = utcTimestamp();
  info.id = newRunId(suite.name, info);
  return RunDirectory::open(options.out_dir, freshState(suite, options, info));
}

RunOutcome runSuite(const Suite& suite, const RunOptions& options) {
  if (options.parallel_jobs < 1)
    throw InputError(fmt::format("--jobs {} runs nothing; give 1 or more", options.parallel_jobs));
  const std::vector<Job> jobs = selectRunJobs(suite, options);
  std::vector<PreparedJob> prepared;
  for (const Job& job : jobs) prepared.push_back(prepareJob(job));
  checkResources(options, prepared);

  const ConditionsSample before = sampleConditions();
  const RunDirectory dir = openRunDirectory(suite, options);
  std::string what = fmt::format("{} jobs", jobs.size());
  if (!options.shard.whole())
    what = fmt::format("shard {}/{}: {}", options.shard.index, options.shard.count, what);
  fmt::print(options.log, "{} run {} of suite '{}' ({}) in {}\n",
             dir.resumed() ? (options.part ? "joining" : "resuming") : "starting", dir.runId(),
             suite.name, what, dir.path().string());
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
  RunJobs run_jobs(prepared, dir, options, store);
  JobScheduler scheduler(
      run_jobs.schedule(), run_jobs.work(),
      {.parallel_jobs = options.parallel_jobs, .part = options.part, .log = options.log});
  scheduler.run(pending, results);

  if (options.part) {
    outcome.failed = scheduler.failed();
    outcome.run_dir = dir.path();
    for (std::optional<results::JobResult>& result : results)
      if (result) outcome.results.jobs.push_back(std::move(*result));
    return outcome;
  }
  std::vector<results::JobResult> finished;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    if (results[i]) {
      finished.push_back(std::move(*results[i]));
      continue;
    }
    results::JobResult failed = describeJob(prepared[i]);
    failed.failure = dir.failure(jobs[i], prepared[i].hash).value_or("no result");
    finished.push_back(std::move(failed));
  }
  return assembleRun(suite, options, dir, std::move(finished), run_jobs.gl(), before,
                     std::move(outcome));
}

void obtainReferencesOfJob(const Suite& suite, const RunOptions& options) {
  const std::vector<Job> jobs = selectRunJobs(suite, options);
  const PreparedJob prepared = prepareJob(jobs.front());
  ref::ReferenceStore store(options.store_root);
  JobEnvironment env;
  env.store = &store;
  env.progress = options.progress;
  env.note = [&](const std::string& note) {
    fmt::print(options.log, "{}: {}\n", jobs.front().id, note);
    std::fflush(options.log);
  };
  obtainJobReferences(prepared, env);
}

RunOutcome mergeRuns(const std::vector<fs::path>& dirs, const RunOptions& options) {
  if (dirs.empty()) throw InputError("merge needs at least one run directory");
  const RunState state = RunDirectory::readState(dirs.front());
  if (state.suite_file.empty())
    throw InputError(
        fmt::format("'{}' was started by a gibench that did not record its suite "
                    "file; run the suite again to merge it",
                    dirs.front().string()));
  for (const fs::path& other : dirs) {
    const RunState theirs = RunDirectory::readState(other);
    if (theirs.suite != state.suite)
      throw InputError(
          fmt::format("'{}' holds a run of suite '{}', '{}' one of '{}'; merge runs "
                      "of one suite",
                      dirs.front().string(), state.suite, other.string(), theirs.suite));
  }
  const Suite suite = loadSuiteFile(state.suite_file);
  RunOptions merged_options = options;
  merged_options.only = state.only;
  const std::vector<Job> jobs = selectJobs(suite, state.only);
  std::vector<PreparedJob> prepared;
  for (const Job& job : jobs) prepared.push_back(prepareJob(job));
  const ConditionsSample before = sampleConditions();
  const fs::path out = options.out_dir.empty() ? dirs.front() : options.out_dir;
  const RunDirectory dir = RunDirectory::open(out, state);

  // The other runs, opened once (their state files read once, not once per job).
  std::vector<RunDirectory> others;
  for (const fs::path& other : dirs)
    if (!fs::equivalent(other, out)) others.push_back(RunDirectory::open(other, state));

  RunOutcome outcome;
  std::vector<results::JobResult> results;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    std::optional<results::JobResult> result = dir.finishedJob(jobs[i], prepared[i].hash);
    // Gather the job from the first other run that finished it (a shard on another machine).
    for (const RunDirectory& theirs : others) {
      if (result) break;
      if (!theirs.finishedJob(jobs[i], prepared[i].hash)) continue;
      const fs::path target = dir.prepareJob(jobs[i]).dir;
      fs::copy(theirs.jobDirectory(jobs[i]).dir, target, fs::copy_options::recursive);
      result = dir.finishedJob(jobs[i], prepared[i].hash);
      // The reference's viewer data lives outside the job's folder (one file per reference).
      if (result && !result->outputs.reference_viewer_data.empty()) {
        const fs::path shared = result->outputs.reference_viewer_data;
        std::error_code ec;
        if (!fs::exists(out / shared, ec) && fs::is_regular_file(theirs.path() / shared, ec)) {
          fs::create_directories((out / shared).parent_path());
          fs::copy_file(theirs.path() / shared, out / shared);
        }
      }
    }
    if (!result) {
      result = describeJob(prepared[i]);
      std::optional<std::string> failure = dir.failure(jobs[i], prepared[i].hash);
      for (std::size_t d = 0; !failure && d < others.size(); ++d)
        failure = others[d].failure(jobs[i], prepared[i].hash);
      result->failure = failure.value_or(
          "no result: its task did not finish (cancelled, pre-empted or crashed); run the "
          "part again (`--resume`) to complete it");
      if (const std::optional<fs::path> log =
              options.log_of ? options.log_of(out, jobs[i].id) : std::nullopt)
        result->outputs.log = log->lexically_relative(out).generic_string();
    }
    results.push_back(std::move(*result));
  }
  outcome.skipped = jobs.size();
  return assembleRun(suite, merged_options, dir, std::move(results), std::nullopt, before,
                     std::move(outcome));
}

}  // namespace gib::suites
