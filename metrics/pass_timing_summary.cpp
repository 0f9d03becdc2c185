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

std::string clockDescription(const std::string& clock) {
  return clock == "cpu" ? "CPU wall clock around glFinish (precise mode)" : "GPU timestamp queries";
}

// The clock that is not reported, and a pass's median of it.
std::string otherClock(const PassTimings& timings) {
  return timings.clock == "cpu" ? "gpu" : "cpu";
}
const std::optional<double>& medianOf(const PassTiming& pass, const std::string& clock) {
  return clock == "cpu" ? pass.cpu_median_ms : pass.gpu_median_ms;
}

std::optional<double> medianIfAny(const std::vector<double>& samples) {
  return samples.empty() ? std::nullopt : std::optional<double>(quantile(samples, 0.5));
}

}  // namespace

PassTimings summarizeProfile(const rt::ProfileRecord& record) {
  if (record.measured_frames <= 0 || record.passes.empty())
    throw std::invalid_argument("no measured frames to summarise");
  if (record.reported_clock != "gpu" && record.reported_clock != "cpu")
    throw std::invalid_argument(
        fmt::format("unknown reported clock '{}' (gpu or cpu)", record.reported_clock));
  const auto frames = std::size_t(record.measured_frames);
  const double frame_total = sum(record.reported(record.passes.front()));
  PassTimings timings;
  timings.clock = record.reported_clock;
  timings.precise = record.precise;
  timings.warmup_frames = record.warmup_frames;
  timings.measured_frames = record.measured_frames;
  for (std::size_t i : depthFirstOrder(record)) {
    const rt::PassRecord& pass = record.passes[i];
    checkSeries(pass, "gpu_ms", pass.gpu_ms.size(), frames, true);
    checkSeries(pass, "cpu_ms", pass.cpu_ms.size(), frames, true);
    checkSeries(pass, record.reported_clock + "_ms", record.reported(pass).size(), frames, false);
    checkSeries(pass, "calls", pass.calls.size(), frames, false);
    checkSeries(pass, "gpu_commands", pass.gpu_commands.size(), frames, true);
    PassTiming row;
    row.name = pass.name;
    row.path = pass.path;
    row.depth = pass.depth;
    row.reported = summarizeTimings(record.reported(pass));  // checked above: it has samples
    row.gpu_median_ms = medianIfAny(pass.gpu_ms);
    row.cpu_median_ms = medianIfAny(pass.cpu_ms);
    row.share = frame_total > 0 ? sum(record.reported(pass)) / frame_total : 0.0;
    row.calls_per_frame =
        double(std::accumulate(pass.calls.begin(), pass.calls.end(), 0L)) / double(frames);
    if (!pass.gpu_commands.empty())
      row.gpu_commands_per_frame =
          double(std::accumulate(pass.gpu_commands.begin(), pass.gpu_commands.end(), 0L)) /
          double(frames);
    row.gpu_ms = pass.gpu_ms;
    row.cpu_ms = pass.cpu_ms;
    timings.passes.push_back(std::move(row));
  }
  return timings;
}

const PassTiming* PassTimings::find(std::string_view path_or_name) const {
  for (const PassTiming& pass : passes)
    if (pass.path == path_or_name) return &pass;
  for (const PassTiming& pass : passes)
    if (pass.name == path_or_name) return &pass;
  return nullptr;
}

std::optional<double> PassTimings::frameRateFps() const {
  if (passes.empty() || root().reported.median <= 0) return std::nullopt;
  return 1000.0 / root().reported.median;
}

std::string PassTimings::clockDescription() const {
  return metrics::clockDescription(clock);
}

std::string formatPassTable(const PassTimings& timings) {
  const std::string other = otherClock(timings);
  const bool both = std::any_of(timings.passes.begin(), timings.passes.end(),
                                [&](const PassTiming& pass) { return medianOf(pass, other); });
  std::size_t name_width = 4;  // "pass"
  for (const PassTiming& pass : timings.passes)
    name_width = std::max(name_width, 2 * std::size_t(pass.depth) + pass.name.size());

  std::string out =
      fmt::format("Per-pass times in ms per frame, {}; {} warm-up and {} measured frames\n",
                  timings.clockDescription(), timings.warmup_frames, timings.measured_frames);
  out += fmt::format("{:<{}}  {:>9} {:>9} {:>9} {:>9} {:>9} {:>7} {:>6} {:>6}", "pass", name_width,
                     "median", "q1", "q3", "min", "max", "share", "calls", "draws");
  if (both) out += fmt::format(" {:>11}", other + " median");
  out += '\n';
  double outside = 1.0;
  bool has_children = false;
  for (const PassTiming& pass : timings.passes) {
    const TimingSummary& s = pass.reported;
    const std::string indented = std::string(2 * std::size_t(pass.depth), ' ') + pass.name;
    out += fmt::format("{:<{}}  {:9.3f} {:9.3f} {:9.3f} {:9.3f} {:9.3f} {:6.1f}% {:>6.3g}",
                       indented, name_width, s.median, s.first_quartile, s.third_quartile,
                       s.minimum, s.maximum, 100.0 * pass.share, pass.calls_per_frame);
    out += pass.gpu_commands_per_frame ? fmt::format(" {:>6.4g}", *pass.gpu_commands_per_frame)
                                       : fmt::format(" {:>6}", "-");
    if (both) {
      const std::optional<double>& o = medianOf(pass, other);
      out += o ? fmt::format(" {:11.3f}", *o) : fmt::format(" {:>11}", "-");
    }
    out += '\n';
    if (pass.depth == 1) {
      outside -= pass.share;
      has_children = true;
    }
  }
  std::vector<std::string> footer;
  if (const std::optional<double> fps = timings.frameRateFps())
    footer.push_back(
        fmt::format("median frame {:.3f} ms = {:.1f} fps", timings.root().reported.median, *fps));
  // Nijasure's "Overheads" row: frame time no pass accounts for.
  if (has_children)
    footer.push_back(fmt::format("outside every pass {:.1f}%", 100.0 * std::max(0.0, outside)));
  if (!footer.empty()) out += fmt::format("{}\n", fmt::join(footer, "; "));
  return out;
}

}  // namespace gib::metrics
