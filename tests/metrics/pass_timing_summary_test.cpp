#include "metrics/pass_timing_summary.h"

#include <gtest/gtest.h>

#include <sstream>

namespace gib::metrics {
namespace {

rt::PassRecord pass(std::string path, std::vector<double> gpu, std::vector<double> cpu = {},
                    std::vector<int> calls = {}) {
  const std::size_t slash = path.rfind('/');
  const int depth = int(std::count(path.begin(), path.end(), '/'));
  if (calls.empty()) calls.assign(std::max(gpu.size(), cpu.size()), 1);
  return {slash == std::string::npos ? path : path.substr(slash + 1),
          path,
          depth,
          std::move(gpu),
          std::move(cpu),
          std::move(calls),
          {}};
}

// Five frames on the GPU clock: frame 60 ms in all, "a" 24, "b" 15 (three entries a frame).
rt::ProfileRecord gpuRecord() {
  rt::ProfileRecord record;
  record.warmup_frames = 2;
  record.measured_frames = 5;
  record.passes = {pass("frame", {10, 12, 11, 13, 14}), pass("frame/a", {4, 5, 4, 6, 5}),
                   pass("frame/b", {3, 3, 3, 3, 3}, {}, {3, 3, 3, 3, 3})};
  return record;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(PassTimingSummary, MediansSharesAndCallsOfTheReportedClock) {
  const std::vector<PassTiming> rows = summarizeProfile(gpuRecord()).passes;
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].path, "frame");
  EXPECT_EQ(rows[0].reported.median, 12);
  EXPECT_EQ(rows[0].reported.minimum, 10);
  EXPECT_EQ(rows[0].reported.maximum, 14);
  EXPECT_DOUBLE_EQ(rows[0].share, 1.0);
  EXPECT_EQ(rows[1].name, "a");
  EXPECT_EQ(rows[1].reported.median, 5);
  EXPECT_EQ(rows[1].reported.first_quartile, 4);
  EXPECT_EQ(rows[1].reported.third_quartile, 5);
  EXPECT_DOUBLE_EQ(rows[1].share, 24.0 / 60.0);
  EXPECT_DOUBLE_EQ(rows[2].share, 15.0 / 60.0);
  EXPECT_DOUBLE_EQ(rows[2].calls_per_frame, 3.0);
  EXPECT_DOUBLE_EQ(rows[1].calls_per_frame, 1.0);
  ASSERT_TRUE(rows[1].gpu_median_ms.has_value());
  EXPECT_EQ(*rows[1].gpu_median_ms, 5);
  EXPECT_FALSE(rows[1].cpu_median_ms.has_value());  // no CPU samples without precise mode
  EXPECT_EQ(rows[2].gpu_ms, (std::vector<double>{3, 3, 3, 3, 3}));
}

TEST(PassTimingSummary, ShareIsOfTheReportedClock) {
  rt::ProfileRecord record;
  record.reported_clock = "cpu";
  record.precise = true;
  record.measured_frames = 2;
  // The GPU clock would say "a" is half the frame; the CPU clock, which is reported, a quarter.
  record.passes = {pass("frame", {2, 2}, {8, 8}), pass("frame/a", {1, 1}, {2, 2})};
  const PassTimings timings = summarizeProfile(record);
  const std::vector<PassTiming>& rows = timings.passes;
  EXPECT_DOUBLE_EQ(rows[1].share, 0.25);
  EXPECT_EQ(rows[1].reported.median, 2);
  ASSERT_TRUE(rows[1].gpu_median_ms && rows[1].cpu_median_ms);
  EXPECT_EQ(*rows[1].gpu_median_ms, 1);
  EXPECT_EQ(timings.reportedSamples(rows[1]), (std::vector<double>{2, 2}));
}

TEST(PassTimingSummary, RowsAreDepthFirstAndTheTableIndentsByDepth) {
  rt::ProfileRecord record = gpuRecord();
  // "frame/a/c" first appeared after "frame/b": it still belongs right under "a".
  record.passes.push_back(pass("frame/a/c", {1, 1, 1, 1, 1}));
  const PassTimings timings = summarizeProfile(record);
  const std::vector<PassTiming>& rows = timings.passes;
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[1].path, "frame/a");
  EXPECT_EQ(rows[2].path, "frame/a/c");
  EXPECT_EQ(rows[2].depth, 2);
  EXPECT_EQ(rows[3].path, "frame/b");

