#include "support/run_equivalence.h"

namespace gib::test {

void expectSameDeterministicResults(const results::RunResults& local,
                                    const results::RunResults& assembled) {
  ASSERT_EQ(local.jobs.size(), assembled.jobs.size());
  EXPECT_EQ(local.run.suite, assembled.run.suite);
  EXPECT_EQ(local.run.suite_hash, assembled.run.suite_hash);
  EXPECT_EQ(local.primary_metric, assembled.primary_metric);
  EXPECT_EQ(local.paper, assembled.paper);
  EXPECT_EQ(local.charts, assembled.charts);
  EXPECT_EQ(local.figures, assembled.figures);
  for (std::size_t i = 0; i < local.jobs.size(); ++i) {
    const results::JobResult& a = local.jobs[i];
    const results::JobResult& b = assembled.jobs[i];
    SCOPED_TRACE(a.id);
    EXPECT_EQ(a.id, b.id);
    EXPECT_FALSE(b.failed()) << b.failure;
    EXPECT_EQ(a.job_hash, b.job_hash);
    EXPECT_EQ(a.scene_hash, b.scene_hash);
    EXPECT_EQ(a.parameters, b.parameters);
    EXPECT_EQ(a.reference.key, b.reference.key);
    EXPECT_EQ(a.full_reference.has_value(), b.full_reference.has_value());
    if (a.full_reference && b.full_reference) {
      EXPECT_EQ(a.full_reference->key, b.full_reference->key);
    }
    // Renders are deterministic (references for any thread count, llvmpipe frames on one
    // machine), so the metrics agree exactly.
    EXPECT_EQ(a.metrics, b.metrics);
    EXPECT_EQ(a.metrics_full, b.metrics_full);
    ASSERT_EQ(a.convergence.has_value(), b.convergence.has_value());
    if (a.convergence) {
      ASSERT_EQ(a.convergence->points.size(), b.convergence->points.size());
      for (std::size_t k = 0; k < a.convergence->points.size(); ++k)
        EXPECT_EQ(a.convergence->points[k].metrics, b.convergence->points[k].metrics);
    }
    EXPECT_EQ(a.statistics, b.statistics);
  }
}

}  // namespace gib::test
