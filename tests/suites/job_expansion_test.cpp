#include "suites/job_expansion.h"

#include "suites/suite_file.h"
#include "support/temp_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>

namespace gib::suites {
namespace {

using ::testing::ElementsAre;
using ::testing::Pair;

class JobExpansionTest : public ::testing::Test {
 protected:
  std::vector<Job> expand(const std::string& text) const {
    const std::filesystem::path path = dir_ / "suite.toml";
    std::ofstream(path) << text;
    return expandSuite(loadSuiteFile(path));
  }

  static std::vector<std::string> ids(const std::vector<Job>& jobs) {
    std::vector<std::string> result;
    for (const Job& job : jobs) result.push_back(job.id);
    return result;
  }

  test::TempDir dir_;
};

TEST_F(JobExpansionTest, CartesianProductWithTheLastKeyFastest) {
  // Keys in file order (toml++ would sort light_samples first).
  const std::vector<Job> jobs = expand(R"(name = "order"
[[case]]
scene = "cornell"
technique = "direct"
set = { shadow = ["hard", "pcf", "vsm"], light_samples = [1, 4] }
)");
  EXPECT_THAT(ids(jobs), ElementsAre("cornell-direct/shadow=hard,light_samples=1",
                                     "cornell-direct/shadow=hard,light_samples=4",
                                     "cornell-direct/shadow=pcf,light_samples=1",
                                     "cornell-direct/shadow=pcf,light_samples=4",
                                     "cornell-direct/shadow=vsm,light_samples=1",
                                     "cornell-direct/shadow=vsm,light_samples=4"));
  EXPECT_THAT(jobs[3].technique_parameters,
              ElementsAre(Pair("shadow", "pcf"), Pair("light_samples", "4")));
  EXPECT_THAT(assignmentStrings(jobs[3].technique_parameters),
              ElementsAre("shadow=pcf", "light_samples=4"));
  EXPECT_EQ(jobs[3].slug, "cornell-direct__shadow-pcf__light_samples-4");
}

TEST_F(JobExpansionTest, CasesInFileOrderWithTheirSettings) {
  const std::vector<Job> jobs = expand(R"(name = "cases"
[defaults]
width = 40
height = 30
metrics = ["mse"]
frames = 3
warmup = 0
[defaults.reference]
spp = 64
[[case]]
scene = "furnace"
technique = "reference"
checkpoints = [2, 8]
[[case]]
name = "box"
scene = "cornell"
technique = "direct"
reference = { max_bounces = 3, seed = 5 }
)");
  ASSERT_EQ(jobs.size(), 2u);
  const Job& reference = jobs[0];
  EXPECT_EQ(reference.suite, "cases");
  EXPECT_EQ(reference.case_name, "furnace-reference");
  EXPECT_EQ(reference.id, "furnace-reference");
  EXPECT_EQ(reference.slug, "furnace-reference");
  EXPECT_TRUE(reference.isReference());
  EXPECT_EQ(reference.scene.nameOrPath(), "furnace");
  EXPECT_THAT(reference.settings.checkpoints, ElementsAre(2, 8));
  EXPECT_EQ(reference.settings.reference.spp, 64);

  const Job& direct = jobs[1];
  EXPECT_EQ(direct.id, "box");
  EXPECT_FALSE(direct.isReference());
  EXPECT_EQ(direct.technique, "direct");
  EXPECT_EQ(direct.settings.width, 40);
  EXPECT_EQ(direct.settings.height, 30);
  EXPECT_EQ(direct.settings.frames, 3);
  EXPECT_EQ(direct.settings.warmup, 0);
  EXPECT_THAT(direct.settings.metrics, ElementsAre("mse"));
  EXPECT_EQ(direct.settings.reference.spp, 64);
  EXPECT_EQ(direct.settings.reference.seed, 5u);
  EXPECT_EQ(direct.settings.reference.max_bounces, 3);
  EXPECT_FALSE(direct.settings.reference.min_bounces.has_value());
  EXPECT_TRUE(direct.technique_parameters.empty());
  EXPECT_TRUE(direct.settings.checkpoints.empty());
}

TEST_F(JobExpansionTest, FixedValuesAreAssignedButNotInTheId) {
  const std::vector<Job> jobs = expand(R"(name = "fixed"
[[case]]
scene = "cornell"
technique = "direct"
set = { shadow_map_size = 256, shadow = ["pcf"], pcf_radius = 1 }
)");
  ASSERT_EQ(jobs.size(), 1u);
  EXPECT_EQ(jobs[0].id, "cornell-direct/shadow=pcf");  // a one-value sweep is still a sweep
  EXPECT_THAT(
      jobs[0].technique_parameters,
      ElementsAre(Pair("shadow_map_size", "256"), Pair("shadow", "pcf"), Pair("pcf_radius", "1")));
}

TEST_F(JobExpansionTest, IdsDoNotDependOnHowNumbersAreWritten) {
  const std::vector<Job> a = expand(R"(name = "a"
[[case]]
scene = "cornell"
technique = "direct"
set = { light_samples = [4, 16], normal_offset = [0.5, 2] }
)");
  const std::vector<Job> b = expand(R"(name = "a"
[[case]]
scene = "cornell"
technique = "direct"
set = { light_samples = [4.0, 1.6e1], normal_offset = ["0.50", 2.0] }
)");
  EXPECT_EQ(ids(a), ids(b));
  EXPECT_THAT(ids(a), ElementsAre("cornell-direct/light_samples=4,normal_offset=0.5",
                                  "cornell-direct/light_samples=4,normal_offset=2",
                                  "cornell-direct/light_samples=16,normal_offset=0.5",
                                  "cornell-direct/light_samples=16,normal_offset=2"));
}

TEST_F(JobExpansionTest, SceneSweepsComeFirstAndAreNamedAsScene) {
  const std::vector<Job> jobs = expand(R"(name = "scenes"
[[case]]
scene = "chamber"
scene_set = { light_target = [[-1, 0, 5], [1, 0, 5]], detail = 2 }
technique = "direct"
set = { shadow = ["hard", "vsm"] }
)");
  EXPECT_THAT(ids(jobs), ElementsAre("chamber-direct/scene.light_target=-1,0,5,shadow=hard",
                                     "chamber-direct/scene.light_target=-1,0,5,shadow=vsm",
                                     "chamber-direct/scene.light_target=1,0,5,shadow=hard",
                                     "chamber-direct/scene.light_target=1,0,5,shadow=vsm"));
  EXPECT_THAT(jobs[0].scene_parameters,
              ElementsAre(Pair("light_target", "-1,0,5"), Pair("detail", "2")));
  EXPECT_THAT(assignmentStrings(jobs[0].scene_parameters),
              ElementsAre("light_target=-1,0,5", "detail=2"));
  EXPECT_EQ(jobs[0].slug, "chamber-direct__scene.light_target--1_0_5__shadow-hard");
}

TEST_F(JobExpansionTest, SlugsAreSafeUniqueAndShort) {
  std::string values;
  for (int i = 1; i <= 40; ++i) {
    if (i > 1) values += ", ";
    values += std::to_string(i);
  }
  const std::vector<Job> jobs = expand(R"(name = "slugs"
[[case]]
name = "a-very-long-case-name-that-takes-up-a-good-part-of-the-slug-all-by-itself-really"
scene = "chamber"
scene_set = { light_position = [[0.125, 6.5, 3.25], [-0.125, 6.5, 3.25]], light_target = ["1,0,5"] }
technique = "direct"
set = { shadow = ["hard", "pcf", "vsm"], light_samples = [)" +
                                       values + R"(], vsm_min_variance = [1e-6, 2e-6] }
)");
  ASSERT_EQ(jobs.size(), 2u * 3 * 40 * 2);
  std::set<std::string> slugs;
  for (const Job& job : jobs) {
    EXPECT_LE(job.slug.size(), 120u) << job.slug;
    EXPECT_EQ(job.slug.find_first_not_of(
                  "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-"),
              std::string::npos)
        << job.slug;
    slugs.insert(job.slug);
  }
  EXPECT_EQ(slugs.size(), jobs.size());
  std::set<std::string> unique_ids;
  for (const Job& job : jobs) unique_ids.insert(job.id);
  EXPECT_EQ(unique_ids.size(), jobs.size());
}

TEST_F(JobExpansionTest, ExpansionIsDeterministic) {
  const std::string text = R"(name = "again"
[[case]]
scene = "cornell"
technique = "direct"
set = { shadow = ["vsm", "hard"], light_samples = [16, 1] }
[[case]]
scene = "cloud"
scene_set = { particles = [64, 16] }
technique = "reference"
)";
  const std::vector<Job> first = expand(text);
  EXPECT_EQ(ids(first), ids(expand(text)));
  // Values keep the order written, not a sorted one.
  EXPECT_THAT(ids(first), ElementsAre("cornell-direct/shadow=vsm,light_samples=16",
                                      "cornell-direct/shadow=vsm,light_samples=1",
                                      "cornell-direct/shadow=hard,light_samples=16",
                                      "cornell-direct/shadow=hard,light_samples=1",
                                      "cloud-reference/scene.particles=64",
                                      "cloud-reference/scene.particles=16"));
}

}  // namespace
}  // namespace gib::suites
