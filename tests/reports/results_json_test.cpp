// results.json as the runner writes it and diff, history and report read it: an exact round
// trip, and a clear error naming the field for anything damaged, truncated or too new.
#include "reports/results_json.h"

#include "common/input_error.h"
#include "support/synthetic_results.h"
#include "support/temp_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;
using ::testing::HasSubstr;

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The message of the InputError `read` throws; fails the test when it does not throw one.
template <typename Read>
std::string inputErrorOf(Read&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(ResultsJson, RoundTripsEveryFieldThroughAFile) {
  test::TempDir dir;
  const RunResults results = test::richResults();
  ASSERT_TRUE(results.jobs[0].full_reference && results.jobs[0].convergence);
  ASSERT_FALSE(results.jobs[1].full_reference || results.jobs[1].convergence);
  writeResultsFile(dir / "results.json", results);
  EXPECT_EQ(readResultsFile(dir / "results.json"), results);
  // A run directory stands for its results.json.
  EXPECT_EQ(readResultsFile(dir.path()), results);
}

TEST(ResultsJson, FilesFromBeforeTheFigureFieldsStillRead) {
  // charts, iteration_timings, statistics and auxiliary_images came after version 1: a file
  // without them reads with their defaults (docs/results-schema.md, compatibility).
  RunResults results = test::richResults();
  nlohmann::ordered_json document = resultsToJson(results);
  document.erase("charts");
  for (auto& job : document["jobs"]) {
    job.erase("iteration_timings");
    job.erase("statistics");
    job.erase("auxiliary_images");
  }
  const RunResults back = resultsFromJson(document, "memory");
  EXPECT_TRUE(back.charts.empty());
  EXPECT_TRUE(back.jobs[0].iteration_timings.is_null());
  EXPECT_TRUE(back.jobs[0].statistics.empty());
  EXPECT_TRUE(back.jobs[0].auxiliary_images.empty());
  EXPECT_EQ(back.jobs[0].metrics, results.jobs[0].metrics);
}

TEST(ResultsJson, KeepsMetricAndParameterOrder) {
  RunResults results = test::richResults();
  results.jobs[0].metrics = {{"relmse", 1}, {"flip_mean", 2}, {"mae", 3}};
  results.jobs[0].parameters = {{"z", "1"}, {"a", "2"}};
  const JobResult back = resultsFromJson(resultsToJson(results), "memory").jobs[0];
  EXPECT_EQ(back.metrics, results.jobs[0].metrics);
  EXPECT_EQ(back.parameters, results.jobs[0].parameters);
}

TEST(ResultsJson, NonFiniteValuesAreStringsAndComeBack) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  RunResults results = test::richResults();
  results.jobs[0].metrics = {{"relmse", nan}, {"psnr", inf}, {"mae", -inf}};
  const json document = resultsToJson(results);
  EXPECT_EQ(document["jobs"][0]["metrics"]["relmse"], "nan");
  EXPECT_EQ(document["jobs"][0]["metrics"]["psnr"], "inf");
  EXPECT_EQ(document["jobs"][0]["metrics"]["mae"], "-inf");
  const NamedValues back = resultsFromJson(json::parse(document.dump()), "memory").jobs[0].metrics;
  ASSERT_EQ(back.size(), 3u);
  EXPECT_TRUE(std::isnan(back[0].second));
  EXPECT_EQ(back[1].second, inf);
  EXPECT_EQ(back[2].second, -inf);
}

TEST(ResultsJson, OptionalPartsAreNullAndMayBeAbsent) {
  RunResults results = test::richResults();
  json document = resultsToJson(results);
  const json& reference_job = document["jobs"][1];
  EXPECT_TRUE(reference_job["full_reference"].is_null());
  EXPECT_TRUE(reference_job["convergence"].is_null());
  EXPECT_TRUE(reference_job["timings"].is_null());
  for (const char* key : {"full_reference", "convergence", "timings"})
    document["jobs"][1].erase(key);
  EXPECT_EQ(resultsFromJson(document, "memory"), results);
}

TEST(ResultsJson, IgnoresUnknownFields) {
  const RunResults results = test::richResults();
  json document = resultsToJson(results);
  document["added_later"] = {1, 2};
  document["jobs"][0]["gpu_power_w"] = 250;
  EXPECT_EQ(resultsFromJson(document, "memory"), results);
}

