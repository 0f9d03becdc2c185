// The job page's image viewer in headless Chromium, driven by input events
// (tests/reports/data/viewer_driver.js: wipe button, wheel zoom, pointer drags of the image and of
// the wipe line, the exposure slider, the false-colour box, a hover), then checked pixel by pixel
// against the synthetic run's linear layers: what the canvas shows must be the right layer's
// value at the right pixel, through the exposure and the sRGB encoding (or the magma map).
#include "reports/html_report.h"

#include "image/false_color.h"
#include "image/output_files.h"
#include "support/headless_browser.h"
#include "support/read_text.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;
using test::readText;

int srgb8(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  return int(
      std::lround(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055)));
}

class ImageViewerBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    results_ = test::syntheticReportResults();
    test::writeSyntheticOutputs(run_dir_, results_);
    writeHtmlReport(run_dir_, results_, {});
  }

  // The job page with the driver appended after the page's own scripts, loaded; the driver's
  // findings.
  nlohmann::json drive(const fs::path& chromium, const results::JobResult& job) {
    std::string page = readText(run_dir_ / "report" / (job.slug + ".html"));
    const std::size_t end = page.rfind("</body>");
    page.insert(end, "<script src=\"viewer_driver.js\"></script>\n");
    image::writeTextFile(run_dir_ / "report" / "driven.html", page);
    fs::copy_file(fs::path(GIB_SOURCE_DIR) / "tests/reports/data/viewer_driver.js",
                  run_dir_ / "report" / "viewer_driver.js", fs::copy_options::overwrite_existing);
    const test::LoadedPage loaded =
        test::loadPage(chromium, run_dir_ / "report" / "driven.html", dir_.path());
    EXPECT_EQ(loaded.exit_code, 0) << loaded.log;
    EXPECT_EQ(test::consoleProblems(loaded.log), std::vector<std::string>{}) << loaded.log;
    EXPECT_EQ(test::reportCheck(loaded.dom), "ok");
    const std::string found = test::rootAttribute(loaded.dom, "data-viewer-test");
    if (found.empty()) return nlohmann::json();
    return nlohmann::json::parse(found);
  }

  test::TempDir dir_;
  fs::path run_dir_ = dir_.path();
  results::RunResults results_;
};

// The image pixel a pane point shows under a view (viewer.js's mapping: the view's centre at the
// pane's centre, `zoom` screen pixels per image pixel).
std::pair<int, int> pixelAt(const nlohmann::json& view, const nlohmann::json& pane, double sx,
                            double sy) {
  const double zoom = view["zoom"];
  return {int(std::floor((sx - pane[0].get<double>() / 2) / zoom + view["cx"].get<double>())),
          int(std::floor((sy - pane[1].get<double>() / 2) / zoom + view["cy"].get<double>()))};
}

TEST_F(ImageViewerBrowser, ZoomPanWipeExposureAndFalseColourShowTheRightValues) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const results::JobResult& job = results_.jobs[1];  // a technique job with every layer
  const nlohmann::json out = drive(*chromium, job);
  ASSERT_TRUE(out.is_object());
  ASSERT_FALSE(out.contains("error")) << out["error"];

  // The pane is the image enlarged by a whole factor to at most 512 pixels.
  const int fit = 512 / job.width;
  ASSERT_EQ(out["pane"][0], job.width * fit);
  EXPECT_EQ(out["fit"]["zoom"], fit);
  EXPECT_EQ(out["fit"]["mode"], "side");
  const nlohmann::json& steps = out["steps"];
  ASSERT_EQ(steps.size(), 6u);
  EXPECT_EQ(steps[0]["view"]["mode"], "wipe");
  // One wheel notch doubles the zoom about the pointer (here the centre, which stays).
  EXPECT_EQ(steps[1]["view"]["zoom"], 2 * fit);
  EXPECT_DOUBLE_EQ(steps[1]["view"]["cx"], job.width / 2.0);
  // Dragging 64 screen pixels to the right moves the image with the pointer: the view's centre
  // moves 64 / zoom image pixels to the left.
  EXPECT_DOUBLE_EQ(steps[2]["view"]["cx"], job.width / 2.0 - 64.0 / (2 * fit));
  EXPECT_DOUBLE_EQ(steps[2]["view"]["wipe"], 0.5);
  // Grabbing the wipe line moves it, not the image.
  EXPECT_NEAR(steps[3]["view"]["wipe"], 0.75, 1e-9);
  EXPECT_DOUBLE_EQ(steps[3]["view"]["cx"], steps[2]["view"]["cx"]);
  EXPECT_EQ(steps[4]["view"]["exposure"], 1);

  // Left of the wipe line the left layer (reference), right of it the right layer (image), each
  // at the pixel under the point, exposed by one stop and sRGB-encoded.
  const nlohmann::json& view = steps[4]["view"];
  const image::Image reference = test::syntheticViewerImage(job, "reference");
  const image::Image picture = test::syntheticViewerImage(job, "image");
  const double wipe_x = view["wipe"].get<double>() * out["pane"][0].get<double>();
  for (const nlohmann::json& sample : out["samples"]) {
    const double sx = sample["at"][0], sy = sample["at"][1];
    const auto [x, y] = pixelAt(view, out["pane"], sx, sy);
    SCOPED_TRACE("pane point " + sample["at"].dump() + ", pixel " + std::to_string(x) + "," +
                 std::to_string(y));
    ASSERT_TRUE(x >= 0 && y >= 0 && x < job.width && y < job.height);
    const float* value = (sx < wipe_x ? reference : picture).pixel(x, y);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sample["rgb"][c].get<int>(), srgb8(2 * value[c]), 1);
  }

  // The readout names the pixel under the pointer and the linear values of every layer there.
  const auto [hx, hy] = pixelAt(view, out["pane"], 300, 200);
  const std::string readout = out["readout"];
  EXPECT_NE(readout.find("pixel (" + std::to_string(hx) + ", " + std::to_string(hy) + ")"),
            std::string::npos)
      << readout;
  const std::size_t at = readout.find("reference ");
  ASSERT_NE(at, std::string::npos) << readout;
  std::istringstream values(readout.substr(at + 10));
  double r = 0, g = 0, b = 0;
  values >> r >> g >> b;
  const float* expected = reference.pixel(hx, hy);
  EXPECT_NEAR(r, expected[0], 1e-3) << readout;
  EXPECT_NEAR(g, expected[1], 1e-3) << readout;
  EXPECT_NEAR(b, expected[2], 1e-3) << readout;
  EXPECT_NE(readout.find("image "), std::string::npos) << readout;
  EXPECT_NE(readout.find("flip "), std::string::npos) << readout;
  EXPECT_NE(readout.find("stderr "), std::string::npos) << readout;

  // False colour: the exposed luminance through the magma map.
  EXPECT_EQ(steps[5]["view"]["falseColour"], true);
  const nlohmann::json& sample = out["false_samples"][0];
  const auto [fx, fy] = pixelAt(steps[5]["view"], out["pane"], sample["at"][0], sample["at"][1]);
  const float* rgb = reference.pixel(fx, fy);
  const double luminance = 2 * (0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]);
  float magma[3];
  image::magmaSrgb(float(std::round(std::clamp(luminance, 0.0, 1.0) * 255) / 255), magma);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(sample["rgb"][c].get<int>(), std::lround(magma[c] * 255), 1) << sample.dump();

  // The view is in the address, so it can be linked to.
  const std::string hash = out["hash"];
  EXPECT_NE(hash.find("mode=wipe"), std::string::npos) << hash;
  EXPECT_NE(hash.find("exposure=1"), std::string::npos) << hash;
}

