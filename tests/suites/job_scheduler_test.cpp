#include "suites/job_scheduler.h"

#include "common/environment_error.h"
#include "common/input_error.h"
#include "support/synthetic_timings.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace gib::suites {
namespace {

using ::testing::Contains;
using ::testing::ElementsAre;
using ::testing::IsEmpty;
using ::testing::Not;
using ::testing::Pair;

// A wait that the scheduler under test should end at once: this long means it never will, and
// the test fails instead of hanging.
constexpr std::chrono::seconds kDeadline{30};

// The scheduler's log, read back as lines.
class CapturedLog {
 public:
  CapturedLog() : file_(open_memstream(&buffer_, &size_)) {}
  ~CapturedLog() {
    std::fclose(file_);
    std::free(buffer_);
  }
  CapturedLog(const CapturedLog&) = delete;
  CapturedLog& operator=(const CapturedLog&) = delete;

  std::FILE* file() const { return file_; }
  std::vector<std::string> lines() {
    std::fflush(file_);
    std::istringstream in(std::string(buffer_, size_));
    std::vector<std::string> result;
    for (std::string line; std::getline(in, line);) result.push_back(line);
    return result;
  }

 private:
  char* buffer_ = nullptr;
  std::size_t size_ = 0;
  std::FILE* file_;
};

// Lets the tasks that reach it go on once `count` of them have; false when that takes until the
// deadline (fewer ran at once).
class Rendezvous {
 public:
  explicit Rendezvous(int count) : count_(count) {}
  bool arriveAndWait() {
    std::unique_lock lock(mutex_);
    if (++arrived_ >= count_) arrived_all_.notify_all();
    return arrived_all_.wait_for(lock, kDeadline, [&] { return arrived_ >= count_; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable arrived_all_;
  int count_;
  int arrived_ = 0;
};

// A signal one task gives and another waits for.
class Event {
 public:
  void set() {
    std::lock_guard lock(mutex_);
    set_ = true;
    changed_.notify_all();
  }
  bool wait() {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, kDeadline, [&] { return set_; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  bool set_ = false;
};

// Jobs that render nothing: each run is a call recorded in order and answered by the test's
// `first_run` and `repeat_run` (by default a result with the job's id and a 1 ms frame).
class FakeJobs {
 public:
  explicit FakeJobs(std::vector<ScheduledJob> jobs) : jobs_(std::move(jobs)) {}

  std::function<results::JobResult(std::size_t)> first_run = [this](std::size_t job) {
    return resultOf(job, 1.0);
  };
  std::function<double(std::size_t, int)> repeat_run = [](std::size_t, int) { return 1.0; };

  results::JobResult resultOf(std::size_t job, double frame_ms) const {
    results::JobResult result;
    result.id = jobs_[job].id;
    result.timings = test::frameTimings({frame_ms});
    return result;
  }

  JobScheduler scheduler(int parallel_jobs, bool part, std::FILE* log) {
    JobWork work;
    work.first_run = [this](std::size_t job, const JobNote&) {
      called("first " + jobs_[job].id);
      return first_run(job);
    };
    work.repeat_run = [this](std::size_t job, const JobNote&) {
      int repeat = 0;
      {
        std::lock_guard lock(mutex_);
        repeat = ++repeats_run_[job];
      }
      called("repeat " + jobs_[job].id);
      return test::frameTimings({repeat_run(job, repeat)});
    };
    work.record = [this](std::size_t job, const results::JobResult& result) {
      std::lock_guard lock(mutex_);
      recorded_.push_back(result.id);
      if (on_record) on_record(job);
    };
    work.record_failure = [this](std::size_t job, const std::string& error) {
      std::lock_guard lock(mutex_);
      failures_.emplace_back(jobs_[job].id, error);
    };
    return JobScheduler(jobs_, work, {.parallel_jobs = parallel_jobs, .part = part, .log = log});
  }

  std::function<void(std::size_t)> on_record;

  std::vector<std::string> calls() const { return calls_; }
  std::vector<std::string> recorded() const { return recorded_; }
  std::vector<std::pair<std::string, std::string>> failures() const { return failures_; }

 private:
  void called(const std::string& what) {
    std::lock_guard lock(mutex_);
    calls_.push_back(what);
  }

  std::vector<ScheduledJob> jobs_;
  std::mutex mutex_;
  std::vector<std::string> calls_, recorded_;
  std::vector<std::pair<std::string, std::string>> failures_;
  std::map<std::size_t, int> repeats_run_;
};

std::vector<ScheduledJob> jobsNamed(const std::vector<std::string>& ids) {
  std::vector<ScheduledJob> jobs;
  for (const std::string& id : ids) jobs.push_back({id, 1});
  return jobs;
}

std::vector<std::size_t> all(std::size_t count) {
  std::vector<std::size_t> indices(count);
  for (std::size_t i = 0; i < count; ++i) indices[i] = i;
  return indices;
}

std::vector<double> frameMedians(const results::JobResult& result) {
  std::vector<double> medians;
  for (const metrics::PassTimings& timings : result.repeats)
    medians.push_back(timings.root().reported.median);
  return medians;
}

TEST(JobScheduler, RunsNJobsAtOnceOnNThreadsAndNoMore) {
  const std::vector<ScheduledJob> jobs = jobsNamed({"a", "b", "c", "d", "e", "f"});
  for (int parallel : {1, 2, 3}) {
    SCOPED_TRACE(::testing::Message() << "--jobs " << parallel);
    FakeJobs fake(jobs);
    Rendezvous first_wave(parallel);
    std::atomic<int> inside{0}, most{0};
    std::atomic<bool> met{true};
    std::mutex threads_mutex;
    std::set<std::thread::id> threads;
    fake.first_run = [&](std::size_t job) {
      const int now = ++inside;
      int seen = most.load();
      while (seen < now && !most.compare_exchange_weak(seen, now)) {
      }
      {
        std::lock_guard lock(threads_mutex);
        threads.insert(std::this_thread::get_id());
      }
      // The first N tasks meet here: they run at the same time.
      if (!first_wave.arriveAndWait()) met = false;
      --inside;
      return fake.resultOf(job, 1.0);
    };
    CapturedLog log;
    std::vector<std::optional<results::JobResult>> results(jobs.size());
    fake.scheduler(parallel, false, log.file()).run(all(jobs.size()), results);
    EXPECT_TRUE(met) << "fewer than " << parallel << " jobs ran at once";
    EXPECT_EQ(most, parallel);
    EXPECT_EQ(threads.size(), std::size_t(parallel));
    EXPECT_EQ(fake.recorded().size(), jobs.size());
  }
}

TEST(JobScheduler, WithMoreJobsAtATimeThanTasksEveryTaskRunsAtOnce) {
  const std::vector<ScheduledJob> jobs = jobsNamed({"a", "b"});
  FakeJobs fake(jobs);
  Rendezvous both(2);
  std::set<std::thread::id> threads;
  std::mutex threads_mutex;
  fake.first_run = [&](std::size_t job) {
    {
      std::lock_guard lock(threads_mutex);
      threads.insert(std::this_thread::get_id());
    }
    EXPECT_TRUE(both.arriveAndWait());
    return fake.resultOf(job, 1.0);
  };
  CapturedLog log;
  std::vector<std::optional<results::JobResult>> results(jobs.size());
  fake.scheduler(8, false, log.file()).run(all(jobs.size()), results);
  EXPECT_EQ(threads.size(), 2u);
}

TEST(JobScheduler, AJobTheMachineCannotRunIsRecordedAsFailedAndTheOthersRun) {
  const std::vector<ScheduledJob> jobs = jobsNamed({"a", "b", "c"});
  FakeJobs fake(jobs);
  fake.first_run = [&](std::size_t job) {
    if (job == 1) throw EnvironmentError("technique 'direct': out of GPU memory");
    return fake.resultOf(job, 1.0);
  };
  CapturedLog log;
  std::vector<std::optional<results::JobResult>> results(jobs.size());
  JobScheduler scheduler = fake.scheduler(1, false, log.file());
  scheduler.run(all(jobs.size()), results);
  EXPECT_EQ(scheduler.failed(), 1u);
  EXPECT_THAT(fake.failures(), ElementsAre(Pair("b", "technique 'direct': out of GPU memory")));
  EXPECT_THAT(fake.recorded(), ElementsAre("a", "c"));
  EXPECT_TRUE(results[0] && results[2]);
  EXPECT_FALSE(results[1]);
  EXPECT_THAT(log.lines(), Contains("[2/3] b: failed: technique 'direct': out of GPU memory"));
}

TEST(JobScheduler, BadInputStopsTheRunAndHandsOutNoFurtherJob) {
  const std::vector<ScheduledJob> jobs = jobsNamed({"a", "b", "c"});
  FakeJobs fake(jobs);
  fake.first_run = [&](std::size_t job) {
    if (job == 1) throw InputError("scene 'nowhere.toml' does not exist");
    return fake.resultOf(job, 1.0);
  };
  CapturedLog log;
  std::vector<std::optional<results::JobResult>> results(jobs.size());
  JobScheduler scheduler = fake.scheduler(1, false, log.file());
  EXPECT_THROW(scheduler.run(all(jobs.size()), results), InputError);
  EXPECT_THAT(fake.calls(), ElementsAre("first a", "first b"));
  // The job finished before the failure keeps its result (the resume point); nothing is recorded
  // as failed: the run ends with the error instead.
  EXPECT_THAT(fake.recorded(), ElementsAre("a"));
  EXPECT_TRUE(results[0]);
  EXPECT_THAT(fake.failures(), IsEmpty());
  EXPECT_EQ(scheduler.failed(), 0u);
  for (const std::string& line : log.lines())
    EXPECT_THAT(line, Not(::testing::StartsWith("[3/3]")));
}

TEST(JobScheduler, AStoppingFailureWaitsForTheJobsStillRunning) {
  const std::vector<ScheduledJob> jobs = jobsNamed({"a", "b"});
  FakeJobs fake(jobs);
  Event b_fails;
  fake.first_run = [&](std::size_t job) {
    if (job == 1) {
      b_fails.set();
      throw std::runtime_error("a bug");
    }
    EXPECT_TRUE(b_fails.wait());  // `a` is still running when `b` throws
    return fake.resultOf(job, 1.0);
  };
  CapturedLog log;
  std::vector<std::optional<results::JobResult>> results(jobs.size());
  EXPECT_THROW(fake.scheduler(2, false, log.file()).run(all(jobs.size()), results),
               std::runtime_error);
  EXPECT_THAT(fake.recorded(), ElementsAre("a"));
  EXPECT_TRUE(results[0]);
}

TEST(JobScheduler, APartRecordsEveryFailureAndGoesOn) {
  const std::vector<ScheduledJob> jobs = jobsNamed({"a", "b", "c"});
  FakeJobs fake(jobs);
  fake.first_run = [&](std::size_t job) {
    if (job == 0) throw InputError("bad parameter");
    if (job == 1) throw std::runtime_error("a bug");
    return fake.resultOf(job, 1.0);
  };
  CapturedLog log;
  std::vector<std::optional<results::JobResult>> results(jobs.size());
  JobScheduler scheduler = fake.scheduler(1, true, log.file());
  scheduler.run(all(jobs.size()), results);
  EXPECT_EQ(scheduler.failed(), 2u);
  EXPECT_THAT(fake.failures(), ElementsAre(Pair("a", "bad parameter"), Pair("b", "a bug")));
  EXPECT_THAT(fake.recorded(), ElementsAre("c"));
  EXPECT_THAT(log.lines(), Contains("[1/3] a: failed: bad parameter"));
}

TEST(JobScheduler, AFailedJobsRemainingRunsAreSkippedAndItFailsOnce) {
  // `a` fails in its second of three runs, `b` in its first of two, `c` runs all of its two.
  const std::vector<ScheduledJob> jobs = {{"a", 3}, {"b", 2}, {"c", 2}};
  FakeJobs fake(jobs);
  fake.first_run = [&](std::size_t job) {
    if (job == 1) throw EnvironmentError("no GL context");
    return fake.resultOf(job, 1.0);
  };
  fake.repeat_run = [](std::size_t job, int) -> double {
    if (job == 0) throw EnvironmentError("out of GPU memory");
    return 1.0;
  };
  CapturedLog log;
  std::vector<std::optional<results::JobResult>> results(jobs.size());
  JobScheduler scheduler = fake.scheduler(1, false, log.file());
  scheduler.run(all(jobs.size()), results);
  EXPECT_THAT(fake.calls(), ElementsAre("first a", "first b", "first c", "repeat a", "repeat c"));
  EXPECT_THAT(fake.failures(),
              ElementsAre(Pair("b", "no GL context"), Pair("a", "out of GPU memory")));
  EXPECT_EQ(scheduler.failed(), 2u);
  EXPECT_THAT(fake.recorded(), ElementsAre("c"));
  EXPECT_FALSE(results[0]);
  EXPECT_FALSE(results[1]);
}

TEST(JobScheduler, RepeatsAreInterleavedAcrossJobsAndTheMedianRunStands) {
  const std::vector<ScheduledJob> jobs = {{"a", 3}, {"b", 1}, {"c", 2}};
  FakeJobs fake(jobs);
  // Frame medians: a's runs 9, 3, 5 ms; b's 7 ms; c's 4, 2 ms.
  fake.first_run = [&](std::size_t job) {
    return fake.resultOf(job, std::vector<double>{9, 7, 4}[job]);
  };
  fake.repeat_run = [](std::size_t job, int repeat) {
    return job == 0 ? std::vector<double>{3, 5}[std::size_t(repeat - 1)] : 2.0;
  };
  CapturedLog log;
  std::vector<std::optional<results::JobResult>> results(jobs.size());
  fake.scheduler(1, false, log.file()).run(all(jobs.size()), results);
  EXPECT_THAT(fake.calls(),
              ElementsAre("first a", "first b", "first c", "repeat a", "repeat c", "repeat a"));
  // A job is recorded when its last run ends.
  EXPECT_THAT(fake.recorded(), ElementsAre("b", "c", "a"));
  ASSERT_TRUE(results[0] && results[1] && results[2]);
  EXPECT_THAT(frameMedians(*results[0]), ElementsAre(9, 3, 5));
  EXPECT_EQ(results[0]->frameMedianMs(), 5);
  EXPECT_THAT(results[1]->repeats, IsEmpty());
  EXPECT_EQ(results[1]->frameMedianMs(), 7);
  EXPECT_THAT(frameMedians(*results[2]), ElementsAre(4, 2));
  EXPECT_EQ(results[2]->frameMedianMs(), 2);  // of an even count, the lower middle run
  const std::vector<std::string> lines = log.lines();
  EXPECT_THAT(lines, Contains("[1/3] a (run 1/3): started"));
  EXPECT_THAT(lines, Contains("[1/3] a (run 3/3): timing again"));
  EXPECT_THAT(lines, Contains("[2/3] b: started"));
}

TEST(JobScheduler, ResultsLandAtTheirJobsPlaceWhateverOrderTheyEndIn) {
  // Jobs 0 and 2 were finished by an earlier attempt; 1 ends after 3.
  const std::vector<ScheduledJob> jobs = jobsNamed({"j0", "j1", "j2", "j3"});
  FakeJobs fake(jobs);
  Event j3_recorded;
  fake.on_record = [&](std::size_t job) {
    if (job == 3) j3_recorded.set();
  };
  fake.first_run = [&](std::size_t job) {
    if (job == 1) {
      EXPECT_TRUE(j3_recorded.wait());
    }
    return fake.resultOf(job, 1.0);
  };
  std::vector<std::optional<results::JobResult>> results(jobs.size());
  results[0] = results[2] = fake.resultOf(0, 1.0);
  results[2]->id = "j2";
  CapturedLog log;
  fake.scheduler(2, false, log.file()).run({1, 3}, results);
  EXPECT_THAT(fake.recorded(), ElementsAre("j3", "j1"));
  ASSERT_TRUE(results[0] && results[1] && results[2] && results[3]);
  EXPECT_EQ(results[0]->id, "j0");
  EXPECT_EQ(results[1]->id, "j1");
  EXPECT_EQ(results[2]->id, "j2");
  EXPECT_EQ(results[3]->id, "j3");
  // Positions in the log count every job of the run.
  const std::vector<std::string> lines = log.lines();
  EXPECT_THAT(lines, Contains("[2/4] j1: started"));
  EXPECT_THAT(lines, Contains("[4/4] j3: started"));
}

TEST(JobScheduler, AJobsNotesAndItsEndAreLoggedUnderItsPrefix) {
  const std::vector<ScheduledJob> jobs = {{"cornell-direct", 2}};
  CapturedLog log;
  JobWork work;
  work.first_run = [](std::size_t, const JobNote& note) {
    note("reference full (16x16, 64 spp, pixel centres): in the store");
    results::JobResult result;
    result.id = "cornell-direct";
    result.seconds = 1.5;
    result.metrics = {{"mse", 0.25}, {"relmse", 0.0123}};
    result.timings = test::frameTimings({4.0});
    return result;
  };
  work.repeat_run = [](std::size_t, const JobNote& note) {
    note("direct: 2 warm-up + 8 measured frames at 16x16");
    return test::frameTimings({6.0});
  };
  work.record = [](std::size_t, const results::JobResult&) {};
  work.record_failure = [](std::size_t, const std::string&) {};
  std::vector<std::optional<results::JobResult>> results(1);
  JobScheduler(jobs, work, {.parallel_jobs = 1, .part = false, .log = log.file()})
      .run({0}, results);
  EXPECT_THAT(log.lines(),
              ElementsAre("[1/1] cornell-direct (run 1/2): started",
                          "[1/1] cornell-direct (run 1/2): reference full (16x16, 64 spp, pixel "
                          "centres): in the store",
                          "[1/1] cornell-direct (run 2/2): timing again",
                          "[1/1] cornell-direct (run 2/2): direct: 2 warm-up + 8 measured frames "
                          "at 16x16",
                          // The lower middle of 4 and 6 ms, and relMSE, the run's primary metric.
                          "[1/1] cornell-direct: done in 1.5 s, relmse 0.0123, frame 4.00 ms"));
}

TEST(JobScheduler, RepeatsOfAJobWithoutTimingsAreAMistakeOfTheCaller) {
  const std::vector<ScheduledJob> jobs = {{"cornell-reference", 2}};
  FakeJobs fake(jobs);
  fake.first_run = [&](std::size_t) {
    results::JobResult result;
    result.id = "cornell-reference";
    return result;
  };
  CapturedLog log;
  std::vector<std::optional<results::JobResult>> results(1);
  EXPECT_THROW(fake.scheduler(1, false, log.file()).run({0}, results), std::logic_error);
}

TEST(RecordRepeats, OneRunLeavesTheResultAsItIs) {
  results::JobResult result;
  result.timings = test::frameTimings({3.0});
  recordRepeats(result, {test::frameTimings({3.0})});
  EXPECT_THAT(result.repeats, IsEmpty());
  EXPECT_EQ(result.frameMedianMs(), 3.0);
}

}  // namespace
}  // namespace gib::suites
