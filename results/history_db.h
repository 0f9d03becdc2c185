// The history database: one SQLite file to which every run is appended, so that trends and
// regressions can be followed across commits. Queryable by commit, date, suite, scene, technique
// and metric (`gibench history`), and the source of the report's trend charts and of run ids for
// `gibench diff`.
#pragma once

#include "results/results.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gib::results {

struct RunSummary {
  std::int64_t row = 0;  // the database's run number (what `gibench diff 12 13` takes)
  std::string id;        // RunInfo::id
  std::string suite;
  std::string started;
  std::string git_commit;
  bool git_dirty = false;
  std::string host;
  std::string gl_renderer;
  std::size_t jobs = 0;
};

struct HistoryFilter {
  std::string suite;      // exact; empty: any
  std::string commit;     // prefix of the git commit; empty: any
  std::string since;      // ISO 8601 date or date-time, inclusive; empty: no bound
  std::string until;      // inclusive
  std::string scene;      // exact job scene; empty: any
  std::string technique;  // exact; empty: any
  std::string job;        // exact job id; empty: any
  std::string metric;     // metric value name; "frame_ms" for the median frame time
  std::size_t limit = 0;  // newest first; 0: no limit
};

struct MetricPoint {
  RunSummary run;
  std::string job;
  std::string scene, technique;
  std::string metric;
  double value = 0;
};

class HistoryDatabase {
 public:
  // Opens or creates the file (and its directory). Throws gib::InputError when it cannot be
  // opened or is not a gibench history database (or one of a newer schema).
  static HistoryDatabase open(const std::filesystem::path& path);
  HistoryDatabase(HistoryDatabase&&) noexcept;
  HistoryDatabase& operator=(HistoryDatabase&&) noexcept;
  ~HistoryDatabase();

  // Appends the run (replacing an earlier append of the same run id: re-running `gibench report`
  // does not duplicate it). Returns its row number.
  std::int64_t append(const RunResults& results);

  // A run by row number or by RunInfo::id; nullopt when absent.
  std::optional<RunResults> run(std::int64_t row) const;
  std::optional<RunResults> run(const std::string& id) const;

  // Runs matching the filter's suite, commit and date bounds (and, when it names a scene,
  // technique or job, having one job that matches them all), newest first. A date bound is a
  // UTC date or date-time prefix ("2026-11-22", "2026-11-22T10", "2026-11-22T10:04:05Z"); else
  // gib::InputError.
  std::vector<RunSummary> runs(const HistoryFilter& filter) const;
  // Values of filter.metric for the matching jobs, newest run first; filter.limit counts runs.
  // NaN values are stored as NULL and read back as NaN.
  std::vector<MetricPoint> values(const HistoryFilter& filter) const;

  // The newest run of `suite` started before `started` (for colouring the report), and the
  // last `count` runs of the suite up to and including the given one, oldest first (trends).
  std::optional<RunResults> previousRun(const std::string& suite, const std::string& started) const;
  std::vector<RunResults> recentRuns(const std::string& suite, const std::string& up_to_started,
                                     std::size_t count) const;

  // Every reference store key some recorded run used (what `gibench store gc` keeps).
  std::set<std::string> referenceKeys() const;

 private:
  struct Impl;
  explicit HistoryDatabase(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace gib::results
