#include "metrics/pass_timing_summary.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

namespace gib::metrics {

namespace {

double sum(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0);
}

void checkSeries(const rt::PassRecord& pass, std::string_view series, std::size_t size,
                 std::size_t frames, bool optional) {
  if (size == frames || (optional && size == 0)) return;
  throw std::invalid_argument(fmt::format("pass '{}' has {} {} values for {} measured frames",
                                          pass.path, size, series, frames));
}

// Record indices in table order: depth first, children in first-seen order. The record lists
// passes in first-seen order, so a pass first seen late (a child of the first pass appearing in
// frame 5) would otherwise land under whatever pass came before it. Paths join names with '/',
// which the profiler keeps out of names.
std::vector<std::size_t> depthFirstOrder(const rt::ProfileRecord& record) {
  const std::size_t n = record.passes.size();
  std::unordered_map<std::string_view, std::size_t> by_path;
  for (std::size_t i = 0; i < n; ++i) by_path.emplace(record.passes[i].path, i);
  std::vector<std::vector<std::size_t>> children(n);
  std::vector<std::size_t> roots;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string_view path = record.passes[i].path;
    const std::size_t slash = path.rfind('/');
    const auto parent =
        slash == std::string_view::npos ? by_path.end() : by_path.find(path.substr(0, slash));
    (parent == by_path.end() ? roots : children[parent->second]).push_back(i);
  }
  std::vector<std::size_t> order;
  std::vector<std::size_t> stack(roots.rbegin(), roots.rend());
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    order.push_back(i);
    stack.insert(stack.end(), children[i].rbegin(), children[i].rend());
  }
  return order;
}

const rt::PassRecord& passAt(const rt::ProfileRecord& record, const std::string& path) {
  for (const rt::PassRecord& pass : record.passes)
    if (pass.path == path) return pass;
  throw std::invalid_argument(fmt::format("no pass '{}' in the profile record", path));
}

std::string clockDescription(const std::string& clock) {
  return clock == "cpu" ? "CPU wall clock around glFinish (precise mode)" : "GPU timestamp queries";
}

// The clock that is not reported, and a row's summary of it.
std::string otherClock(const rt::ProfileRecord& record) {
  return record.reported_clock == "cpu" ? "gpu" : "cpu";
}
const std::optional<TimingSummary>& summaryOf(const PassTimingRow& row, const std::string& clock) {
  return clock == "cpu" ? row.cpu : row.gpu;
}

std::optional<double> frameRate(const std::vector<PassTimingRow>& rows) {
  if (rows.empty() || rows.front().reported.median <= 0) return std::nullopt;
  return 1000.0 / rows.front().reported.median;
}

}  // namespace

