// results.json as the runner writes it and diff, history and report read it: an exact round
// trip, and a clear error naming the field for anything damaged, truncated or too new.
#include "results/results_json.h"

#include "common/input_error.h"
#include "support/read_text.h"
#include "support/synthetic_results.h"
#include "support/synthetic_timings.h"
#include "support/temp_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

namespace gib::results {
namespace {

namespace fs = std::filesystem;
using test::readText;
using json = nlohmann::ordered_json;
using ::testing::HasSubstr;

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
  // charts, figures, iteration_timings, statistics, auxiliary_images, scene_file, repeats and
  // conditions came after version 1: a file without them reads with their defaults
  // (docs/results-schema.md, compatibility).
  RunResults results = test::richResults();
  nlohmann::ordered_json document = resultsToJson(results);
  document.erase("charts");
  document.erase("figures");
  document["run"].erase("conditions");
  for (auto& job : document["jobs"]) {
    for (const char* key : {"iteration_timings", "statistics", "auxiliary_images", "scene_file",
                            "repeats", "conditions"})
      job.erase(key);
  }
  const RunResults back = resultsFromJson(document, "memory");
  EXPECT_TRUE(back.charts.empty());
  EXPECT_TRUE(back.figures.empty());
  EXPECT_EQ(back.run.conditions, RunConditions{});
  EXPECT_FALSE(back.jobs[0].iteration_timings.has_value());
  EXPECT_TRUE(back.jobs[0].statistics.empty());
  EXPECT_TRUE(back.jobs[0].auxiliary_images.empty());
  EXPECT_TRUE(back.jobs[0].scene_file.empty());
  EXPECT_TRUE(back.jobs[0].repeats.empty());
  EXPECT_EQ(back.jobs[0].conditions, RunConditions{});
  EXPECT_EQ(back.jobs[0].metrics, results.jobs[0].metrics);
}

TEST(ResultsJson, FiguresKeepTheirPanelsAndCellsAndRefuseCellsOutsideTheGrid) {
  const RunResults results = test::richResults();
  ASSERT_EQ(results.figures.size(), 1u);
  const json document = resultsToJson(results);
  // As docs/results-schema.md documents them.
  const json& figure = document.at("figures").at(0);
  EXPECT_EQ(figure.at("name"), "fig-6");
  EXPECT_EQ(figure.at("columns"), 3);
  const json& panel = figure.at("panels").at(0);
  EXPECT_EQ(panel.at("job"), "cornell-direct/shadow=pcf");
  EXPECT_EQ(panel.at("image"), "aux:atlas");
  EXPECT_EQ(panel.at("caption"), "atlas");
  EXPECT_EQ(panel.at("row"), 1);
  EXPECT_EQ(panel.at("column"), 3);
  EXPECT_EQ(panel.at("metric"), "full:relmse");
  EXPECT_EQ(resultsFromJson(document, "memory").figures, results.figures);

  // A hand-edited cell outside the figure is named, not laid out.
  json outside = document;
  outside["figures"][0]["panels"][1]["column"] = 4;
  EXPECT_THAT(inputErrorOf([&] { resultsFromJson(outside, "memory"); }),
              HasSubstr("figures[0].panels[1].column: must be in [1, 3]"));
  json no_row = document;
  no_row["figures"][0]["panels"][0]["row"] = 0;
  EXPECT_THAT(inputErrorOf([&] { resultsFromJson(no_row, "memory"); }),
              HasSubstr("figures[0].panels[0].row: must be 1 or more"));
  json missing = document;
  missing["figures"][0].erase("panels");
  EXPECT_THAT(inputErrorOf([&] { resultsFromJson(missing, "memory"); }),
              HasSubstr("figures[0].panels"));
}

// The per-pass timings as results.json and timings.json hold them (docs/results-schema.md).
TEST(ResultsJson, PassTimingsWriteEveryFieldAndTheRawSamples) {
  const metrics::PassTimings timings = test::syntheticTimings({{"frame", {10, 12, 11, 13, 14}},
                                                               {"frame/a", {4, 5, 4, 6, 5}},
                                                               {"frame/b", {3, 3, 3, 3, 3}, 3, 7}});
  const json j = passTimingsToJson(timings);
  const nlohmann::json parsed = nlohmann::json::parse(j.dump());
  EXPECT_EQ(parsed["clock"], "gpu");
  EXPECT_EQ(parsed["clock_description"], "GPU timestamp queries");
  EXPECT_EQ(parsed["precise"], false);
  EXPECT_EQ(parsed["warmup_frames"], 2);
  EXPECT_EQ(parsed["measured_frames"], 5);
  EXPECT_NEAR(parsed["frame_rate_fps"].get<double>(), 1000.0 / 12.0, 1e-9);
  ASSERT_EQ(parsed["passes"].size(), 3u);
  const nlohmann::json& b = parsed["passes"][2];
  EXPECT_EQ(b["name"], "b");
  EXPECT_EQ(b["path"], "frame/b");
  EXPECT_EQ(b["depth"], 1);
  EXPECT_EQ(b["median_ms"], 3.0);
  EXPECT_EQ(b["min_ms"], 3.0);
  EXPECT_EQ(b["mad_ms"], 0.0);
  EXPECT_DOUBLE_EQ(b["share"].get<double>(), 0.25);
  EXPECT_EQ(b["calls_per_frame"], 3.0);
  EXPECT_EQ(b["gpu_commands_per_frame"], 7.0);
  EXPECT_TRUE(parsed["passes"][1]["gpu_commands_per_frame"].is_null()) << "not counted";
  EXPECT_EQ(b["gpu_median_ms"], 3.0);
  EXPECT_TRUE(b["cpu_median_ms"].is_null());
  EXPECT_EQ(b["gpu_ms"].get<std::vector<double>>(), (std::vector<double>{3, 3, 3, 3, 3}));
  EXPECT_TRUE(b["cpu_ms"].empty());
  // Keys in a fixed order, so stored results diff cleanly.
  EXPECT_EQ(j.begin().key(), "clock");
  // And they read back as they were, typed.
  RunResults results = test::richResults();
  results.jobs[0].timings = timings;
  EXPECT_EQ(resultsFromJson(resultsToJson(results), "memory").jobs[0].timings, timings);
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
      {[](json& d) { d["jobs"][0]["timings"]["passes"][0]["median_ms"] = "fast"; },
       "jobs[0].timings.passes[0].median_ms: expected a number"},
      {[](json& d) { d["jobs"][0]["timings"]["passes"][0].erase("share"); },
       "jobs[0].timings.passes[0].share: missing"},
      {[](json& d) { d["jobs"][0]["timings"]["clock"] = "wall"; },
       "jobs[0].timings.clock: 'wall' is neither \"gpu\" nor \"cpu\""},
      {[](json& d) { d["jobs"][0]["timings"]["passes"] = json::array(); },
       "jobs[0].timings.passes: has no passes"},
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

// Found by fuzzing (fuzz/corpus/results_json/regression-number-overflow.json): a number beyond a
// double's range is valid JSON syntax, and the parser's overflow escaped as an internal error.
TEST(ResultsJson, ANumberBeyondDoubleRangeIsAnInputError) {
  test::TempDir dir;
  writeText(dir / "overflow.json", R"({"schema": "gibench-results", "schema_version": 1e999})");
  EXPECT_THAT(inputErrorOf([&] { readResultsFile(dir / "overflow.json"); }),
              HasSubstr("overflow.json' holds a number beyond the range of a double"));
  EXPECT_THAT(inputErrorOf([&] { readJobFile(dir / "overflow.json"); }),
              HasSubstr("beyond the range of a double"));
  EXPECT_THAT(inputErrorOf([&] { readPassTimingsFile(dir / "overflow.json"); }),
              HasSubstr("beyond the range of a double"));
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

// A paper value's tolerance is optional: absent from the file when not set (a value shown, not
// judged), and a hand-edited negative one is refused like any bad field.
TEST(ResultsJson, PaperTolerancesAreWrittenWhenSetAndRoundTrip) {
  RunResults results = test::richResults();
  results::PaperValue judged = results.paper.at(0);
  judged.quantity = "relmse";
  judged.value = 0.02;
  judged.tolerance = 0.05;
  results.paper.push_back(judged);
  json document = resultsToJson(results);
  EXPECT_FALSE(document.at("paper").at(0).contains("tolerance"));
  EXPECT_EQ(document.at("paper").at(1).at("tolerance"), 0.05);
  EXPECT_EQ(resultsFromJson(document, "memory").paper, results.paper);
  document["paper"][1]["tolerance"] = -0.05;
  EXPECT_THAT(inputErrorOf([&] { resultsFromJson(document, "r.json"); }),
              HasSubstr("paper[1].tolerance: must be a finite number ≥ 0"));
}

}  // namespace
}  // namespace gib::results