TEST_F(ImageViewerBrowser, AViewInTheAddressIsRestored) {
  GIB_REQUIRE_CHROMIUM(chromium);
  // The driver reads the view before it acts: a page opened with a #fragment starts there.
  const results::JobResult& job = results_.jobs[1];
  std::string page = readText(run_dir_ / "report" / (job.slug + ".html"));
  const std::string restore =
      "<script>history.replaceState(null, '', "
      "'#a=flip&b=reference&mode=wipe&wipe=0.3&zoom=64&cx=5&cy=6&exposure=-2&probe=4,5');"
      "</script>\n";
  // Before the viewer script: as if the page had been opened with that address.
  page.insert(page.find("<script>"), restore);
  image::writeTextFile(run_dir_ / "report" / (job.slug + ".html"), page);
  const nlohmann::json out = drive(*chromium, job);
  ASSERT_TRUE(out.is_object());
  const nlohmann::json& start = out["fit"];
  EXPECT_EQ(start["a"], "flip");
  EXPECT_EQ(start["b"], "reference");
  EXPECT_EQ(start["mode"], "wipe");
  EXPECT_DOUBLE_EQ(start["wipe"], 0.3);
  EXPECT_EQ(start["zoom"], 64);
  EXPECT_EQ(start["exposure"], -2);
  EXPECT_EQ(start["probe"]["x"], 4);
  EXPECT_EQ(start["probe"]["y"], 5);
}

TEST_F(ImageViewerBrowser, ARunWrittenBeforeViewerDataShowsItsPngs) {
  GIB_REQUIRE_CHROMIUM(chromium);
  // results.json of an older run: no viewer data listed, so the report falls back to the PNGs.
  for (results::JobResult& job : results_.jobs) {
    job.outputs.viewer_data.clear();
    job.outputs.reference_viewer_data.clear();
  }
  writeHtmlReport(run_dir_, results_, {});
  const results::JobResult& job = results_.jobs[1];
  const test::LoadedPage loaded =
      test::loadPage(*chromium, run_dir_ / "report" / (job.slug + ".html"), dir_.path());
  EXPECT_EQ(test::reportCheck(loaded.dom), "ok") << loaded.log;
  EXPECT_EQ(test::consoleProblems(loaded.log), std::vector<std::string>{}) << loaded.log;
  EXPECT_NE(loaded.dom.find("data-viewer-state=\"ready\""), std::string::npos);
  EXPECT_EQ(loaded.dom.find("<script src="), std::string::npos);  // no data to load
  // Exposure and false colour need linear values: offered disabled, and the page says why.
  EXPECT_NE(loaded.dom.find("data-role=\"exposure\" min=\"-10\" max=\"10\" step=\"0.5\" "
                            "value=\"0\" disabled"),
            std::string::npos);
  EXPECT_NE(loaded.dom.find("no linear viewer data"), std::string::npos);
}

TEST_F(ImageViewerBrowser, MissingViewerDataFailsTheSelfCheck) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const results::JobResult& job = results_.jobs[1];
  fs::remove(run_dir_ / job.outputs.viewer_data);  // a report copied without its data
  const test::LoadedPage loaded =
      test::loadPage(*chromium, run_dir_ / "report" / (job.slug + ".html"), dir_.path());
  const std::string check = test::reportCheck(loaded.dom);
  EXPECT_EQ(check.rfind("failed: ", 0), 0u) << check;
  EXPECT_NE(check.find("viewer data " + job.outputs.viewer_data), std::string::npos) << check;
}

}  // namespace
}  // namespace gib::reports
