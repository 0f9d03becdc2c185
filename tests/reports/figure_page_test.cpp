// A figure suite's [[figure]] in the report: its page (panels in their declared cells with
// captions and numbers, a note for a picture the run lacks, the paper's values and charts of the
// figure's jobs only), the index's link to it, and the standalone files of figures/ (the panels
// composited into one PNG, every chart as an SVG document).
#include "reports/figure_page.h"

#include "common/input_error.h"
#include "image/display_png.h"
#include "reports/figure_charts.h"
#include "reports/figure_composite.h"
#include "reports/figure_panels.h"
#include "reports/html_report.h"
#include "reports/html_text.h"
#include "reports/number_format.h"
#include "support/markup_check.h"
#include "support/read_text.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"
#include "support/xml_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;
using test::readText;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

class FigurePage : public ::testing::Test {
 protected:
  void SetUp() override {
    results_ = test::syntheticReportResults();
    test::writeSyntheticOutputs(dir_.path(), results_);
  }
  const results::FigureSpec& figure() const { return results_.figures.at(0); }
  const results::JobResult& job(const std::string& id) const { return *results_.findJob(id); }
  std::string write() {
    writeHtmlReport(dir_.path(), results_, {});
    return readText(dir_ / figurePageFile(figure()));
  }

  // The HTML of the panel in cell (row, column): from its element to the next panel's or the end
  // of the grid.
  static std::string cell(const std::string& page, int row, int column) {
    const std::string start = "<div class=\"figure-panel\" data-row=\"" + std::to_string(row) +
                              "\" data-column=\"" + std::to_string(column) + "\"";
    const std::size_t at = page.find(start);
    if (at == std::string::npos) return {};
    std::size_t end = page.find("<div class=\"figure-panel\"", at + start.size());
    if (end == std::string::npos) end = page.find("</figure>", at);
    return page.substr(at, end - at);
  }

  test::TempDir dir_;
  results::RunResults results_;
};

TEST_F(FigurePage, PanelsSitInTheirDeclaredCellsWithCaptionsAndNumbers) {
  const std::string page = write();
  EXPECT_EQ(test::markupProblem(page), "");
  EXPECT_THAT(page, HasSubstr("<h1>" + escapeHtml(figure().title) + "</h1>"));
  EXPECT_THAT(page, HasSubstr("<figcaption>" + escapeHtml(figure().caption) + "</figcaption>"));
  EXPECT_THAT(page, HasSubstr("grid-template-columns: repeat(" + std::to_string(figure().columns) +
                              ", auto)"));
  EXPECT_EQ(test::countOccurrences(page, "<div class=\"figure-panel\""),
            int(figure().panels.size()));
  for (const results::FigureSpec::Panel& panel : figure().panels) {
    const std::string html = cell(page, panel.row, panel.column);
    SCOPED_TRACE(panel.caption);
    ASSERT_FALSE(html.empty());
    EXPECT_THAT(html, HasSubstr("style=\"grid-row: " + std::to_string(panel.row) +
                                "; grid-column: " + std::to_string(panel.column) + "\""));
    EXPECT_THAT(
        html, HasSubstr("<p class=\"figure-panel-caption\">" + escapeHtml(panel.caption) + "</p>"));
    // Every panel links its job's page.
    EXPECT_THAT(html, HasSubstr("href=\"../report/" + job(panel.job).slug + ".html\""));
  }
  const results::JobResult& reference = job(figure().panels[0].job);
  const results::JobResult& pcf = job(figure().panels[1].job);

  // (1, 1): the reference's image with the run's primary metric (no metric given).
  const std::string path_traced = cell(page, 1, 1);
  EXPECT_THAT(path_traced, HasSubstr("src=\"../" + reference.outputs.image_png + "\""));
  EXPECT_THAT(path_traced, HasSubstr(results_.primary_metric + ": " +
                                     formatNumber(*reference.metric(results_.primary_metric))));
  // (1, 2): the PCF image with its median frame time.
  const std::string pcf_image = cell(page, 1, 2);
  EXPECT_THAT(pcf_image, HasSubstr("src=\"../" + pcf.outputs.image_png + "\""));
  EXPECT_THAT(pcf_image, HasSubstr("frame: " + formatNumber(*pcf.frameMedianMs()) + " ms"));
  // (2, 2): the PCF job's atlas with the relmse against the full reference.
  const std::string atlas = cell(page, 2, 2);
  EXPECT_THAT(atlas, HasSubstr("src=\"../" + pcf.auxiliary_images.at(0).png + "\""));
  EXPECT_THAT(atlas, HasSubstr("relmse against the full reference: " +
                               formatNumber(pcf.metrics_full.at(0).second)));
  // (2, 1): the reference job has no atlas: a note instead of a picture, and metric "none".
  const std::string missing = cell(page, 2, 1);
  EXPECT_THAT(missing, Not(HasSubstr("<img")));
  EXPECT_THAT(missing, HasSubstr("class=\"figure-absent\">" +
                                 escapeHtml("No picture: job '" + reference.id +
                                            "' has no auxiliary image 'atlas' (it has none).") +
                                 "</div>"));
  EXPECT_THAT(missing, Not(HasSubstr("figure-panel-value")));
}

