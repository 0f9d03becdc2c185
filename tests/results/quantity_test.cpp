#include "results/quantity.h"

#include "support/synthetic_results.h"

#include <gtest/gtest.h>

namespace gib::results {
namespace {

TEST(Quantity, NamesEveryKindOfNumberOfAJob) {
  const JobResult job = test::richResults().jobs[0];
  EXPECT_EQ(quantityValue(job, "relmse"), job.metric("relmse"));
  EXPECT_EQ(quantityValue(job, "full:relmse"), 0.25);
  EXPECT_EQ(quantityValue(job, "full:ssim"), 0.91);
  EXPECT_EQ(quantityValue(job, "frame"), job.frameMedianMs());
  EXPECT_EQ(quantityValue(job, "iteration"), 2.25);  // median of 1.5, 2, 2.5, 3
  EXPECT_EQ(quantityValue(job, "iterations"), 4.0);
  EXPECT_EQ(quantityValue(job, "statistic:vertices"), 1536.0);
  EXPECT_EQ(quantityValue(job, "parameter:light_samples"), 16.0);
  // A parameter that is not a number has no value but names a series.
  EXPECT_EQ(quantityValue(job, "parameter:shadow"), std::nullopt);
  EXPECT_EQ(parameterText(job, "shadow"), "pcf");
  // Scene parameters, named as job ids name them.
  JobResult cloud = job;
  cloud.scene_parameters = {{"particles", "512"}, {"surface", "slab"}};
  EXPECT_EQ(quantityValue(cloud, "parameter:scene.particles"), 512.0);
  EXPECT_EQ(parameterText(cloud, "scene.surface"), "slab");
  EXPECT_EQ(parameterText(cloud, "scene.shadow"), std::nullopt);
  EXPECT_EQ(parameterText(cloud, "particles"), std::nullopt);
  // Sums: a paper's row that spans several of our passes.
  EXPECT_EQ(quantityValue(job, "frame + iteration"), *job.frameMedianMs() + 2.25);
  EXPECT_EQ(quantityValue(job, "iteration+statistic:vertices"), 2.25 + 1536);
  EXPECT_EQ(quantityValue(job, "frame + shadow maps"), std::nullopt);
  EXPECT_EQ(quantityValue(job, "scene"), std::nullopt);
  for (const char* absent : {"hdrflip_mean", "full:hdrflip_mean", "statistic:texels",
                             "parameter:grid", "iteration/update", "shadow maps"})
    EXPECT_EQ(quantityValue(job, absent), std::nullopt) << absent;
}

TEST(Quantity, ReferenceJobsHaveNoTimings) {
  const JobResult reference = test::richResults().jobs[1];
  EXPECT_EQ(quantityValue(reference, "frame"), std::nullopt);
  EXPECT_EQ(quantityValue(reference, "iteration"), std::nullopt);
  EXPECT_EQ(quantityValue(reference, "iterations"), std::nullopt);
}

TEST(Quantity, LabelsSayWhatTheAxisMeasures) {
  EXPECT_EQ(quantityLabel("full:relmse"), "relmse against the full reference");
  EXPECT_EQ(quantityLabel("iteration/update"), "ms per iteration (update)");
  EXPECT_EQ(quantityLabel("frame"), "ms per frame");
  EXPECT_EQ(quantityLabel("statistic:vertices"), "vertices");
  EXPECT_EQ(quantityLabel("relmse"), "relmse");
}

// What a suite checks against the technique's declared passes.
TEST(Quantity, PassesAreTheTermsThatAreNotMetricsCountsOrParameters) {
  EXPECT_EQ(quantityPasses("frame"), std::vector<std::string>{"frame"});
  EXPECT_EQ(quantityPasses("sh projection + frame/relight cube maps + relmse"),
            (std::vector<std::string>{"sh projection", "frame/relight cube maps"}));
  EXPECT_EQ(quantityPasses("iteration/update"), std::vector<std::string>{"iteration/update"});
  for (const char* none : {"relmse", "flip_mean", "energy_ratio", "full:ssim", "iterations",
                           "statistic:vertices", "parameter:atlas", "scene"})
    EXPECT_TRUE(quantityPasses(none).empty()) << none;
}

TEST(Quantity, SyntaxErrorsNameTheProblem) {
  for (const char* good : {"relmse", "full:relmse", "frame", "frame/shadow maps", "iteration",
                           "iteration/selection", "statistic:vertices", "parameter:atlas"})
    EXPECT_EQ(quantitySyntaxError(good), std::nullopt) << good;
  EXPECT_EQ(quantitySyntaxError(""), "is empty");
  EXPECT_EQ(quantitySyntaxError("parameter:"), "names no parameter after 'parameter:'");
  EXPECT_EQ(quantitySyntaxError("iteration/"), "has an empty pass name");
  EXPECT_EQ(quantitySyntaxError("frame + iteration/update"), std::nullopt);
  EXPECT_EQ(quantitySyntaxError("frame + "), "has a term that is empty");
  EXPECT_EQ(quantitySyntaxError("param:atlas"),
            "has an unknown prefix 'param:' (known: full:, statistic:, parameter:)");
}

}  // namespace
}  // namespace gib::results
