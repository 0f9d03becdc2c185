// What the report's pages say about what they compare (issue 41 §2): the reference named beside
// each number, the full-reference error, iterations' time, the renderer, metric definitions from
// the registry, GPU times and per-frame strips, the full-precision files and the disagreement
// mask. Each test builds a synthetic run, changes the part it checks and reads the pages.
#include "metrics/metric_registry.h"
#include "reports/figure_panels.h"
#include "reports/html_report.h"
#include "reports/html_text.h"
#include "reports/metric_labels.h"
#include "reports/report_labels.h"
#include "support/markup_check.h"
#include "support/read_text.h"
#include "support/synthetic_report_run.h"
#include "support/synthetic_timings.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;
using test::countOccurrences;
using test::readText;

constexpr std::size_t kReference = 0, kPcf = 1, kVsm = 2;  // the synthetic run's jobs

// The text from `start` (inclusive) to the first `end` after it; "" when `start` is absent.
std::string between(const std::string& html, const std::string& start, const std::string& end) {
  const std::size_t from = html.find(start);
  if (from == std::string::npos) return {};
  const std::size_t to = html.find(end, from);
  return html.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

std::string section(const std::string& html, const std::string& id) {
  return between(html, "<section id=\"" + id + "\">", "</section>");
}

// A job's entry in the index matrix: from its <div class="job …"> to the next entry or the end
// of the cell.
std::string matrixEntry(const std::string& index, const results::JobResult& job) {
  const std::size_t link = index.find("<a href=\"report/" + job.slug + ".html\">");
  if (link == std::string::npos) return {};
  const std::size_t start = index.rfind("<div class=\"job", link);
  const std::size_t end = std::min(index.find("<div class=\"job", link), index.find("</td>", link));
  return index.substr(start, end - start);
}

void writeFile(const fs::path& path, const std::string& text = "x") {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

class HtmlReportPages : public ::testing::Test {
 protected:
  void SetUp() override {
    results_ = test::syntheticReportResults();
    for (results::JobResult& job : results_.jobs) {
      job.reference.pixel_sampling = "center";
      if (job.full_reference) job.full_reference->pixel_sampling = "center";
    }
  }
  std::string writeIndex() {
    test::writeSyntheticOutputs(dir_.path(), results_);
    return readText(writeHtmlReport(dir_.path(), results_, {}));
  }
  std::string page(std::size_t job) const {
    return readText(dir_ / jobPageFile(results_.jobs[job]));
  }
  std::vector<std::string> allPages() const {
    std::vector<std::string> pages = {readText(dir_ / "index.html")};
    for (std::size_t i = 0; i < results_.jobs.size(); ++i) pages.push_back(page(i));
    for (const results::FigureSpec& figure : results_.figures)
      pages.push_back(readText(dir_ / figurePageFile(figure)));
    return pages;
  }

  test::TempDir dir_;
  results::RunResults results_;
};

TEST_F(HtmlReportPages, IndexNamesTheReferenceBesideEachNumber) {
  results_.jobs[kReference].reference.spp = 1024;
  const std::string index = writeIndex();
  const std::string pcf = matrixEntry(index, results_.jobs[kPcf]);
  ASSERT_FALSE(pcf.empty()) << index;
  EXPECT_NE(
      pcf.find("0.0021</span> <span class=\"against\">vs L(D|S|P){0,1}E, pixel centres</span>"),
      std::string::npos)
      << pcf;
  // The reference job's number measures its last checkpoint against the stored reference.
  const std::string reference = matrixEntry(index, results_.jobs[kReference]);
  EXPECT_NE(reference.find("vs the 256-spp checkpoint against the 1024-spp reference"),
            std::string::npos)
      << reference;
  // Every number of the matrix names its reference: one "vs" per value.
  const std::string matrix = between(index, "<table class=\"matrix\">", "</table>");
  EXPECT_EQ(countOccurrences(matrix, "class=\"against\""), 5);  // 3 jobs, 2 with a full number
  EXPECT_EQ(countOccurrences(matrix, "class=\"against\""),
            countOccurrences(matrix, "<span class=\"metric-name\""));
  // An anti-aliased reference is said to be one.
  results_.jobs[kPcf].reference.pixel_sampling = "area";
  EXPECT_NE(matrixEntry(writeIndex(), results_.jobs[kPcf]).find("vs L(D|S|P){0,1}E, box-filtered"),
            std::string::npos);
}

TEST_F(HtmlReportPages, IndexShowsTheFullReferenceErrorWhereTheClassIsNarrower) {
  const std::string index = writeIndex();
  const std::string pcf = matrixEntry(index, results_.jobs[kPcf]);
  EXPECT_NE(pcf.find("0.0084</span> <span class=\"against\">vs full: all paths, pixel centres"),
            std::string::npos)
      << pcf;  // 4 × relmse against all paths
  // The reference job is the full reference: no second number.
  EXPECT_EQ(matrixEntry(index, results_.jobs[kReference]).find("vs full:"), std::string::npos);
  EXPECT_EQ(countOccurrences(index, "vs full:"), 2);
  results_.jobs[kVsm].full_reference.reset();
  results_.jobs[kVsm].metrics_full.clear();
  EXPECT_EQ(countOccurrences(writeIndex(), "vs full:"), 1);
}

TEST_F(HtmlReportPages, IndexShowsIterationsTimeAndPreparationBesideTheFrameTime) {
  const std::string index = writeIndex();
  const std::string pcf = matrixEntry(index, results_.jobs[kPcf]);
  EXPECT_NE(pcf.find("<div>8 it. in 16 ms</div>"), std::string::npos) << pcf;
  EXPECT_NE(pcf.find("<div>prepare 12 ms</div>"), std::string::npos) << pcf;
  EXPECT_LT(pcf.find("frame "), pcf.find("it. in"));
  // vsm does not iterate; the reference neither iterates nor prepares.
  EXPECT_EQ(matrixEntry(index, results_.jobs[kVsm]).find("it. in"), std::string::npos);
  EXPECT_EQ(matrixEntry(index, results_.jobs[kReference]).find("prepare"), std::string::npos);
  // Under a millisecond, microseconds.
  results_.jobs[kPcf].iterate_ms = 0.436;
  EXPECT_NE(matrixEntry(writeIndex(), results_.jobs[kPcf]).find("8 it. in 436 \u00b5s"),
            std::string::npos);
}

TEST_F(HtmlReportPages, SoftwareRasterisersAreFlaggedOnEveryPageAndGpusAreNot) {
  writeIndex();  // the synthetic run's renderer is llvmpipe
  for (const std::string& html : allPages()) {
    EXPECT_NE(html.find("llvmpipe (LLVM 15.0.6, 256 bits)"), std::string::npos);
    EXPECT_NE(html.find("class=\"renderer software-renderer\""), std::string::npos);
    EXPECT_NE(html.find("not representative of a GPU"), std::string::npos);
  }
  const std::string gpu = "NVIDIA GeForce RTX 4090/PCIe/SSE2";
  results_.run.gl_renderer = gpu;
  writeIndex();
  for (const std::string& html : allPages()) {
    EXPECT_NE(html.find("GL renderer: <strong>" + gpu + "</strong>"), std::string::npos);
    EXPECT_EQ(html.find("class=\"renderer software-renderer\""), std::string::npos);
  }
  // A job that ran elsewhere names its own renderer.
  results_.jobs[kVsm].execution.gl_renderer = "softpipe";
  writeIndex();
  EXPECT_NE(page(kVsm).find("class=\"renderer software-renderer\""), std::string::npos);
  EXPECT_EQ(page(kPcf).find("class=\"renderer software-renderer\""), std::string::npos);
}

TEST(ReportLabels, SoftwareRasterisersAreKnownByMesaNames) {
  for (const char* software :
       {"llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "Software Rasterizer", "Mesa swrast"})
    EXPECT_TRUE(isSoftwareRasteriser(software)) << software;
  for (const char* gpu : {"NVIDIA GeForce RTX 4090/PCIe/SSE2", "AMD Radeon RX 7900 XTX (radeonsi)",
                          "Mesa Intel(R) UHD Graphics 630 (CFL GT2)", ""})
    EXPECT_FALSE(isSoftwareRasteriser(gpu)) << gpu;
}

TEST_F(HtmlReportPages, MetricLegendGivesEachShownValuesDefinitionDirectionAndParameters) {
  const std::string index = writeIndex();
  const metrics::MetricInfo& relmse =
      *std::find_if(metrics::metricCatalogue().begin(), metrics::metricCatalogue().end(),
                    [](const metrics::MetricInfo& m) { return m.name == "relmse"; });
  const std::string legend = between(index, "<table class=\"metric-legend\">", "</table>");
  ASSERT_FALSE(legend.empty()) << index;
  EXPECT_NE(legend.find(escapeHtml(relmse.description)), std::string::npos) << legend;
  EXPECT_NE(legend.find("lower is better"), std::string::npos);
  EXPECT_NE(legend.find("\u03b5 = 0.01"), std::string::npos);
  // The same on hover, wherever the name stands.
  EXPECT_NE(index.find("title=\"" + escapeHtml(metricDescription("relmse")) + "\">relmse</span>"),
            std::string::npos);
  // The job page's legend has every value of its table, similarities the other way round.
  const std::string job_legend = between(page(kPcf), "<table class=\"metric-legend\">", "</table>");
  for (const char* value : {">relmse<", ">flip mean<", ">psnr<"})
    EXPECT_NE(job_legend.find(value), std::string::npos) << value;
  EXPECT_NE(job_legend.find("higher is better"), std::string::npos);
  // One row per metric: flip's values share theirs, each value still named with its tooltip.
  results_.jobs[kPcf].metrics = {{"flip_mean", 0.08}, {"flip_median", 0.05}, {"psnr", 31.5}};
  results_.jobs[kPcf].metrics_full = results_.jobs[kPcf].metrics;
  writeIndex();
  const std::string grouped = between(page(kPcf), "<table class=\"metric-legend\">", "</table>");
  EXPECT_EQ(countOccurrences(grouped, "<tr>"), 1 + 2) << grouped;  // the head, flip, psnr
  EXPECT_NE(grouped.find(">flip mean</span>, <span"), std::string::npos) << grouped;
}

TEST_F(HtmlReportPages, FlipPercentilesAreLabelledWeightedAndKeepTheirResultsNames) {
  results_.jobs[kPcf].metrics = {{"flip_median", 0.05}, {"flip_q1", 0.01}, {"flip_q3", 0.1}};
  writeIndex();
  const std::string metrics = section(page(kPcf), "metrics");
  for (const char* label : {">flip weighted median<", ">flip weighted first quartile<",
                            ">flip weighted third quartile<"})
    EXPECT_NE(metrics.find(label), std::string::npos) << label;
  EXPECT_EQ(metrics.find(">flip_median<"), std::string::npos);
  EXPECT_NE(metrics.find("results.json: flip_median"), std::string::npos);
  EXPECT_EQ(metricLabel("hdrflip_q1"), "hdrflip weighted first quartile");
  EXPECT_EQ(metricLabel("flip_mean"), "flip mean");
  EXPECT_EQ(metricLabel("mse"), "mse");  // no label of its own: the name
}

// A value the registry gains (the error-concentration values, say) is described without a change
// to the report: every declared value gets its metric's definition and a direction.
TEST(MetricLabels, EveryValueTheRegistryDeclaresIsDescribedFromIt) {
  for (const metrics::MetricInfo& metric : metrics::metricCatalogue())
    for (const metrics::MetricValueInfo& value : metric.values) {
      const std::string description = metricDescription(value.name);
      EXPECT_EQ(description.rfind(metric.description, 0), 0u) << value.name;
      EXPECT_NE(description.find(" better"), std::string::npos) << value.name;
      EXPECT_NE(metricLegend({value.name}).find(escapeHtml(metric.description)), std::string::npos)
          << value.name;
    }
  EXPECT_NE(metricDescription("a_removed_metric").find("not declared by the metric registry"),
            std::string::npos);
}

// Timings on the CPU clock with GPU timer-query samples beside them, as a precise-mode run
// records both.
metrics::PassTimings withGpuSamples(metrics::PassTimings timings) {
  for (metrics::PassTiming& pass : timings.passes) {
    for (double ms : pass.cpu_ms) pass.gpu_ms.push_back(0.5 * ms);
    pass.gpu_median_ms = 0.5 * pass.reported.median;
  }
  return timings;
}

TEST_F(HtmlReportPages, PassTableShowsGpuTimesBesideCpuTimesWithUnits) {
  results_.jobs[kPcf].timings = withGpuSamples(*results_.jobs[kPcf].timings);
  writeIndex();
  const std::string timings = section(page(kPcf), "timings");
  for (const char* heading : {">CPU median (ms)<", ">CPU first quartile (ms)<", ">GPU median (ms)<",
                              ">share of frame (%)<", ">calls per frame<"})
    EXPECT_NE(timings.find(heading), std::string::npos) << heading;
  // The frame: CPU 20 ms, GPU 10 ms beside it.
  EXPECT_NE(timings.find(">frame</span></td><td class=\"num\">20</td>"), std::string::npos);
  const std::string frame_row = between(timings, ">frame</span>", "</tr>");
  EXPECT_EQ(countOccurrences(frame_row, "<td class=\"num\">10</td>"), 1) << frame_row;
  // Without GPU samples, no GPU column.
  EXPECT_EQ(section(page(kVsm), "timings").find("GPU median"), std::string::npos);
  // A sub-millisecond frame in microseconds.
  results_.jobs[kVsm].timings = test::nestedPassTimings(0.01);
  writeIndex();
  const std::string fast = section(page(kVsm), "timings");
  EXPECT_NE(fast.find(">CPU median (\u00b5s)<"), std::string::npos);
  EXPECT_NE(fast.find(">frame</span></td><td class=\"num\">200</td>"), std::string::npos);
  // The charts beside the table in the same unit.
  EXPECT_NE(fast.find("\u00b5s per frame: median, whiskers"), std::string::npos);
  EXPECT_NE(fast.find("\u00b5s per frame: a dot per frame"), std::string::npos);
}

TEST_F(HtmlReportPages, TimingTablesHaveNoEmptyRows) {
  // A pass the measured frames never entered, and a job that neither iterates nor prepares.
  std::vector<test::SyntheticPass> passes = {{"frame", {20, 21, 22}, 1},
                                             {"frame/shading", {10, 11, 12}, 1},
                                             {"frame/never_taken", {0, 0, 0}, 0}};
  results_.jobs[kVsm].timings = test::syntheticTimings(passes, "cpu");
  results_.jobs[kVsm].prepare_ms = 0;
  writeIndex();
  const std::string timings = section(page(kVsm), "timings");
  EXPECT_NE(timings.find(">shading</span>"), std::string::npos);
  EXPECT_EQ(timings.find("never_taken"), std::string::npos);
  EXPECT_NE(timings.find("upload (scene to the GPU)"), std::string::npos);
  EXPECT_EQ(timings.find("prepare (precomputation)"), std::string::npos);
  EXPECT_EQ(timings.find("iterate ("), std::string::npos);
  EXPECT_EQ(timings.find("<td></td>"), std::string::npos);
  // The iterating job keeps its iterate row.
  EXPECT_NE(section(page(kPcf), "timings").find("iterate (8 iterations)"), std::string::npos);
}

TEST_F(HtmlReportPages, EveryFrameIsADotOfTheStripPlot) {
  writeIndex();
  const std::string html = page(kPcf);
  const std::string strip =
      between(section(html, "timings"), "aria-label=\"Each frame&#39;s time per pass", "</svg>");
  ASSERT_FALSE(strip.empty()) << section(html, "timings");
  // 8 measured frames × 5 passes.
  EXPECT_EQ(countOccurrences(strip, "<circle "), 40);
  EXPECT_NE(strip.find("<title>frame 8, shading: 11 ms</title>"), std::string::npos);
  // The iterations too, one dot per iteration.
  const std::string iterations = between(section(html, "iteration-timings"),
                                         "aria-label=\"Each iteration&#39;s time", "</svg>");
  EXPECT_EQ(countOccurrences(iterations, "<circle "), 40);
}

TEST_F(HtmlReportPages, JobPageLinksOnlyTheFullPrecisionFilesThatArePresent) {
  results::JobResult& pcf = results_.jobs[kPcf];
  pcf.outputs.reference_exr = "jobs/" + pcf.slug + "/reference.exr";
  pcf.outputs.full_reference_exr = "jobs/" + pcf.slug + "/full_reference.exr";
  for (const std::string& file :
       {pcf.outputs.image, pcf.outputs.reference_exr, pcf.outputs.timings_json})
    writeFile(dir_ / file);
  writeIndex();
  const std::string files = section(page(kPcf), "files");
  for (const std::string& file :
       {pcf.outputs.image, pcf.outputs.reference_exr, pcf.outputs.timings_json})
    EXPECT_NE(files.find("href=\"../" + file + "\""), std::string::npos) << file;
  EXPECT_EQ(files.find("full_reference.exr"), std::string::npos);  // listed, not written
  EXPECT_EQ(files.find("results.json"), std::string::npos);
  writeFile(dir_ / "results.json", "{}");
  writeFile(dir_ / pcf.outputs.full_reference_exr);
  writeIndex();
  const std::string all = section(page(kPcf), "files");
  EXPECT_NE(all.find("href=\"../results.json\""), std::string::npos);
  EXPECT_NE(all.find("href=\"../" + pcf.outputs.full_reference_exr + "\""), std::string::npos);
  // A job with none of them present has no such section.
  EXPECT_EQ(section(page(kVsm), "files").find("EXR"), std::string::npos);
  EXPECT_EQ(countOccurrences(page(kVsm), "id=\"files\""), 1);  // results.json, now present
}

TEST_F(HtmlReportPages, DisagreementMaskAndCountAreShownWhenPresent) {
  results::JobResult& pcf = results_.jobs[kPcf];
  pcf.disagreement_pixels = 42;
  pcf.outputs.disagreement_png = pcf.outputs.difference_png;  // any picture that is written
  writeIndex();
  const std::string html = section(page(kPcf), "disagreement");
  EXPECT_NE(html.find("<strong>42</strong> pixels (5.5%)"), std::string::npos) << html;  // of 768
  EXPECT_NE(html.find("src=\"../" + pcf.outputs.disagreement_png + "\""), std::string::npos);
  EXPECT_EQ(page(kVsm).find("id=\"disagreement\""), std::string::npos);  // not checked: -1
  // Listed but gone: the count stays, no broken picture.
  pcf.outputs.disagreement_png = "jobs/absent.png";
  writeIndex();
  const std::string count_only = section(page(kPcf), "disagreement");
  EXPECT_NE(count_only.find("<strong>42</strong>"), std::string::npos);
  EXPECT_EQ(count_only.find("<img"), std::string::npos);
  // No pixel disagrees: the count, and no black picture.
  pcf.disagreement_pixels = 0;
  pcf.outputs.disagreement_png = pcf.outputs.difference_png;
  writeIndex();
  const std::string none = section(page(kPcf), "disagreement");
  EXPECT_NE(none.find("<strong>0</strong> pixels (0.0%)"), std::string::npos) << none;
  EXPECT_EQ(none.find("<img"), std::string::npos);
}

TEST_F(HtmlReportPages, JobPageSaysTheReferencesPixelSampling) {
  results_.jobs[kVsm].reference.pixel_sampling = "area";
  writeIndex();
  EXPECT_NE(page(kPcf).find("against the reference of its class (L(D|S|P){0,1}E, pixel centres)"),
            std::string::npos);
  EXPECT_NE(page(kPcf).find("pixel sampling: pixel centres."), std::string::npos);
  EXPECT_NE(page(kVsm).find("(L(D|S|P){0,1}E, box-filtered over the pixel)"), std::string::npos);
}

TEST_F(HtmlReportPages, ReferenceJobSaysWhichCheckpointItComparesWithWhichReference) {
  results_.jobs[kReference].reference.spp = 1024;
  writeIndex();
  const std::string html = page(kReference);
  const std::string what = "the 256-spp checkpoint against the 1024-spp reference";
  EXPECT_NE(section(html, "metrics").find(what), std::string::npos) << section(html, "metrics");
  EXPECT_NE(html.find("<th scope=\"row\">compares</th><td>" + what), std::string::npos);
  EXPECT_EQ(section(html, "metrics").find("approximation error"), std::string::npos);
  // A technique job compares no checkpoint.
  EXPECT_EQ(page(kPcf).find("-spp checkpoint"), std::string::npos);
}

TEST_F(HtmlReportPages, ConvergenceChartNamesTheMetricItFits) {
  results::Convergence& c = *results_.jobs[kPcf].convergence;
  for (results::Convergence::Point& point : c.points)
    point.metrics.insert(point.metrics.begin(), {"mse", 0.5 * point.metrics[0].second});
  c.fit_metric = "mse";
  writeIndex();
  const std::string convergence = section(page(kPcf), "convergence");
  EXPECT_NE(convergence.find("aria-label=\"Convergence of mse (fitted)\""), std::string::npos);
  EXPECT_NE(convergence.find(">mse: slope \u22120.98"), std::string::npos) << convergence;
  EXPECT_NE(convergence.find("The fit follows <span class=\"metric-name\""), std::string::npos);
  EXPECT_EQ(convergence.find(">relmse: slope"), std::string::npos);
}

TEST_F(HtmlReportPages, NewPartsKeepThePagesWellFormed) {
  results::JobResult& pcf = results_.jobs[kPcf];
  pcf.disagreement_pixels = 3;
  pcf.outputs.disagreement_png = pcf.outputs.difference_png;
  pcf.timings = withGpuSamples(*pcf.timings);
  writeIndex();
  for (const std::string& html : allPages()) EXPECT_EQ(test::markupProblem(html), "");
}

TEST(ReportLabels, FileUrlsAreAbsoluteAndPercentEncoded) {
  EXPECT_EQ(fileUrl("/tmp/a run/index.html"), "file:///tmp/a%20run/index.html");
  EXPECT_EQ(fileUrl("/tmp/x/../runs/#1/index.html"), "file:///tmp/runs/%231/index.html");
  const std::string relative = fileUrl("runs/smoke/index.html");
  EXPECT_EQ(relative.rfind("file:///", 0), 0u) << relative;
  EXPECT_NE(relative.find(urlPath(fs::current_path().generic_string()) + "/runs/smoke/index.html"),
            std::string::npos)
      << relative;
}

}  // namespace
}  // namespace gib::reports
