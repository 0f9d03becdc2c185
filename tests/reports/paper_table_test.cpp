// The paper table's tolerance column: a value with a tolerance shows whether ours reproduces it,
// in the report's verdict colours; a table of values without one has no such column.
#include "reports/paper_table.h"

#include "support/markup_check.h"
#include "support/synthetic_report_run.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace gib::reports {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(PaperTable, AToleranceColumnShowsWithinOrOutsideInTheVerdictColours) {
  results::RunResults results = test::syntheticReportResults();
  const results::JobResult& pcf = results.jobs[1];
  const results::JobResult& vsm = results.jobs[2];
  results.paper = {{pcf.id, "relmse", *pcf.metric("relmse") * 1.04, "", "Paper A", "", 0.05},
                   {vsm.id, "relmse", *vsm.metric("relmse") * 1.5, "", "Paper B", "", 0.05},
                   {vsm.id, "frame", 1.0, "ms", "Paper C", "other hardware"}};
  const std::string all = paperTable(results, nullptr);
  EXPECT_EQ(test::markupProblem(all), "");
  EXPECT_THAT(all, HasSubstr("<th>tolerance</th>"));
  EXPECT_THAT(all, HasSubstr("<span class=\"verdict-improved\">within ±5%</span>"));
  EXPECT_THAT(all, HasSubstr("<span class=\"verdict-regressed\">outside ±5%</span>"));
  EXPECT_EQ(test::countOccurrences(all, "±5%"), 2);  // the frame time has none

  // A job's page shows its own rows: the failed comparison is the vsm job's alone.
  EXPECT_THAT(paperTable(results, &pcf.id), Not(HasSubstr("outside")));
  EXPECT_THAT(paperTable(results, &vsm.id), HasSubstr("outside ±5%"));

  // A failed job's value is not judged again: its failure says enough.
  results.jobs[2].failure = "no result";
  EXPECT_THAT(paperTable(results, &vsm.id), HasSubstr("±5% (not judged: the job failed)"));
}

TEST(PaperTable, ValuesWithoutToleranceHaveNoToleranceColumn) {
  const results::RunResults results = test::syntheticReportResults();
  ASSERT_FALSE(results.paper.empty());
  const std::string all = paperTable(results, nullptr);
  EXPECT_THAT(all, Not(HasSubstr("tolerance")));
  EXPECT_THAT(all, HasSubstr(results.paper[0].source));
}

}  // namespace
}  // namespace gib::reports