std::vector<PassTimingRow> summarizeProfile(const rt::ProfileRecord& record) {
  if (record.measured_frames <= 0 || record.passes.empty())
    throw std::invalid_argument("no measured frames to summarise");
  if (record.reported_clock != "gpu" && record.reported_clock != "cpu")
    throw std::invalid_argument(
        fmt::format("unknown reported clock '{}' (gpu or cpu)", record.reported_clock));
  const auto frames = std::size_t(record.measured_frames);
  const double frame_total = sum(record.reported(record.passes.front()));
  std::vector<PassTimingRow> rows;
  for (std::size_t i : depthFirstOrder(record)) {
    const rt::PassRecord& pass = record.passes[i];
    checkSeries(pass, "gpu_ms", pass.gpu_ms.size(), frames, true);
    checkSeries(pass, "cpu_ms", pass.cpu_ms.size(), frames, true);
    checkSeries(pass, record.reported_clock + "_ms", record.reported(pass).size(), frames, false);
    checkSeries(pass, "calls", pass.calls.size(), frames, false);
    PassTimingRow row;
    row.name = pass.name;
    row.path = pass.path;
    row.depth = pass.depth;
    if (!pass.gpu_ms.empty()) row.gpu = summarizeTimings(pass.gpu_ms);
    if (!pass.cpu_ms.empty()) row.cpu = summarizeTimings(pass.cpu_ms);
    row.reported = *summaryOf(row, record.reported_clock);  // checked above: it has samples
    row.share = frame_total > 0 ? sum(record.reported(pass)) / frame_total : 0.0;
    row.calls_per_frame =
        double(std::accumulate(pass.calls.begin(), pass.calls.end(), 0L)) / double(frames);
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string formatPassTable(const rt::ProfileRecord& record,
                            const std::vector<PassTimingRow>& rows) {
  const std::string other = otherClock(record);
  const bool both = std::any_of(rows.begin(), rows.end(), [&](const PassTimingRow& row) {
    return summaryOf(row, other).has_value();
  });
  std::size_t name_width = 4;  // "pass"
  for (const PassTimingRow& row : rows)
    name_width = std::max(name_width, 2 * std::size_t(row.depth) + row.name.size());

  std::string out = fmt::format(
      "Per-pass times in ms per frame, {}; {} warm-up and {} measured frames\n",
      clockDescription(record.reported_clock), record.warmup_frames, record.measured_frames);
  out += fmt::format("{:<{}}  {:>9} {:>9} {:>9} {:>9} {:>9} {:>7} {:>6}", "pass", name_width,
                     "median", "q1", "q3", "min", "max", "share", "calls");
  if (both) out += fmt::format(" {:>11}", other + " median");
  out += '\n';
  double outside = 1.0;
  bool has_children = false;
  for (const PassTimingRow& row : rows) {
    const TimingSummary& s = row.reported;
    const std::string indented = std::string(2 * std::size_t(row.depth), ' ') + row.name;
    out += fmt::format("{:<{}}  {:9.3f} {:9.3f} {:9.3f} {:9.3f} {:9.3f} {:6.1f}% {:>6.3g}",
                       indented, name_width, s.median, s.first_quartile, s.third_quartile,
                       s.minimum, s.maximum, 100.0 * row.share, row.calls_per_frame);
    if (both) {
      const std::optional<TimingSummary>& o = summaryOf(row, other);
      out += o ? fmt::format(" {:11.3f}", o->median) : fmt::format(" {:>11}", "-");
    }
    out += '\n';
    if (row.depth == 1) {
      outside -= row.share;
      has_children = true;
    }
  }
  std::vector<std::string> footer;
  if (const std::optional<double> fps = frameRate(rows))
    footer.push_back(
        fmt::format("median frame {:.3f} ms = {:.1f} fps", rows.front().reported.median, *fps));
  // Nijasure's "Overheads" row: frame time no pass accounts for.
  if (has_children)
    footer.push_back(fmt::format("outside every pass {:.1f}%", 100.0 * std::max(0.0, outside)));
  if (!footer.empty()) out += fmt::format("{}\n", fmt::join(footer, "; "));
  return out;
}

nlohmann::ordered_json passTimingsJson(const rt::ProfileRecord& record,
                                       const std::vector<PassTimingRow>& rows) {
  using json = nlohmann::ordered_json;
  auto median = [](const std::optional<TimingSummary>& s) {
    return s ? json(s->median) : json(nullptr);
  };
  json passes = json::array();
  for (const PassTimingRow& row : rows) {
    const rt::PassRecord& pass = passAt(record, row.path);
    passes.push_back({{"name", row.name},
                      {"path", row.path},
                      {"depth", row.depth},
                      {"median_ms", row.reported.median},
                      {"first_quartile_ms", row.reported.first_quartile},
                      {"third_quartile_ms", row.reported.third_quartile},
                      {"min_ms", row.reported.minimum},
                      {"max_ms", row.reported.maximum},
                      {"mad_ms", row.reported.median_absolute_deviation},
                      {"gpu_median_ms", median(row.gpu)},
                      {"cpu_median_ms", median(row.cpu)},
                      {"share", row.share},
                      {"calls_per_frame", row.calls_per_frame},
                      {"gpu_ms", pass.gpu_ms},
                      {"cpu_ms", pass.cpu_ms}});
  }
  const std::optional<double> fps = frameRate(rows);
  return {{"clock", record.reported_clock},
          {"clock_description", clockDescription(record.reported_clock)},
          {"precise", record.precise},
          {"warmup_frames", record.warmup_frames},
          {"measured_frames", record.measured_frames},
          {"frame_rate_fps", fps ? json(*fps) : json(nullptr)},
          {"passes", std::move(passes)}};
}

}  // namespace gib::metrics
