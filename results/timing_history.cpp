#include "results/timing_history.h"

#include <algorithm>

namespace gib::results {

namespace {

bool sameTimingSetup(const metrics::PassTimings& a, const metrics::PassTimings& b) {
  return a.clock == b.clock && a.measured_frames == b.measured_frames &&
         a.warmup_frames == b.warmup_frames;
}

}  // namespace

bool comparableTiming(const RunInfo& run, const JobResult& job, const RunInfo& reference_run,
                      const JobResult& reference) {
  if (!job.timings || !reference.timings) return false;
  return run.host == reference_run.host && run.gl_renderer == reference_run.gl_renderer &&
         run.build_type == reference_run.build_type && job.id == reference.id &&
         job.scene_hash == reference.scene_hash && job.technique == reference.technique &&
         job.parameters == reference.parameters && job.width == reference.width &&
         job.height == reference.height && job.iterations == reference.iterations &&
         job.repeats.size() == reference.repeats.size() &&
         sameTimingSetup(*job.timings, *reference.timings);
}

TimingHistory timingHistoryOf(const std::vector<RunResults>& runs, const RunResults& base,
                              const RunResults& next) {
  const std::string latest = std::max(base.run.started, next.run.started);
  std::vector<const RunResults*> ordered;
  for (const RunResults& run : runs)
    if (run.run.id != base.run.id && run.run.id != next.run.id && run.run.started <= latest)
      ordered.push_back(&run);
  std::sort(ordered.begin(), ordered.end(), [](const RunResults* a, const RunResults* b) {
    return a->run.started < b->run.started;
  });
  TimingHistory history;
  for (const JobResult& job : next.jobs) {
    if (!job.timings) continue;
    std::vector<double>& medians = history[job.id];
    for (const RunResults* run : ordered)
      if (const JobResult* earlier = run->findJob(job.id);
          earlier && comparableTiming(run->run, *earlier, next.run, job))
        if (const std::optional<double> median = earlier->runMedianMs()) medians.push_back(*median);
  }
  return history;
}

TimingHistory loadTimingHistory(const HistoryDatabase& db, const RunResults& base,
                                const RunResults& next, std::size_t max_runs) {
  const std::string latest = std::max(base.run.started, next.run.started);
  // Two more than wanted: the compared runs themselves may be among them.
  return timingHistoryOf(db.recentRuns(next.run.suite, latest, max_runs + 2), base, next);
}

}  // namespace gib::results