TEST(ResultsJson, MalformedFieldsAreNamedByTheirPath) {
  struct Case {
    std::function<void(json&)> damage;
    std::string message;
  };
  const std::vector<Case> cases = {
      {[](json& d) { d["jobs"][1]["metrics"]["relmse"] = "high"; },
       "r.json: jobs[1].metrics.relmse: expected a number (or \"nan\", \"inf\", \"-inf\"), found "
       "\"high\";"},
      {[](json& d) { d["jobs"][0].erase("scene"); }, "r.json: jobs[0].scene: missing;"},
      {[](json& d) { d["jobs"][0]["width"] = 64.5; }, "jobs[0].width: expected an integer"},
      {[](json& d) { d["jobs"][0]["reference"]["seed"] = -1; },
       "jobs[0].reference.seed: expected a non-negative integer"},
      {[](json& d) { d["run"]["git_dirty"] = "yes"; },
       "run.git_dirty: expected true or false, found a string"},
      {[](json& d) { d["jobs"] = json::object(); }, "jobs: expected an array, found an object"},
      {[](json& d) { d["tolerances"]["metrics"]["relmse"].erase("relative"); },
       "tolerances.metrics.relmse.relative: missing"},
      {[](json& d) { d["jobs"][0]["parameters"]["shadow"] = 3; },
       "jobs[0].parameters.shadow: expected a string, found a number"},
      {[](json& d) { d["jobs"][0]["timings"]["passes"][0]["gpu_ms"][3] = nullptr; },
       "jobs[0].timings.passes[0].gpu_ms[3]: expected a number"},
      {[](json& d) { d["jobs"][0]["convergence"]["points"][1].erase("x"); },
       "jobs[0].convergence.points[1].x: missing"},
      {[](json& d) { d = json::array(); }, "r.json: top level: expected an object, found an array"},
  };
  RunResults results = test::richResults();
  results.tolerances.metrics["relmse"] = {0.0, 0.1};
  for (const Case& c : cases) {
    json document = resultsToJson(results);
    c.damage(document);
    const std::string message = inputErrorOf([&] { resultsFromJson(document, "r.json"); });
    EXPECT_THAT(message, HasSubstr(c.message));
    EXPECT_THAT(message, HasSubstr("; run the suite again")) << message;
  }
}

TEST(ResultsJson, RejectsAnotherSchemaAndANewerVersion) {
  json document = resultsToJson(test::richResults());
  document["schema_version"] = 2;
  EXPECT_EQ(inputErrorOf([&] { resultsFromJson(document, "r.json"); }),
            "r.json: schema_version 2 is newer than this gibench reads (1); update gibench");
  document["schema_version"] = 0;
  EXPECT_THAT(inputErrorOf([&] { resultsFromJson(document, "r.json"); }),
              HasSubstr("schema_version: 0 is not a schema version"));
  document["schema"] = "chrome-trace";
  EXPECT_THAT(inputErrorOf([&] { resultsFromJson(document, "r.json"); }),
              HasSubstr("r.json: schema: 'chrome-trace' is not 'gibench-results'"));
  document.erase("schema");
  EXPECT_THAT(inputErrorOf([&] { resultsFromJson(document, "r.json"); }),
              HasSubstr("r.json: schema: missing"));
}

TEST(ResultsJson, TruncatedMissingAndEmptyFilesAreInputErrors) {
  test::TempDir dir;
  writeResultsFile(dir / "results.json", test::richResults());
  const std::string text = readText(dir / "results.json");
  writeText(dir / "truncated.json", text.substr(0, text.size() / 2));
  EXPECT_THAT(inputErrorOf([&] { readResultsFile(dir / "truncated.json"); }),
              HasSubstr("truncated.json' is not valid JSON"));
  writeText(dir / "empty.json", "");
  EXPECT_THAT(inputErrorOf([&] { readResultsFile(dir / "empty.json"); }),
              HasSubstr("empty.json' is not valid JSON"));
  EXPECT_THAT(inputErrorOf([&] { readResultsFile(dir / "absent.json"); }),
              HasSubstr("absent.json' does not exist"));
  fs::create_directory(dir / "run");
  EXPECT_THAT(inputErrorOf([&] { readResultsFile(dir / "run"); }),
              HasSubstr("holds no results.json"));
}

TEST(ResultsJson, WritingLeavesNoFileWhenTheDirectoryIsMissing) {
  test::TempDir dir;
  EXPECT_THROW(writeResultsFile(dir / "absent" / "results.json", test::richResults()), InputError);
  EXPECT_FALSE(fs::exists(dir / "absent"));
}

TEST(ResultsJson, JobFilesRoundTripAndAreNotResultsFiles) {
  test::TempDir dir;
  const RunResults results = test::richResults();
  writeJobFile(dir / "job.json", results.jobs[0]);
  EXPECT_EQ(readJobFile(dir / "job.json"), results.jobs[0]);
  EXPECT_EQ(jobFromJson(jobToJson(results.jobs[1]), "memory"), results.jobs[1]);
  EXPECT_THAT(inputErrorOf([&] { readResultsFile(dir / "job.json"); }),
              HasSubstr("'gibench-job' is not 'gibench-results'"));
  writeResultsFile(dir / "results.json", results);
  EXPECT_THAT(inputErrorOf([&] { readJobFile(dir / "results.json"); }),
              HasSubstr("'gibench-results' is not 'gibench-job'"));
}

}  // namespace
}  // namespace gib::reports