TEST_F(FigurePage, APictureListedButGoneOrAJobNotRunGetsANoteNotABrokenImage) {
  const results::JobResult& pcf = job(figure().panels[1].job);
  fs::remove(dir_ / pcf.outputs.image_png);
  results_.figures[0].panels[2].job = "cornell-direct/shadow=none";  // not in this run
  const std::string page = write();
  EXPECT_THAT(cell(page, 1, 2),
              HasSubstr("No picture: " + pcf.outputs.image_png +
                        " is listed in the results but was absent when the report was written"));
  const std::string absent_job = cell(page, 2, 1);
  EXPECT_THAT(
      absent_job,
      HasSubstr(escapeHtml("No picture: job 'cornell-direct/shadow=none' is not in this run")));
  EXPECT_THAT(absent_job, HasSubstr("figure-panel-job muted\">cornell-direct/shadow=none"));
  EXPECT_THAT(page, Not(HasSubstr("src=\"../" + pcf.outputs.image_png)));
}

TEST_F(FigurePage, ThePaperTableAndTheChartsAreThoseOfTheFiguresJobs) {
  // A paper value and a chart of the vsm job, which is in no panel.
  const results::JobResult& vsm = results_.jobs[2];
  ASSERT_EQ(std::count_if(figure().panels.begin(), figure().panels.end(),
                          [&](const auto& panel) { return panel.job == vsm.id; }),
            0);
  results::PaperValue value;
  value.job = vsm.id;
  value.quantity = "relmse";
  value.value = 0.004;
  value.source = "Vsm source";
  value.note = "a value of the vsm job";
  results_.paper.push_back(value);
  results::ChartSpec chart;
  chart.title = "VSM alone";
  chart.jobs = vsm.id;
  chart.x = "frame";
  chart.y = "relmse";
  results_.charts.push_back(chart);

  const std::string page = write();
  // Both paper rows of the PCF job, linked to its page from report/.
  const std::string pcf_link = "<a href=\"../report/" + results_.jobs[1].slug + ".html\">";
  EXPECT_EQ(test::countOccurrences(page, "<td>" + pcf_link), 2) << page;
  EXPECT_THAT(page, HasSubstr("Radeon 9800 Pro"));
  EXPECT_THAT(page, Not(HasSubstr("a value of the vsm job")));
  // The charts whose glob matches a job of the figure, each with its SVG; not the vsm one.
  const std::vector<std::string> slugs = chartSlugs(results_.charts);
  EXPECT_THAT(page, HasSubstr(">" + results_.charts[0].title + "<"));
  EXPECT_THAT(page, HasSubstr(">" + results_.charts[1].title + "<"));
  EXPECT_THAT(page, HasSubstr("href=\"../figures/" + slugs[0] + ".svg\""));
  EXPECT_THAT(page, HasSubstr("href=\"../figures/" + slugs[1] + ".svg\""));
  EXPECT_THAT(page, Not(HasSubstr(">VSM alone<")));
  EXPECT_THAT(page, Not(HasSubstr(slugs[2])));
  // The index still shows all of them.
  const std::string index = readText(dir_ / "index.html");
  EXPECT_THAT(index, HasSubstr("a value of the vsm job"));
  EXPECT_THAT(index, HasSubstr(">VSM alone<"));
}

