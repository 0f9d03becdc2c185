#include "reports/html_report.h"

#include "common/input_error.h"
#include "reports/figure_panels.h"
#include "support/markup_check.h"
#include "support/read_text.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;
using test::countOccurrences;
using test::readText;

// Every value of `attribute` ("href", "src") in the page.
std::vector<std::string> attributeValues(const std::string& html, const std::string& attribute) {
  std::vector<std::string> values;
  const std::regex pattern(" " + attribute + "=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), pattern);
       it != std::sregex_iterator(); ++it)
    values.push_back((*it)[1]);
  return values;
}

// A link of the report as the file it names (the synthetic ids need no percent-decoding beyond
// what this test checks separately).
fs::path linkedFile(const fs::path& page, const std::string& link) {
  return (page.parent_path() / link).lexically_normal();
}

class HtmlReport : public ::testing::Test {
 protected:
  void SetUp() override {
    results_ = test::syntheticReportResults();
    test::writeSyntheticOutputs(dir_.path(), results_);
  }
  fs::path write(const ReportContext& context = {}) {
    return writeHtmlReport(dir_.path(), results_, context);
  }
  std::string jobPage(std::size_t job) const {
    return readText(dir_ / "report" / (results_.jobs[job].slug + ".html"));
  }

  test::TempDir dir_;
  results::RunResults results_;
};

TEST_F(HtmlReport, WritesAWellFormedIndexAndOnePagePerJobWhoseLinksResolve) {
  const fs::path index = write();
  EXPECT_EQ(index, dir_ / "index.html");
  std::vector<fs::path> pages = {index};
  for (const results::JobResult& job : results_.jobs)
    pages.push_back(dir_ / "report" / (job.slug + ".html"));
  ASSERT_FALSE(results_.figures.empty());
  for (const results::FigureSpec& figure : results_.figures)
    pages.push_back(dir_ / figurePageFile(figure));
  for (const fs::path& page : pages) {
    ASSERT_TRUE(fs::is_regular_file(page)) << page;
    const std::string html = readText(page);
    EXPECT_EQ(test::markupProblem(html), "") << page;
    EXPECT_NE(html.find("data-report-check"), std::string::npos) << "self-check script";
    for (const std::string attribute : {"href", "src"})
      for (const std::string& link : attributeValues(html, attribute)) {
        if (link.rfind("data:", 0) == 0) continue;
        EXPECT_TRUE(fs::exists(linkedFile(page, link))) << page << " links to " << link;
      }
  }
  const std::string html = readText(index);
  for (const results::JobResult& job : results_.jobs)
    EXPECT_NE(html.find("href=\"report/" + job.slug + ".html\""), std::string::npos) << job.id;
  // Nothing but the report was added: no temporary files left beside the pages.
  std::size_t report_files = 0;
  for (const auto& entry : fs::directory_iterator(dir_ / "report")) {
    EXPECT_EQ(entry.path().extension(), ".html") << entry.path();
    ++report_files;
  }
  EXPECT_EQ(report_files, results_.jobs.size() + results_.figures.size());
}

TEST_F(HtmlReport, IndexShowsTheRunAndAMatrixOfScenesByTechniquesWithTheReferenceFirst) {
  std::swap(results_.jobs[0], results_.jobs[2]);  // the reference job last in suite order
  const std::string html = readText(write());
  for (const char* fact : {"20261122-100405-smoke-1a2b3c4d", "0123456789abcdef",
                           "llvmpipe (LLVM 15.0.6, 256 bits)", "3.13.5", "Release", "testhost",
                           "Test CPU @ 3 GHz (2 cores)", "/tmp/store", "0.1.0+0123456789ab"})
    EXPECT_NE(html.find(fact), std::string::npos) << fact;
  const std::size_t matrix = html.find("class=\"matrix\"");
  ASSERT_NE(matrix, std::string::npos);
  const std::size_t reference = html.find("<th>reference</th>", matrix);
  const std::size_t direct = html.find("<th>direct</th>", matrix);
  ASSERT_NE(reference, std::string::npos);
  ASSERT_NE(direct, std::string::npos);
  EXPECT_LT(reference, direct);
  EXPECT_EQ(countOccurrences(html, "<td>cornell</td>"), 1);  // one row per scene
  // Each job's entry: sweep label, primary metric value, frame median.
  EXPECT_NE(html.find(">shadow=pcf,light_samples=4</a>"), std::string::npos);
  EXPECT_NE(html.find("0.0021"), std::string::npos);
  EXPECT_NE(html.find("20 ms"), std::string::npos);
  EXPECT_NE(html.find("30 ms"), std::string::npos);  // the vsm job runs 1.5× longer
  EXPECT_NE(html.find("nothing is coloured"), std::string::npos);
  EXPECT_EQ(html.find("class=\"job verdict-regressed"), std::string::npos);
}