  const std::vector<std::string> table = lines(formatPassTable(timings));
  ASSERT_EQ(table.size(), 7u);  // header, column names, four passes, frame rate
  EXPECT_TRUE(table[2].starts_with("frame ")) << table[2];
  EXPECT_TRUE(table[3].starts_with("  a ")) << table[3];
  EXPECT_TRUE(table[4].starts_with("    c ")) << table[4];
  EXPECT_TRUE(table[5].starts_with("  b ")) << table[5];
}

TEST(PassTimingSummary, TableNamesTheClockTheFramesAndTheFrameRate) {
  const rt::ProfileRecord record = gpuRecord();
  const std::string table = formatPassTable(summarizeProfile(record));
  EXPECT_NE(table.find("GPU timestamp queries"), std::string::npos) << table;
  EXPECT_NE(table.find("2 warm-up and 5 measured frames"), std::string::npos) << table;
  EXPECT_NE(table.find("83.3 fps"), std::string::npos) << table;  // 1000 / 12 ms
  EXPECT_NE(table.find("40.0%"), std::string::npos) << table;     // share of "a"
  // a + b = 65% of the frame: 35% is in no pass (Nijasure's "Overheads").
  EXPECT_NE(table.find("outside every pass 35.0%"), std::string::npos) << table;
  EXPECT_EQ(table.find("cpu median"), std::string::npos) << table;  // only one clock
}

TEST(PassTimingSummary, TableShowsTheOtherClockWhenBothWereRecorded) {
  rt::ProfileRecord record;
  record.reported_clock = "cpu";
  record.precise = true;
  record.measured_frames = 3;
  record.passes = {pass("frame", {1, 2, 3}, {4, 5, 6}),
                   pass("frame/x", {0.5, 0.5, 0.5}, {1, 2, 3})};
  const std::string table = formatPassTable(summarizeProfile(record));
  EXPECT_NE(table.find("CPU wall clock around glFinish (precise mode)"), std::string::npos);
  EXPECT_NE(table.find("gpu median"), std::string::npos) << table;
  EXPECT_NE(table.find("0.500"), std::string::npos) << table;
}

TEST(PassTimingSummary, FindsPassesByPathOrName) {
  const PassTimings timings = summarizeProfile(gpuRecord());
  EXPECT_EQ(timings.find("frame/b")->name, "b");
  EXPECT_EQ(timings.find("b")->path, "frame/b");
  EXPECT_EQ(timings.find("frame")->path, "frame");
  EXPECT_EQ(timings.find("c"), nullptr);
  EXPECT_NEAR(*timings.frameRateFps(), 1000.0 / 12.0, 1e-9);
}

TEST(PassTimingSummary, MissingOrMalformedSamplesThrow) {
  rt::ProfileRecord empty;
  empty.passes = {pass("frame", {})};
  EXPECT_THROW(summarizeProfile(empty), std::invalid_argument);
  EXPECT_THROW(summarizeProfile(rt::ProfileRecord{}), std::invalid_argument);

  rt::ProfileRecord no_cpu = gpuRecord();
  no_cpu.reported_clock = "cpu";  // says CPU, has only GPU samples
  EXPECT_THROW(summarizeProfile(no_cpu), std::invalid_argument);

  rt::ProfileRecord short_series = gpuRecord();
  short_series.passes[1].gpu_ms.pop_back();
  EXPECT_THROW(summarizeProfile(short_series), std::invalid_argument);

  rt::ProfileRecord unknown_clock = gpuRecord();
  unknown_clock.reported_clock = "wall";
  EXPECT_THROW(summarizeProfile(unknown_clock), std::invalid_argument);
}

}  // namespace
}  // namespace gib::metrics
