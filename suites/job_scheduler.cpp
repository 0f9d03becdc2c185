#include "suites/job_scheduler.h"

#include "common/environment_error.h"
#include "suites/primary_metric.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>

namespace gib::suites {

namespace {

// A job this machine could not run (gib::EnvironmentError: a GL driver that rejects a shader, GPU
// memory that runs out) says nothing about the other jobs: it is recorded as failed and the run
// goes on. Bad input and bugs stop the run.
bool isEnvironmentFailure(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const EnvironmentError&) {
    return true;
  } catch (...) {
    return false;
  }
}

std::string messageOf(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "unknown error";
  }
}

std::string summaryOf(const results::JobResult& job) {
  std::string text = fmt::format("done in {:.1f} s", job.seconds);
  const std::string metric = primaryMetric(job.metrics);
  if (const std::optional<double> value = job.metric(metric))
    text += fmt::format(", {} {:.4g}", metric, *value);
  if (const std::optional<double> frame = job.frameMedianMs())
    text += fmt::format(", frame {:.2f} ms", *frame);
  return text;
}

}  // namespace

JobScheduler::JobScheduler(std::vector<ScheduledJob> jobs, JobWork work, SchedulerOptions options)
    : jobs_(std::move(jobs)), work_(std::move(work)), options_(options), states_(jobs_.size()) {}

void JobScheduler::run(const std::vector<std::size_t>& pending,
                       std::vector<std::optional<results::JobResult>>& results) {
  results_ = &results;
  std::vector<Task> tasks;
  int most = 1;
  for (std::size_t index : pending) {
    const int repeats = jobs_[index].repeats;
    states_[index].timings.resize(std::size_t(repeats));
    states_[index].remaining = repeats;
    most = std::max(most, repeats);
  }
  for (int repeat = 0; repeat < most; ++repeat)
    for (std::size_t index : pending)
      if (repeat < jobs_[index].repeats) tasks.push_back({index, repeat});

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
        if (options_.part || isEnvironmentFailure(std::current_exception())) {
          recordFailure(tasks[k].job, std::current_exception());
          continue;
        }
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

void JobScheduler::log(const std::string& line) {
  std::lock_guard lock(log_mutex_);
  fmt::print(options_.log, "{}\n", line);
  std::fflush(options_.log);
}

void JobScheduler::runTask(const Task& task) {
  const int repeats = jobs_[task.job].repeats;
  std::string prefix = fmt::format("[{}/{}] {}", task.job + 1, jobs_.size(), jobs_[task.job].id);
  if (repeats > 1) prefix += fmt::format(" (run {}/{})", task.repeat + 1, repeats);
  JobState& state = states_[task.job];
  {
    std::lock_guard lock(state_mutex_);
    if (state.failed) return;
  }
  const JobNote note = [this, prefix](const std::string& line) { log(prefix + ": " + line); };
  if (task.repeat == 0) {
    {
      std::lock_guard lock(state_mutex_);
      state.before = sampleConditions();
    }
    log(prefix + ": started");
    results::JobResult result = work_.first_run(task.job, note);
    if (repeats > 1 && !result.timings)
      throw std::logic_error(
          fmt::format("job {} is timed {} times, but its first run has no timings",
                      jobs_[task.job].id, repeats));
    std::lock_guard lock(state_mutex_);
    if (result.timings) state.timings[0] = result.timings;
    state.result = std::move(result);
  } else {
    log(prefix + ": timing again");
    metrics::PassTimings timings = work_.repeat_run(task.job, note);
    std::lock_guard lock(state_mutex_);
    state.timings[std::size_t(task.repeat)] = std::move(timings);
  }
  bool last = false;
  {
    std::lock_guard lock(state_mutex_);
    last = --state.remaining == 0 && !state.failed;
  }
  if (last) finish(task.job);
}

// Recorded once (a resume runs the job again); its remaining tasks are skipped.
void JobScheduler::recordFailure(std::size_t index, const std::exception_ptr& error) {
  const std::string message = messageOf(error);
  {
    std::lock_guard lock(state_mutex_);
    if (states_[index].failed) return;
    states_[index].failed = true;
    ++failed_;
  }
  work_.record_failure(index, message);
  log(fmt::format("[{}/{}] {}: failed: {}", index + 1, jobs_.size(), jobs_[index].id, message));
}

// Every task of the job has ended: its repeats and conditions join the first run's result, which
// is recorded and logged.
void JobScheduler::finish(std::size_t index) {
  JobState& state = states_[index];
  results::JobResult result = std::move(*state.result);
  if (state.timings.size() > 1) {
    std::vector<metrics::PassTimings> repeats;
    for (std::optional<metrics::PassTimings>& timings : state.timings)
      repeats.push_back(std::move(*timings));
    recordRepeats(result, std::move(repeats));
  }
  result.conditions = conditionsBetween(state.before, sampleConditions());
  work_.record(index, result);
  log(fmt::format("[{}/{}] {}: {}", index + 1, jobs_.size(), jobs_[index].id, summaryOf(result)));
  std::lock_guard lock(state_mutex_);
  (*results_)[index] = std::move(result);
}

void recordRepeats(results::JobResult& result, std::vector<metrics::PassTimings> repeats) {
  if (repeats.size() < 2) return;
  std::vector<std::size_t> order(repeats.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return repeats[a].root().reported.median < repeats[b].root().reported.median;
  });
  result.timings = repeats[order[(order.size() - 1) / 2]];
  result.repeats = std::move(repeats);
}

}  // namespace gib::suites
