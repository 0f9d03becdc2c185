#include "reports/timing_sections.h"

#include "reports/html_text.h"
#include "reports/number_format.h"
#include "reports/report_labels.h"
#include "reports/report_page.h"
#include "reports/svg_charts.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace gib::reports {

namespace {

std::string clockName(const std::string& clock) {
  return clock == "cpu" ? "CPU" : "GPU";
}

// The clock recorded beside the reported one (GPU timer queries beside the CPU clock of precise
// mode, or the CPU clock beside the timer queries); empty when no pass has its samples.
std::string otherClock(const metrics::PassTimings& timings) {
  const std::string other = timings.clock == "cpu" ? "gpu" : "cpu";
  for (const metrics::PassTiming& pass : timings.passes)
    if ((other == "cpu" ? pass.cpu_median_ms : pass.gpu_median_ms).has_value()) return other;
  return {};
}

std::optional<double> medianOn(const metrics::PassTiming& pass, const std::string& clock) {
  return clock == "cpu" ? pass.cpu_median_ms : pass.gpu_median_ms;
}

// The passes worth a row: a pass never entered in the measured frames (a branch the technique
// did not take) has nothing but zeros to show.
std::vector<const metrics::PassTiming*> shownPasses(const metrics::PassTimings& timings) {
  std::vector<const metrics::PassTiming*> shown;
  for (const metrics::PassTiming& pass : timings.passes)
    if (pass.calls_per_frame > 0 || pass.reported.median != 0) shown.push_back(&pass);
  return shown;
}

// One unit for every time of a table, chosen by its largest (the frame's third quartile, or the
// other clock's median when that is larger).
TimeUnit tableUnit(const std::vector<const metrics::PassTiming*>& passes,
                   const std::string& other) {
  double largest = 0;
  for (const metrics::PassTiming* pass : passes) {
    largest = std::max(largest, pass->reported.third_quartile);
    if (const std::optional<double> median = medianOn(*pass, other))
      largest = std::max(largest, *median);
  }
  return timeUnitFor(largest);
}

std::string timingsIntro(const metrics::PassTimings& timings,
                         const std::optional<JobComparison>& compared) {
  std::string intro = fmt::format("<p>{}; {} warm-up and {} measured frames.",
                                  escapeHtml(timings.clockDescription()), timings.warmup_frames,
                                  timings.measured_frames);
  if (const std::string other = otherClock(timings); !other.empty())
    intro += fmt::format(" The {} clock's medians are shown beside it.", clockName(other));
  const double frame = timings.root().reported.median;
  if (std::isfinite(frame))
    intro += fmt::format(" Median frame {}", escapeHtml(formatMilliseconds(frame)));
  if (const std::optional<double> fps = timings.frameRateFps())
    intro += fmt::format(" ({} fps)", formatNumber(*fps, 3));
  if (compared && compared->timing) {
    const results::TimingChange& t = *compared->timing;
    intro += fmt::format("; previous run {} ms, now {}: {} ({})", formatNumber(t.base_median_ms),
                         verdictSpan(formatNumber(t.next_median_ms) + " ms", compared->timing),
                         results::verdictName(t.verdict), escapeHtml(t.explanation()));
  }
  return intro + ".</p>\n";
}

std::vector<TableColumn> passColumns(const metrics::PassTimings& timings, const std::string& other,
                                     const TimeUnit& unit, std::string_view sample, bool commands) {
  const std::string reported = clockName(timings.clock);
  std::vector<TableColumn> columns = {
      {"pass"},
      {fmt::format("{} median ({})", reported, unit.symbol), true},
      {fmt::format("{} first quartile ({})", reported, unit.symbol), true},
      {fmt::format("{} third quartile ({})", reported, unit.symbol), true}};
  if (!other.empty())
    columns.push_back({fmt::format("{} median ({})", clockName(other), unit.symbol), true});
  columns.push_back({fmt::format("share of {} (%)", sample), true});
  columns.push_back({fmt::format("calls per {}", sample), true});
  if (commands) columns.push_back({fmt::format("GPU commands per {}", sample), true});
  return columns;
}

// `sample`: what one sample times, "frame" or "iteration"; `unit`: of every time in it.
std::string passTable(const metrics::PassTimings& timings, std::string_view sample,
                      const TimeUnit& unit) {
  const std::vector<const metrics::PassTiming*> passes = shownPasses(timings);
  const std::string other = otherClock(timings);
  const bool commands = std::any_of(passes.begin(), passes.end(), [](const auto* pass) {
    return pass->gpu_commands_per_frame.has_value();
  });
  const auto time = [&](double ms) { return formatNumber(ms * unit.per_ms); };
  HtmlTable table(passColumns(timings, other, unit, sample, commands));
  for (const metrics::PassTiming* pass : passes) {
    std::vector<std::string> row = {
        fmt::format("<span style=\"padding-left:{}em\">{}</span>", 1.2 * std::max(0, pass->depth),
                    escapeHtml(pass->name)),
        time(pass->reported.median), time(pass->reported.first_quartile),
        time(pass->reported.third_quartile)};
    if (!other.empty()) {
      const std::optional<double> median = medianOn(*pass, other);
      row.push_back(median ? time(*median) : std::string("—"));
    }
    row.push_back(formatShare(pass->share));
    row.push_back(formatNumber(pass->calls_per_frame, 3));
    if (commands)
      row.push_back(pass->gpu_commands_per_frame ? formatNumber(*pass->gpu_commands_per_frame, 4)
                                                 : std::string("—"));
    table.addRow(row);
  }
  return table.html();
}

std::vector<PassBar> passBars(const metrics::PassTimings& timings) {
  std::vector<PassBar> bars;
  for (const metrics::PassTiming* pass : shownPasses(timings))
    bars.push_back({pass->name, pass->depth, pass->reported.median, pass->reported.first_quartile,
                    pass->reported.third_quartile});
  return bars;
}

// Every sample of every shown pass, on the reported clock.
std::string passStrips(const metrics::PassTimings& timings, std::string_view sample,
                       const TimeUnit& unit) {
  const std::vector<const metrics::PassTiming*> passes = shownPasses(timings);
  StripPlot plot{
      fmt::format("Each {}'s time per pass ({} clock)", sample, clockName(timings.clock)),
      std::string(sample),
      unit.symbol,
      {}};
  for (const metrics::PassTiming* pass : passes) {
    StripRow row{pass->name, pass->depth, {}};
    for (double ms : timings.reportedSamples(*pass)) row.values.push_back(ms * unit.per_ms);
    plot.rows.push_back(std::move(row));
  }
  return stripChart(plot);
}

// The table, the bar chart of medians and the strip plot of every sample, in one unit.
std::string passFigures(const metrics::PassTimings& timings, std::string_view sample) {
  const TimeUnit unit = tableUnit(shownPasses(timings), otherClock(timings));
  return "<div class=\"charts\">\n" + passTable(timings, sample, unit) +
         passTimingChart(passBars(timings), sample, unit) + "\n" +
         passStrips(timings, sample, unit) + "\n</div>\n";
}

// A job run several times: each run's median, the one shown below being the median of them.
std::string repeatsText(const results::JobResult& job) {
  if (job.repeats.size() < 2) return {};
  std::vector<std::string> medians;
  for (double median : job.repeatMediansMs()) medians.push_back(formatNumber(median));
  return fmt::format(
      "<p>{} runs of the job, each with a fresh GL context and interleaved with the other jobs' "
      "runs; their median frame times (ms): {}. The table shows the run of the median.</p>\n",
      job.repeats.size(), escapeHtml(fmt::format("{}", fmt::join(medians, ", "))));
}

std::string conditionsParagraph(const results::RunConditions& conditions) {
  return fmt::format("<p class=\"muted\">Machine around the job: {}.</p>\n",
                     escapeHtml(conditionsText(conditions)));
}

// The work before the measured frames; phases that took no time (a technique that does not
// iterate) get no row.
std::string phasesTable(const results::JobResult& job) {
  HtmlTable table({{"phase"}, {"time", true}});
  if (job.upload_ms > 0)
    table.addRow({"upload (scene to the GPU)", escapeHtml(formatMilliseconds(job.upload_ms))});
  if (job.prepare_ms > 0)
    table.addRow({"prepare (precomputation)", escapeHtml(formatMilliseconds(job.prepare_ms))});
  if (job.iterations > 0 || job.iterate_ms > 0)
    table.addRow(
        {fmt::format("iterate ({} iteration{})", job.iterations, job.iterations == 1 ? "" : "s"),
         escapeHtml(formatMilliseconds(job.iterate_ms))});
  if (table.empty()) return {};
  return "<h3>Before the frames</h3>\n" + table.html();
}

}  // namespace

std::string timingsSection(const results::JobResult& job,
                           const std::optional<JobComparison>& compared) {
  const std::string phases = phasesTable(job);
  if (!job.timings)
    return phases.empty() ? std::string() : htmlSection("timings", "Timings", phases);
  return htmlSection("timings", "Timings",
                     timingsIntro(*job.timings, compared) + repeatsText(job) +
                         conditionsParagraph(job.conditions) + passFigures(*job.timings, "frame") +
                         phases);
}

std::string iterationTimingsSection(const results::JobResult& job) {
  if (!job.iteration_timings) return {};
  const metrics::PassTimings& timings = *job.iteration_timings;
  const std::string intro =
      fmt::format("<p>{}; {} iterations, each timed as one unit. Median iteration {}.</p>\n",
                  escapeHtml(timings.clockDescription()), timings.measured_frames,
                  escapeHtml(formatMilliseconds(timings.root().reported.median)));
  return htmlSection("iteration-timings", "Time per iteration",
                     intro + passFigures(timings, "iteration"));
}

}  // namespace gib::reports
