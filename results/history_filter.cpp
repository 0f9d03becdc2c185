#include "results/history_filter.h"

#include "common/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <regex>

namespace gib::results::detail {

namespace {

// Dates compare as text: runs record `started` as "2026-11-22T10:04:05Z", so a bound that is a
// prefix of that form (a day, an hour, a second) compares correctly. Other forms (time zones,
// "22/11/2026") would compare wrongly, so they are refused.
void checkDateBound(const std::string& value, const char* option) {
  static const std::regex iso(R"(\d{4}-\d{2}-\d{2}(T\d{2}(:\d{2}(:\d{2})?)?Z?)?)");
  if (!std::regex_match(value, iso))
    throw InputError(fmt::format(
        "{} '{}' is not a UTC date; give 2026-11-22 or 2026-11-22T10:04:05Z", option, value));
}

class ConditionBuilder {
 public:
  void add(const std::string& value, const char* sql) {
    if (value.empty()) return;
    condition_.where += condition_.where.empty() ? " WHERE " : " AND ";
    condition_.where += sql;
    condition_.parameters.push_back(value);
  }
  void addRunConditions(const HistoryFilter& filter) {
    add(filter.suite, "r.suite = ?");
    std::string commit = filter.commit;
    std::transform(commit.begin(), commit.end(), commit.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    add(commit, "instr(r.git_commit, ?) = 1");
    if (!filter.since.empty()) checkDateBound(filter.since, "--since");
    add(filter.since, "r.started >= ?");
    if (!filter.until.empty()) checkDateBound(filter.until, "--until");
    // Inclusive of everything the bound is a prefix of: '~' sorts after every character of a
    // date-time, so "2026-11-22~" keeps the whole day.
    add(filter.until.empty() ? "" : filter.until + "~", "r.started <= ?");
  }
  SqlCondition take() { return std::move(condition_); }

 private:
  SqlCondition condition_;
};

}  // namespace

SqlCondition runCondition(const HistoryFilter& filter) {
  ConditionBuilder builder;
  builder.addRunConditions(filter);
  // One EXISTS per job criterion would let different jobs satisfy each; one subquery with all.
  ConditionBuilder jobs;
  jobs.add(filter.scene, "j.scene = ?");
  jobs.add(filter.technique, "j.technique = ?");
  jobs.add(filter.job, "j.job = ?");
  SqlCondition job_condition = jobs.take();
  SqlCondition condition = builder.take();
  if (job_condition.where.empty()) return condition;
  const std::string exists =
      fmt::format("EXISTS (SELECT 1 FROM jobs j{} AND j.run = r.row)", job_condition.where);
  condition.where += (condition.where.empty() ? " WHERE " : " AND ") + exists;
  condition.parameters.insert(condition.parameters.end(), job_condition.parameters.begin(),
                              job_condition.parameters.end());
  return condition;
}

SqlCondition valueCondition(const HistoryFilter& filter) {
  ConditionBuilder builder;
  builder.add(filter.metric, "m.metric = ?");
  builder.add(filter.scene, "m.scene = ?");
  builder.add(filter.technique, "m.technique = ?");
  builder.add(filter.job, "m.job = ?");
  builder.addRunConditions(filter);
  return builder.take();
}

}  // namespace gib::results::detail