TEST_F(FigurePage, TheIndexLinksEachFigureWithItsFirstPictureAsPreview) {
  write();
  const std::string index = readText(dir_ / "index.html");
  const std::size_t link =
      index.find("<a class=\"figure-link\" href=\"report/figure-" + figure().name + ".html\">");
  ASSERT_NE(link, std::string::npos) << index;
  const std::string preview =
      "<img src=\"" + job(figure().panels[0].job).outputs.image_png + "\" alt=\"\">";
  // The preview is there, and no other picture comes between the link and it.
  const std::size_t at = index.find(preview, link);
  ASSERT_NE(at, std::string::npos) << index;
  EXPECT_EQ(at, index.find("<img", link));
  EXPECT_THAT(index, HasSubstr("<span>" + escapeHtml(figure().title) + "</span>"));
}

TEST_F(FigurePage, TheCompositePngHasEveryPanelCentredInItsCellWithWhiteGaps) {
  const std::string page = write();
  const fs::path file = dir_ / figurePngFile(figure());
  ASSERT_TRUE(fs::is_regular_file(file));
  EXPECT_THAT(page, HasSubstr("href=\"../" + figurePngFile(figure()) + "\">PNG</a>"));
  const image::DisplayPicture composite = image::readDisplayPng(file);

  // The panels' own pictures, by cell; the cell without one has no size.
  std::map<std::pair<int, int>, image::DisplayPicture> pictures;
  for (const results::FigureSpec::Panel& panel : figure().panels) {
    const PanelPicture picture = panelPicture(dir_.path(), results_, panel);
    if (!picture.path.empty())
      pictures[{panel.row, panel.column}] = image::readDisplayPng(dir_ / picture.path);
  }
  ASSERT_EQ(pictures.size(), 3u);
  int rows = 0;
  for (const results::FigureSpec::Panel& panel : figure().panels) rows = std::max(rows, panel.row);
  std::vector<int> widths(std::size_t(figure().columns), 0), heights(std::size_t(rows), 0);
  for (const auto& [cell, picture] : pictures) {
    heights[std::size_t(cell.first - 1)] =
        std::max(heights[std::size_t(cell.first - 1)], picture.height);
    widths[std::size_t(cell.second - 1)] =
        std::max(widths[std::size_t(cell.second - 1)], picture.width);
  }
  auto start = [](const std::vector<int>& sizes, int index) {
    int at = 0;
    for (int i = 0; i < index; ++i) at += sizes[std::size_t(i)] + kFigureGapPixels;
    return at;
  };
  EXPECT_EQ(composite.width, start(widths, figure().columns) - kFigureGapPixels);
  EXPECT_EQ(composite.height, start(heights, rows) - kFigureGapPixels);
  // The synthetic atlas is smaller than the images: centring is seen.
  ASSERT_LT(pictures.at({2, 2}).width, widths[1]);

  for (const auto& [cell, picture] : pictures) {
    SCOPED_TRACE(testing::Message() << "cell " << cell.first << ", " << cell.second);
    const int x0 =
        start(widths, cell.second - 1) + (widths[std::size_t(cell.second - 1)] - picture.width) / 2;
    const int y0 = start(heights, cell.first - 1) +
                   (heights[std::size_t(cell.first - 1)] - picture.height) / 2;
    int differing = 0;
    for (int y = 0; y < picture.height; ++y)
      for (int x = 0; x < picture.width; ++x)
        differing += !std::equal(picture.pixel(x, y), picture.pixel(x, y) + 3,
                                 composite.pixel(x0 + x, y0 + y));
    EXPECT_EQ(differing, 0);
  }
  // White between the columns and in the cell without a picture.
  auto white = [&](int x, int y) {
    const std::uint8_t* p = composite.pixel(x, y);
    return p[0] == 255 && p[1] == 255 && p[2] == 255;
  };
  for (int y = 0; y < composite.height; ++y)
    for (int x = widths[0]; x < widths[0] + kFigureGapPixels; ++x)
      ASSERT_TRUE(white(x, y)) << x << "," << y;
  const int row2 = start(heights, 1);
  for (int y = row2; y < row2 + heights[1]; ++y)
    for (int x = 0; x < widths[0]; ++x) ASSERT_TRUE(white(x, y)) << x << "," << y;
}