TEST_F(HtmlReport, JobIdsAndTextAreEscapedEverywhere) {
  results_.jobs[1].id = "cornell-direct/label=<b>&\"x\"";
  results_.jobs[1].parameters = {{"label", "<b>&\"x\""}};
  results_.paper.clear();
  write();
  for (const std::string& html : {readText(dir_ / "index.html"), jobPage(1)}) {
    EXPECT_EQ(html.find("<b>"), std::string::npos);
    EXPECT_NE(html.find("label=&lt;b&gt;&amp;&quot;x&quot;"), std::string::npos);
    EXPECT_EQ(test::markupProblem(html), "");
  }
  EXPECT_NE(readText(dir_ / "index.html").find("&lt;shadow maps&gt; &amp; friends"),
            std::string::npos);
}

TEST_F(HtmlReport, JobPageHasMetricsImagesTimingsConvergenceAndPaperValues) {
  write();
  const std::string html = jobPage(1);
  // Metric tables against the class and the full reference.
  EXPECT_NE(html.find("against the reference of its class (L(D|S|P){0,1}E, "), std::string::npos);
  EXPECT_NE(html.find("against the full reference (all paths, "), std::string::npos);
  EXPECT_NE(html.find("0.0084"), std::string::npos);  // 4 × relmse against all paths
  // The viewer with its four pictures and the FLIP colour bar.
  for (const char* layer : {"reference", "image", "difference", "flip"})
    EXPECT_NE(html.find(std::string("data-layer=\"") + layer + "\" src="), std::string::npos)
        << layer;
  EXPECT_NE(html.find("FLIP error colour bar"), std::string::npos);
  // Per-pass table: names indented by depth, share, calls; the bar chart.
  EXPECT_NE(html.find("padding-left:2.4em\">cube_faces"), std::string::npos);
  EXPECT_NE(html.find("30.0%"), std::string::npos);  // shadow maps: 6 of 20 ms
  // GPU commands per frame, the frame's first: 30 draws and dispatches.
  EXPECT_NE(html.find("GPU commands per frame"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">1</td><td class=\"num\">30</td>"), std::string::npos);
  EXPECT_NE(html.find("Median time per pass in ms"), std::string::npos);
  EXPECT_NE(html.find("upload (scene to the GPU)"), std::string::npos);
  // Convergence with its slope; the paper's numbers beside ours with the ratio.
  EXPECT_NE(html.find("slope \u22120.98 \u00b1 0.03"), std::string::npos);
  EXPECT_NE(html.find("Nijasure et al. 2005, Table 1"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">40 ms</td><td class=\"num\">20 ms</td><td "
                      "class=\"num\">0.5</td>"),
            std::string::npos);
  EXPECT_NE(html.find("href=\"../index.html\""), std::string::npos);
}

TEST_F(HtmlReport, FigureSuitesShowChartsIterationTimingsAndAuxiliaryImages) {
  const std::string index = readText(write());
  // The index's figures: both charts, a series per shadow filter, the front, the paper table.
  EXPECT_NE(index.find("id=\"figures\""), std::string::npos);
  EXPECT_NE(index.find(">Frame time against vertex count<"), std::string::npos);
  EXPECT_NE(index.find(">shadow = pcf<"), std::string::npos);
  EXPECT_NE(index.find(">shadow = vsm<"), std::string::npos);
  EXPECT_NE(index.find(">Pareto front<"), std::string::npos);
  EXPECT_NE(index.find(">Radeon 9800 Pro<"), std::string::npos);
  EXPECT_EQ(test::markupProblem(index), "");

  const std::string pcf = jobPage(1);
  EXPECT_NE(pcf.find("id=\"iteration-timings\""), std::string::npos);
  EXPECT_NE(pcf.find("ms per iteration: median"), std::string::npos);
  EXPECT_NE(pcf.find("share of iteration"), std::string::npos);
  EXPECT_NE(pcf.find("src=\"../jobs/" + results_.jobs[1].slug + "/image-atlas.png\""),
            std::string::npos);
  EXPECT_NE(pcf.find("the radiance atlas after 8 iterations"), std::string::npos);
  EXPECT_NE(pcf.find("vertices 3000, atlas_texels 16000"), std::string::npos) << pcf;
  // A job that does not iterate has neither.
  const std::string vsm = jobPage(2);
  EXPECT_EQ(vsm.find("id=\"iteration-timings\""), std::string::npos);
  EXPECT_EQ(vsm.find("id=\"auxiliary\""), std::string::npos);
}

