#include "reports/report_context.h"

#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

namespace gib::reports {
namespace {

results::RunResults runOn(const std::string& suite, int day) {
  results::RunResults run = test::syntheticReportResults(suite + "-" + std::to_string(day));
  run.run.suite = suite;
  run.run.started = "2026-11-" + std::to_string(10 + day) + "T10:00:00Z";
  return run;
}

std::vector<std::string> ids(const std::vector<results::RunResults>& runs) {
  std::vector<std::string> out;
  for (const results::RunResults& run : runs) out.push_back(run.run.id);
  return out;
}

class ReportContextTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (int day = 1; day <= 3; ++day) db_.append(runOn("smoke", day));
    db_.append(runOn("nightly", 2));  // another suite: neither previous nor trend
  }
  test::TempDir dir_;
  results::HistoryDatabase db_ = results::HistoryDatabase::open(dir_ / "history.sqlite");
};

TEST_F(ReportContextTest, ARunNotYetRecordedIsComparedWithTheNewestEarlierRunOfItsSuite) {
  const results::RunResults next = runOn("smoke", 4);
  const ReportContext context = loadReportContext(db_, next, 3);
  ASSERT_TRUE(context.previous.has_value());
  EXPECT_EQ(context.previous->run.id, "smoke-3");
  // The report appends the run itself: two recorded runs make a trend of three.
  EXPECT_EQ(ids(context.history), (std::vector<std::string>{"smoke-2", "smoke-3"}));
}

TEST_F(ReportContextTest, ARecordedRunEndsItsOwnTrendAndIsNotItsOwnPrevious) {
  const ReportContext context = loadReportContext(db_, runOn("smoke", 3), 3);
  ASSERT_TRUE(context.previous.has_value());
  EXPECT_EQ(context.previous->run.id, "smoke-2");
  EXPECT_EQ(ids(context.history), (std::vector<std::string>{"smoke-1", "smoke-2", "smoke-3"}));
}

TEST_F(ReportContextTest, TheFirstRunOfASuiteHasNothingToCompareWith) {
  const ReportContext context = loadReportContext(db_, runOn("figures", 5), 20);
  EXPECT_FALSE(context.previous.has_value());
  EXPECT_TRUE(context.history.empty());
}

}  // namespace
}  // namespace gib::reports
