// The report in a real browser: every page of a synthetic run loads in headless Chromium without
// console errors, and the page's own self-check finds every image decoded and every chart drawn.
// The negative tests show that both checks can fail.
#include "reports/html_report.h"

#include "image/output_files.h"
#include "reports/figure_panels.h"
#include "support/headless_browser.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;

std::string describe(const test::LoadedPage& page) {
  return "exit " + std::to_string(page.exit_code) + "\nlog:\n" + page.log;
}

class HtmlReportBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    results_ = test::syntheticReportResults();
    // The parts that say what a page compares: a pixel-centre reference, a disagreement mask,
    // GPU timer-query times beside the CPU clock (so the GPU column and the strip plot are drawn).
    results::JobResult& pcf = results_.jobs[1];
    pcf.reference.pixel_sampling = "center";
    pcf.disagreement_pixels = 12;
    pcf.outputs.disagreement_png = pcf.outputs.difference_png;
    for (metrics::PassTiming& pass : pcf.timings->passes) {
      pass.gpu_ms = pass.cpu_ms;
      pass.gpu_median_ms = pass.reported.median;
    }
    test::writeSyntheticOutputs(run_dir_, results_);
    ReportContext context;
    context.previous = test::syntheticReportResults("20261121-100405-smoke-00000000", "fedcba98");
    context.previous->jobs[1].metrics[0].second = 0.001;  // a regression to colour
    context.history = {*context.previous};                // two runs: trend charts
    index_ = writeHtmlReport(run_dir_, results_, context);
  }

  test::TempDir dir_;
  fs::path run_dir_ = dir_.path();
  results::RunResults results_;
  fs::path index_;
};

TEST_F(HtmlReportBrowser, EveryPageLoadsWithoutConsoleErrorsAndPassesItsSelfCheck) {
  GIB_REQUIRE_CHROMIUM(chromium);
  std::vector<fs::path> pages = {index_};
  for (const results::JobResult& job : results_.jobs)
    pages.push_back(run_dir_ / "report" / (job.slug + ".html"));
  // The figure pages too: the synthetic run has a figure (with a panel whose picture is absent).
  ASSERT_FALSE(results_.figures.empty());
  for (const results::FigureSpec& figure : results_.figures)
    pages.push_back(run_dir_ / figurePageFile(figure));
  for (const fs::path& page : pages) {
    SCOPED_TRACE(page.string());
    const test::LoadedPage loaded = test::loadPage(*chromium, page, dir_.path());
    ASSERT_EQ(loaded.exit_code, 0) << describe(loaded);
    EXPECT_EQ(test::reportCheck(loaded.dom), "ok") << describe(loaded);
    EXPECT_EQ(test::consoleProblems(loaded.log), std::vector<std::string>{}) << describe(loaded);
  }
}

TEST_F(HtmlReportBrowser, WhatAJobPageComparesSurvivesItsScripts) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const results::JobResult& job = results_.jobs[1];
  const test::LoadedPage loaded =
      test::loadPage(*chromium, run_dir_ / "report" / (job.slug + ".html"), dir_.path());
  ASSERT_EQ(loaded.exit_code, 0) << describe(loaded);
  EXPECT_EQ(test::reportCheck(loaded.dom), "ok") << describe(loaded);
  // Tooltips and legend, the renderer's flag, the mask and the strip plot's dots, as drawn.
  EXPECT_NE(loaded.dom.find("<span class=\"metric-name\" title=\"relative MSE"), std::string::npos);
  EXPECT_NE(loaded.dom.find("<table class=\"metric-legend\">"), std::string::npos);
  EXPECT_NE(loaded.dom.find("class=\"renderer software-renderer\""), std::string::npos);
  EXPECT_NE(loaded.dom.find("<img class=\"disagreement\""), std::string::npos);
  EXPECT_NE(loaded.dom.find("<title>frame 8, shading: 11 ms</title>"), std::string::npos);
}

TEST_F(HtmlReportBrowser, APageWithAMissingPictureFailsItsSelfCheck) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const results::JobResult& job = results_.jobs[1];
  fs::remove(run_dir_ / job.outputs.flip_png);  // a report copied without one of its images
  const test::LoadedPage loaded =
      test::loadPage(*chromium, run_dir_ / "report" / (job.slug + ".html"), dir_.path());
  ASSERT_EQ(loaded.exit_code, 0) << describe(loaded);
  const std::string check = test::reportCheck(loaded.dom);
  EXPECT_EQ(check.rfind("failed: ", 0), 0u) << check;
  EXPECT_NE(check.find("flip.png"), std::string::npos) << check;
  // The reader sees it too: the banner is shown with the same message.
  EXPECT_NE(loaded.dom.find("This page is incomplete"), std::string::npos);
}

TEST_F(HtmlReportBrowser, ConsoleErrorsOfAPageAreFound) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const fs::path page = dir_ / "broken.html";
  image::writeTextFile(page,
                       "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><link rel=\"icon\" "
                       "href=\"data:,\"></head><body><script>console.error('broken report'); "
                       "undefinedFunction();</script></body></html>");
  const test::LoadedPage loaded = test::loadPage(*chromium, page, dir_.path());
  ASSERT_EQ(loaded.exit_code, 0) << describe(loaded);
  const std::vector<std::string> problems = test::consoleProblems(loaded.log);
  ASSERT_EQ(problems.size(), 2u) << describe(loaded);
  EXPECT_NE(problems[0].find("broken report"), std::string::npos);
  EXPECT_NE(problems[1].find("Uncaught ReferenceError"), std::string::npos);
  EXPECT_EQ(test::reportCheck(loaded.dom), "");  // no self-check on this page
}

}  // namespace
}  // namespace gib::reports