TEST_F(FigurePage, AFigureWithoutAnyPictureHasNoPngAndSaysSo) {
  write();
  ASSERT_TRUE(fs::exists(dir_ / figurePngFile(figure())));
  for (results::FigureSpec::Panel& panel : results_.figures[0].panels) panel.job = "not-run";
  const std::string page = write();
  EXPECT_FALSE(fs::exists(dir_ / figurePngFile(figure()))) << "an older composite is removed";
  EXPECT_THAT(page, HasSubstr("No picture of the whole figure"));
  EXPECT_THAT(page, Not(HasSubstr("<img")));
  const std::string index = readText(dir_ / "index.html");
  EXPECT_THAT(index, HasSubstr("href=\"report/figure-" + figure().name + ".html\"><span>"));
}

TEST_F(FigurePage, EveryChartIsAStandaloneWellFormedSvgFile) {
  write();
  const std::vector<std::string> slugs = chartSlugs(results_.charts);
  ASSERT_EQ(slugs.size(), results_.charts.size());
  for (std::size_t i = 0; i < results_.charts.size(); ++i) {
    SCOPED_TRACE(results_.charts[i].title);
    EXPECT_EQ(chartSvgFile(results_, i), "figures/" + slugs[i] + ".svg");
    const std::string svg = readText(dir_ / chartSvgFile(results_, i));
    EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ", 0), 0u);
    // Well-formed XML (a parser refuses what a page forgives, such as an attribute given twice),
    // an <svg> root in the SVG namespace, titled.
    test::XmlElement root;
    ASSERT_NO_THROW(root = test::parseXml(svg));
    EXPECT_EQ(root.name, "svg");
    EXPECT_EQ(root.at("xmlns"), "http://www.w3.org/2000/svg");
    ASSERT_NE(root.child("title"), nullptr);
    EXPECT_EQ(root.child("title")->text, results_.charts[i].title);
  }
  EXPECT_THROW(test::parseXml("<svg a=\"1\" a=\"2\"/>"), std::runtime_error);
}

TEST(FigureFiles, ChartSlugsFollowTheTitlesAndStayDistinct) {
  std::vector<results::ChartSpec> charts(4);
  charts[0].title = "Fig. 6: Error — against iterations!";
  charts[1].title = "Fig. 6: error against iterations";
  charts[2].title = "²";
  charts[3].title = "fig 6 error against iterations";
  EXPECT_THAT(chartSlugs(charts),
              ElementsAre("fig-6-error-against-iterations", "fig-6-error-against-iterations-2",
                          "chart-3", "fig-6-error-against-iterations-3"));
}

TEST_F(FigurePage, FigureNamesThatAreNoFileNamesOrRepeatedAreRefused) {
  results_.figures[0].name = "../escape";
  EXPECT_THROW(writeHtmlReport(dir_.path(), results_, {}), InputError);
  results_.figures[0].name = "twice";
  results_.figures.push_back(results_.figures[0]);
  EXPECT_THROW(writeHtmlReport(dir_.path(), results_, {}), InputError);
  results_.figures.resize(1);
  results_.figures[0].name = "x";
  results_.jobs[0].slug = "figure-x";  // the figure's page would be the job's
  EXPECT_THROW(writeHtmlReport(dir_.path(), results_, {}), InputError);
}

}  // namespace
}  // namespace gib::reports