TEST_F(HtmlReport, MissingOptionalOutputsAreOmittedNotBroken) {
  fs::remove(dir_ / results_.jobs[1].outputs.difference_png);  // listed, but gone
  write();
  const std::string reference = jobPage(0);
  EXPECT_EQ(reference.find("data-layer=\"flip\""), std::string::npos);
  EXPECT_EQ(reference.find("id=\"timings\""), std::string::npos);
  EXPECT_EQ(reference.find("id=\"paper\""), std::string::npos);
  EXPECT_EQ(reference.find("id=\"trends\""), std::string::npos);
  EXPECT_NE(reference.find("id=\"convergence\""), std::string::npos);
  const std::string pcf = jobPage(1);
  EXPECT_EQ(pcf.find("data-layer=\"difference\""), std::string::npos);
  EXPECT_NE(
      pcf.find("absent when the report was written: " + results_.jobs[1].outputs.difference_png),
      std::string::npos);

  results_.jobs[1].convergence.reset();
  results_.jobs[1].outputs = {};
  results_.jobs[1].auxiliary_images.clear();
  write();
  const std::string bare = jobPage(1);
  EXPECT_EQ(bare.find("<img"), std::string::npos);
  EXPECT_EQ(bare.find("id=\"convergence\""), std::string::npos);
  EXPECT_NE(bare.find("No pictures were written for this job."), std::string::npos);
}

TEST_F(HtmlReport, ValuesAreColouredAgainstThePreviousRunAndRegressionsListed) {
  ReportContext context;
  context.previous = test::syntheticReportResults("20261121-100405-smoke-00000000", "fedcba98");
  context.previous->jobs[1].metrics[0].second = 0.0010;  // pcf's relmse doubled since: worse
  context.previous->jobs[2].metrics[0].second = 0.0100;  // vsm's fell to a third: better
  const std::string html = readText(write(context));
  EXPECT_NE(html.find("20261121-100405-smoke-00000000"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"verdict-regressed\">0.0021</span> <small>(+110.0%)</small>"),
            std::string::npos);
  EXPECT_NE(html.find("<span class=\"verdict-improved\">0.0035</span>"), std::string::npos);
  EXPECT_EQ(countOccurrences(html, "class=\"job verdict-regressed\""), 1);
  EXPECT_EQ(countOccurrences(html, "class=\"job verdict-improved\""), 1);
  const std::size_t regressions = html.find("id=\"regressions\"");
  ASSERT_NE(regressions, std::string::npos);
  EXPECT_NE(html.find("cornell-direct/shadow=pcf,light_samples=4</a>", regressions),
            std::string::npos);
  EXPECT_NE(html.find("legend"), std::string::npos);
  EXPECT_NE(jobPage(1).find("<span class=\"verdict-regressed\">0.0021</span>"), std::string::npos);
}

TEST_F(HtmlReport, TrendChartsFollowTheJobOverTheHistory) {
  ReportContext context;
  for (int i = 0; i < 3; ++i) {
    results::RunResults run = test::syntheticReportResults("run-" + std::to_string(i),
                                                           "abcdef" + std::to_string(i) + "00");
    run.jobs[1].metrics[0].second = 0.001 * (i + 1);
    context.history.push_back(run);
  }
  write(context);
  const std::string html = jobPage(1);
  ASSERT_NE(html.find("id=\"trends\""), std::string::npos);
  EXPECT_NE(html.find("relmse over the last 4 runs"), std::string::npos);  // history + this run
  EXPECT_NE(html.find("Median frame time over the last 4 runs"), std::string::npos);
  ASSERT_GE(results_.jobs[1].metrics.size(), 2u);
  for (const auto& [name, value] : results_.jobs[1].metrics)  // a trend of each metric
    EXPECT_NE(html.find(name + " over the last 4 runs"), std::string::npos) << name;
  for (const char* commit : {">abcdef0<", ">abcdef1<", ">abcdef2<", ">0123456<"})
    EXPECT_NE(html.find(commit), std::string::npos) << commit;
  // The reference job has no frame times: only its metric's trend.
  const std::string reference = jobPage(0);
  EXPECT_NE(reference.find("relmse over the last 4 runs"), std::string::npos);
  EXPECT_EQ(reference.find("Median frame time over"), std::string::npos);

  context.history.resize(1);
  context.history[0] = results_;  // only this run: nothing to trend
  write(context);
  EXPECT_EQ(jobPage(1).find("id=\"trends\""), std::string::npos);
}

TEST_F(HtmlReport, SlugsThatAreNotFileNamesAreInputErrorsAndNothingIsWritten) {
  for (const std::string slug : {"../escape", "", "a/b", ".."}) {
    results::RunResults bad = results_;
    bad.jobs[1].slug = slug;
    EXPECT_THROW(writeHtmlReport(dir_.path(), bad, {}), InputError) << slug;
  }
  results::RunResults twice = results_;
  twice.jobs[2].slug = twice.jobs[1].slug;
  try {
    writeHtmlReport(dir_.path(), twice, {});
    ADD_FAILURE() << "two jobs with one slug were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(twice.jobs[1].slug), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(dir_ / "index.html"));
  EXPECT_FALSE(fs::exists(dir_ / "report"));
  EXPECT_FALSE(fs::exists(dir_.path().parent_path() / "escape.html"));
}

TEST_F(HtmlReport, AMissingRunDirectoryIsAnInputError) {
  EXPECT_THROW(writeHtmlReport(dir_ / "absent", results_, {}), InputError);
  EXPECT_FALSE(fs::exists(dir_ / "absent"));
}

}  // namespace
}  // namespace gib::reports
