// The job page's image viewer in headless Chromium, driven by input events
// (tests/reports/data/viewer_driver.js: wipe button, wheel zoom, pointer drags of the image and of
// the wipe line, the exposure slider, the false-colour box, a hover), then checked pixel by pixel
// against the synthetic run's linear layers: what the canvas shows must be the right layer's
// value at the right pixel, through the exposure and the sRGB encoding (or the magma map).
// tests/reports/data/viewer_features_driver.js drives one scenario per test: wheel deltas, a
// probe in the address, the error layers with their colour bars, the panes in windows of two
// sizes and the full-window button.
#include "reports/html_report.h"

#include "common/subprocess.h"
#include "image/false_color.h"
#include "image/output_files.h"
#include "image/viewer_data.h"
#include "reports/html_text.h"
#include "support/headless_browser.h"
#include "support/read_text.h"
#include "support/synthetic_report_run.h"
#include "support/temp_dir.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace gib::reports {
namespace {

namespace fs = std::filesystem;
using test::readText;

int srgb8(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  return int(
      std::lround(255 * (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055)));
}

// How a test drives the viewer: the driver (tests/reports/data/), the scenario it runs
// (viewer_features_driver.js), the #fragment the page opens with, the browser window's size (0:
// headless Chromium's default, whose page is 780 × 437 pixels).
struct Drive {
  std::string driver = "viewer_driver.js";
  std::string scenario;
  std::string fragment;
  int window_width = 0;
  int window_height = 0;
};

// viewer_features_driver.js running `scenario`, in a window of the given size (0: the default),
// the page opened with `fragment`.
Drive features(const std::string& scenario, const std::string& fragment = {}, int window_width = 0,
               int window_height = 0) {
  return {"viewer_features_driver.js", scenario, fragment, window_width, window_height};
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
  nlohmann::json drive(const fs::path& chromium, const results::JobResult& job,
                       const Drive& how = {}) {
    std::string page = readText(run_dir_ / "report" / (job.slug + ".html"));
    // Before the viewer's script: as if the page had been opened with that address.
    std::string prelude;
    if (!how.fragment.empty())
      prelude += "history.replaceState(null, '', '#" + how.fragment + "');";
    if (!how.scenario.empty()) prelude += "window.gibViewerScenario = '" + how.scenario + "';";
    if (!prelude.empty()) page.insert(page.find("<script>"), "<script>" + prelude + "</script>\n");
    page.insert(page.rfind("</body>"), "<script src=\"" + how.driver + "\"></script>\n");
    image::writeTextFile(run_dir_ / "report" / "driven.html", page);
    fs::copy_file(fs::path(GIB_SOURCE_DIR) / "tests/reports/data" / how.driver,
                  run_dir_ / "report" / how.driver, fs::copy_options::overwrite_existing);
    const fs::path driven = run_dir_ / "report" / "driven.html";
    const test::LoadedPage loaded =
        test::loadPage(chromium, driven, dir_.path(), test::PageClock::kVirtual,
                       {how.window_width, how.window_height});
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

// The colour a pane shows for a value and the colour of the bar's column at that value differ by
// at most one entry of the colour map (the column's centre is within half a column of the
// value, and a bar is hundreds of columns wide); neighbouring entries of magma and of the
// diverging map differ by at most 4 per channel.
constexpr int kBarColourTolerance = 6;

// The 99th percentile of the magnitudes of `values` (viewer.js's automatic range, as the report's
// error-map PNGs: metrics/error_map_display.cpp).
double percentile99OfMagnitudes(std::vector<double> values) {
  for (double& v : values) v = std::abs(v);
  std::sort(values.begin(), values.end());
  return values[std::size_t(0.99 * double(values.size() - 1))];
}

double luminance(const float* rgb) {
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

// A colour bar as the driver read it spans [low, high], and its ticks are evenly spaced values
// within it, a step of 1, 2 or 5 × 10^k apart, labelled with their values and placed where those
// values fall on the bar.
void expectBar(const nlohmann::json& bar, const std::string& layer, double low, double high) {
  SCOPED_TRACE("colour bar of " + layer + ": " + bar.value("caption", std::string()));
  ASSERT_FALSE(bar.contains("hidden"));
  EXPECT_EQ(bar["layer"], layer);
  EXPECT_NEAR(bar["low"].get<double>(), low, 1e-9 * std::max(1.0, std::abs(low)));
  EXPECT_NEAR(bar["high"].get<double>(), high, 1e-9 * std::max(1.0, std::abs(high)));
  const nlohmann::json& ticks = bar["ticks"];
  ASSERT_GE(ticks.size(), 2u);
  const double step = ticks[1]["value"].get<double>() - ticks[0]["value"].get<double>();
  const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  EXPECT_TRUE(std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 ||
              std::abs(mantissa - 5) < 1e-6)
      << step;
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    const double value = ticks[i]["value"];
    SCOPED_TRACE(ticks[i].dump());
    EXPECT_NEAR(std::stod(ticks[i]["text"].get<std::string>()), value, 1e-9 * step);
    EXPECT_GE(value, low - 1e-9 * step);
    EXPECT_LE(value, high + 1e-9 * step);
    // Percent of the bar's width, as CSS keeps it (6 significant digits).
    EXPECT_NEAR(ticks[i]["left"].get<double>(), 100 * (value - low) / (high - low), 1e-3);
    if (i > 0) {
      EXPECT_NEAR(value - ticks[i - 1]["value"].get<double>(), step, 1e-9 * step);
    }
  }
}

// The pane's colour for `value` is the bar's colour at that value: the bar shows the true values
// of what the pane shows.
void expectColourOnBar(const nlohmann::json& bar, const nlohmann::json& rgb, double value) {
  const nlohmann::json& strip = bar["strip"];
  const double low = bar["low"], high = bar["high"];
  const double t = std::clamp((value - low) / (high - low), 0.0, 1.0);
  const std::size_t column = std::min(std::size_t(t * double(strip.size())), strip.size() - 1);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(rgb[c].get<int>(), strip[column][c].get<int>(), kBarColourTolerance)
        << "value " << value << " at column " << column << " of " << strip.size() << ", pane "
        << rgb.dump() << ", bar " << strip[column].dump();
}

TEST_F(ImageViewerBrowser, ZoomPanWipeExposureAndFalseColourShowTheRightValues) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const results::JobResult& job = results_.jobs[1];  // a technique job with every layer
  const nlohmann::json out = drive(*chromium, job);
  ASSERT_TRUE(out.is_object());
  ASSERT_FALSE(out.contains("error")) << out["error"];

  // The pane is the image enlarged by a whole factor to the room the window gives it.
  const double fit = out["fit"]["zoom"];
  EXPECT_EQ(fit, std::floor(fit));
  EXPECT_GE(fit, 2);
  ASSERT_EQ(out["pane"][0], job.width * fit);
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
    const auto [x, y] =
        pixelAt(view, out["pane"], sx + 0.5, sy + 0.5);  // the canvas pixel's centre
    SCOPED_TRACE("pane point " + sample["at"].dump() + ", pixel " + std::to_string(x) + "," +
                 std::to_string(y));
    ASSERT_TRUE(x >= 0 && y >= 0 && x < job.width && y < job.height);
    const float* value = (sx < wipe_x ? reference : picture).pixel(x, y);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sample["rgb"][c].get<int>(), srgb8(2 * value[c]), 1);
  }

  // The readout names the pixel under the pointer and the linear values of every layer there.
  const auto [hx, hy] = pixelAt(view, out["pane"], out["hover"][0], out["hover"][1]);
  const std::string readout = out["readout"];
  EXPECT_NE(readout.find("pixel (" + std::to_string(hx) + ", " + std::to_string(hy) + ")"),
            std::string::npos)
      << readout;
  std::smatch rgb_values;
  ASSERT_TRUE(
      std::regex_search(readout, rgb_values, std::regex("Reference R (\\S+) G (\\S+) B (\\S+)")))
      << readout;
  const float* expected = reference.pixel(hx, hy);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(std::stod(rgb_values[c + 1]), expected[c], 1e-3) << readout;
  for (const char* layer : {"Image R ", "Difference ", "Signed difference ", "Relative error ",
                            "FLIP ", "Standard error R "})
    EXPECT_NE(readout.find(layer), std::string::npos) << layer << " in " << readout;

  // False colour: the exposed luminance through the magma map.
  EXPECT_EQ(steps[5]["view"]["falseColour"], true);
  const nlohmann::json& sample = out["false_samples"][0];
  const auto [fx, fy] = pixelAt(steps[5]["view"], out["pane"], sample["at"][0].get<double>() + 0.5,
                                sample["at"][1].get<double>() + 0.5);
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
  const nlohmann::json out = drive(
      *chromium, job,
      {"viewer_driver.js", "",
       "a=flip&b=reference&mode=wipe&wipe=0.3&zoom=64&cx=5&cy=6&exposure=-2&auto=0&probe=4,5"});
  ASSERT_TRUE(out.is_object());
  const nlohmann::json& start = out["fit"];
  EXPECT_EQ(start["a"], "flip");
  EXPECT_EQ(start["b"], "reference");
  EXPECT_EQ(start["mode"], "wipe");
  EXPECT_DOUBLE_EQ(start["wipe"], 0.3);
  EXPECT_EQ(start["zoom"], 64);
  EXPECT_EQ(start["cx"], 5);  // the address's centre, not the probe's
  EXPECT_EQ(start["cy"], 6);
  EXPECT_EQ(start["exposure"], -2);
  EXPECT_EQ(start["autoRange"], false);
  EXPECT_EQ(start["probe"]["x"], 4);
  EXPECT_EQ(start["probe"]["y"], 5);
}

TEST_F(ImageViewerBrowser, WheelZoomsInProportionToItsDelta) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const nlohmann::json out = drive(*chromium, results_.jobs[1], features("wheel"));
  ASSERT_TRUE(out.is_object());
  ASSERT_FALSE(out.contains("error")) << out["error"];
  // Zoom steps of 2× per case: 100 pixels, 3 lines or a page are one step (a mouse's notch); a
  // trackpad's small deltas zoom as much as they add up to.
  const std::vector<double> expected = {0.1, 1, 0.03, 1, -0.5, 1, 1};
  ASSERT_EQ(out["cases"].size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const nlohmann::json& c = out["cases"][i];
    EXPECT_NEAR(std::log2(c["zoom"].get<double>() / out["fit"].get<double>()), expected[i], 1e-9)
        << c.dump();
  }
}

TEST_F(ImageViewerBrowser, AProbeWithoutACentreIsCentredInThePane) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const results::JobResult& job = results_.jobs[1];
  const nlohmann::json out = drive(*chromium, job, features("probe", "zoom=8&probe=4,5"));
  ASSERT_TRUE(out.is_object());
  ASSERT_FALSE(out.contains("error")) << out["error"];
  EXPECT_EQ(out["view"]["zoom"], 8);
  EXPECT_DOUBLE_EQ(out["view"]["cx"], 4.5);
  EXPECT_DOUBLE_EQ(out["view"]["cy"], 5.5);
  // The pane's centre shows the probe pixel (of the reference, the left layer).
  const double w = out["pane"][0], h = out["pane"][1];
  EXPECT_EQ(pixelAt(out["view"], out["pane"], w / 2 + 0.5, h / 2 + 0.5), std::make_pair(4, 5));
  const image::Image reference = test::syntheticViewerImage(job, "reference");
  const float* value = reference.pixel(4, 5);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(out["centre"][c].get<int>(), srgb8(value[c]), 1);
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

// The test image of the error layers: the reference plus d(x) = (x − 12) / 32 in every channel,
// so that its luminance differs from the reference's by d (the luminance weights sum to 1):
// negative left of column 12, zero on it, positive to its right. Exact in half floats.
class ImageViewerErrorLayers : public ImageViewerBrowser {
 protected:
  void SetUp() override {
    ImageViewerBrowser::SetUp();
    const results::JobResult& job = results_.jobs[1];
    reference_ = test::syntheticViewerImage(job, "reference");
    image::Image picture = reference_;
    for (int y = 0; y < job.height; ++y)
      for (int x = 0; x < job.width; ++x)
        for (int c = 0; c < 3; ++c) picture.pixel(x, y)[c] += float(signedDifference(x));
    flip_ = test::syntheticViewerImage(job, "flip");
    image::writeViewerData(run_dir_ / job.outputs.viewer_data, job.outputs.viewer_data,
                           {{"image", &picture}, {"flip", &flip_}});
  }

  static double signedDifference(int x) { return (x - 12) / 32.0; }
  // |ΔL| / (L(reference) + ε), ε = 0.01 as relMSE's.
  double relativeError(int x, int y) const {
    return std::abs(signedDifference(x)) / (luminance(reference_.pixel(x, y)) + 0.01);
  }
  template <typename F>
  std::vector<double> everyPixel(F value) const {
    std::vector<double> values;
    for (int y = 0; y < reference_.height(); ++y)
      for (int x = 0; x < reference_.width(); ++x) values.push_back(value(x, y));
    return values;
  }

  image::Image reference_;
  image::Image flip_;
};

TEST_F(ImageViewerErrorLayers, SignedAndRelativeErrorsShowTheirValuesOnColourBars) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const nlohmann::json out = drive(*chromium, results_.jobs[1], features("layers"));
  ASSERT_TRUE(out.is_object());
  ASSERT_FALSE(out.contains("error")) << out["error"];
  EXPECT_EQ(out["view"]["a"], "signed");
  EXPECT_EQ(out["view"]["b"], "relative");

  // Automatic range: symmetric about 0 for the signed difference, from 0 for the relative error,
  // to the 99th percentile of the magnitudes (19/32 for the signed difference).
  const double signed_high =
      percentile99OfMagnitudes(everyPixel([](int x, int) { return signedDifference(x); }));
  EXPECT_DOUBLE_EQ(signed_high, 19.0 / 32);
  const double relative_high =
      percentile99OfMagnitudes(everyPixel([&](int x, int y) { return relativeError(x, y); }));
  const nlohmann::json& automatic = out["auto"];
  expectBar(automatic["a"], "signed", -signed_high, signed_high);
  expectBar(automatic["b"], "relative", 0, relative_high);
  // 0 is a tick of the signed difference's bar, and white; below it blue, above it red.
  bool zero_tick = false;
  for (const nlohmann::json& tick : automatic["a"]["ticks"]) zero_tick |= tick["value"] == 0.0;
  EXPECT_TRUE(zero_tick) << automatic["a"]["ticks"].dump();
  for (const nlohmann::json& sample : automatic["samples"]) {
    const int x = sample["pixel"][0], y = sample["pixel"][1];
    SCOPED_TRACE(sample.dump());
    const double d = signedDifference(x);
    expectColourOnBar(automatic["a"], sample["a"], d);
    expectColourOnBar(automatic["b"], sample["b"], relativeError(x, y));
    const int r = sample["a"][0], g = sample["a"][1], b = sample["a"][2];
    if (d < 0) {
      EXPECT_GT(b, r + 40);
    } else if (d > 0) {
      EXPECT_GT(r, b + 40);
    } else {
      EXPECT_GE(std::min({r, g, b}), 230);
    }
  }
  // The pinned pixel's values: d(20) = 0.25.
  const std::string readout = out["readout"];
  EXPECT_NE(readout.find("pixel (20, 7) pinned"), std::string::npos) << readout;
  EXPECT_NE(readout.find("Signed difference 0.2500"), std::string::npos) << readout;
  std::smatch relative;
  ASSERT_TRUE(std::regex_search(readout, relative, std::regex("Relative error (\\S+)"))) << readout;
  EXPECT_NEAR(std::stod(relative[1]), relativeError(20, 7), 5e-4 * relativeError(20, 7));

  // Without the automatic range: ±2^-exposure and 0 to 2^-exposure, at exposure 0.
  const nlohmann::json& fixed = out["fixed"];
  EXPECT_EQ(fixed["view"]["autoRange"], false);
  expectBar(fixed["a"], "signed", -1, 1);
  expectBar(fixed["b"], "relative", 0, 1);
  for (const nlohmann::json& sample : fixed["samples"]) {
    const int x = sample["pixel"][0], y = sample["pixel"][1];
    SCOPED_TRACE(sample.dump());
    expectColourOnBar(fixed["a"], sample["a"], signedDifference(x));
    expectColourOnBar(fixed["b"], sample["b"], relativeError(x, y));
  }
}

TEST_F(ImageViewerErrorLayers, DifferenceFlipAndFalseColourHaveColourBarsOfTheirValues) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const nlohmann::json out = drive(*chromium, results_.jobs[1], features("layers"));
  ASSERT_TRUE(out.is_object());
  ASSERT_FALSE(out.contains("error")) << out["error"];
  // The difference |ΔL| and FLIP, automatic range: to their 99th percentiles.
  const double flip_high = percentile99OfMagnitudes(
      everyPixel([&](int x, int y) { return double(flip_.pixel(x, y)[0]); }));
  const nlohmann::json& errors = out["errors"];
  expectBar(errors["a"], "difference", 0, 19.0 / 32);
  expectBar(errors["b"], "flip", 0, flip_high);
  for (const nlohmann::json& sample : errors["samples"]) {
    const int x = sample["pixel"][0], y = sample["pixel"][1];
    SCOPED_TRACE(sample.dump());
    expectColourOnBar(errors["a"], sample["a"], std::abs(signedDifference(x)));
    expectColourOnBar(errors["b"], sample["b"], flip_.pixel(x, y)[0]);
  }
  // Fixed: the difference to 2^-exposure, FLIP over its own range [0, 1].
  const nlohmann::json& fixed = out["errorsFixed"];
  expectBar(fixed["a"], "difference", 0, 1);
  expectBar(fixed["b"], "flip", 0, 1);
  for (const nlohmann::json& sample : fixed["samples"]) {
    const int x = sample["pixel"][0], y = sample["pixel"][1];
    SCOPED_TRACE(sample.dump());
    expectColourOnBar(fixed["b"], sample["b"], flip_.pixel(x, y)[0]);
  }
  // False colour at +1 EV: the luminance over [0, 1/2], for the reference and the image alike.
  const nlohmann::json& false_colour = out["falseColour"];
  EXPECT_EQ(false_colour["view"]["exposure"], 1);
  expectBar(false_colour["a"], "reference", 0, 0.5);
  expectBar(false_colour["b"], "image", 0, 0.5);
  for (const nlohmann::json& sample : false_colour["samples"]) {
    const int x = sample["pixel"][0], y = sample["pixel"][1];
    SCOPED_TRACE(sample.dump());
    const float* rgb = reference_.pixel(x, y);
    expectColourOnBar(false_colour["a"], sample["a"], luminance(rgb));
    expectColourOnBar(false_colour["b"], sample["b"], luminance(rgb) + signedDifference(x));
  }
  // Side by side, each bar is under its own pane, even when the other pane has none.
  const nlohmann::json& alignment = out["alignment"];
  EXPECT_NEAR(alignment["bar"]["left"].get<double>(), alignment["pane"]["left"].get<double>(), 1.0);
  EXPECT_NEAR(alignment["bar"]["width"].get<double>(), alignment["pane"]["width"].get<double>(),
              1.0);
}

// True when `text` is a number of 4 significant digits (2.500, 0.01250, 1.250e-5) or 0.
bool fourSignificantDigits(const std::string& text) {
  static const std::regex format("-?(0|[1-9]\\.\\d{3}e[+-]\\d+|\\d+\\.?\\d*)");
  if (!std::regex_match(text, format)) return false;
  if (text.find('e') != std::string::npos || text == "0") return true;
  std::string digits;
  for (char c : text)
    if (std::isdigit(static_cast<unsigned char>(c))) digits += c;
  return digits.substr(digits.find_first_not_of('0')).size() == 4;
}

TEST_F(ImageViewerErrorLayers, TheReadoutLabelsChannelsInOneFormatAndKeepsEachLayerOnOneLine) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const nlohmann::json out = drive(*chromium, results_.jobs[1], features("layers"));
  ASSERT_TRUE(out.is_object());
  ASSERT_FALSE(out.contains("error")) << out["error"];
  // A group per layer, even where the readout is 120 pixels wide: RGB layers with R, G and B,
  // error layers with one value, every number with 4 significant digits.
  const nlohmann::json& groups = out["narrowReadout"];
  ASSERT_EQ(groups.size(), 7u) << groups.dump();
  const std::regex rgb("(Reference|Image|Standard error) R (\\S+) G (\\S+) B (\\S+)");
  const std::regex single("(Difference|Signed difference|Relative error|FLIP) (\\S+)");
  for (const nlohmann::json& group : groups) {
    const std::string text = group["text"];
    SCOPED_TRACE(text);
    EXPECT_EQ(group["lines"], 1);
    std::smatch match;
    const bool is_rgb = std::regex_match(text, match, rgb);
    ASSERT_TRUE(is_rgb || std::regex_match(text, match, single));
    for (std::size_t i = 2; i < match.size(); ++i)
      EXPECT_TRUE(fourSignificantDigits(match[i])) << match[i];
  }
}

TEST_F(ImageViewerBrowser, PanesFitTheWindowSideBySideAndGrowOnAWideScreen) {
  GIB_REQUIRE_CHROMIUM(chromium);
  std::vector<nlohmann::json> found;
  for (const int width : {1000, 1800}) {
    const nlohmann::json out =
        drive(*chromium, results_.jobs[1], features("layout", "", width, 1200));
    ASSERT_TRUE(out.is_object());
    ASSERT_FALSE(out.contains("error")) << out["error"];
    SCOPED_TRACE("window " + out["window"].dump());
    const double window = out["window"]["width"];  // the page's: less a scrollbar
    EXPECT_GE(window, width - 20);
    const nlohmann::json& a = out["side"]["a"];
    const nlohmann::json& b = out["side"]["b"];
    // Both panes inside the window, side by side, of one size, using most of the width.
    EXPECT_GE(a["left"].get<double>(), 0);
    EXPECT_LE(b["right"].get<double>(), window);
    EXPECT_GE(b["left"].get<double>(), a["right"].get<double>());
    EXPECT_EQ(a["top"], b["top"]);
    EXPECT_EQ(a["width"], b["width"]);
    EXPECT_GE(a["width"].get<double>() + b["width"].get<double>(), 0.8 * window);
    EXPECT_LE(a["height"].get<double>(), out["window"]["height"].get<double>());
    found.push_back(out);
  }
  // On the wide screen the panes grow past the page's text column (1200 pixels at most).
  const double narrow = found[0]["side"]["a"]["width"], wide = found[1]["side"]["a"]["width"];
  EXPECT_GT(wide, 1.5 * narrow);
  EXPECT_GT(2 * wide, found[1]["page"]["width"].get<double>());
}

TEST_F(ImageViewerBrowser, TheFullWindowButtonMakesOnePaneFillTheWindowAndBack) {
  GIB_REQUIRE_CHROMIUM(chromium);
  const nlohmann::json out = drive(*chromium, results_.jobs[1], features("layout", "", 1000, 800));
  ASSERT_TRUE(out.is_object());
  ASSERT_FALSE(out.contains("error")) << out["error"];
  const double width = out["window"]["width"], height = out["window"]["height"];
  const auto area = [](const nlohmann::json& r) {
    return r["width"].get<double>() * r["height"].get<double>();
  };
  const nlohmann::json& side = out["side"];
  for (const char* pane : {"a", "b"}) {
    const nlohmann::json& full = out[pane == std::string("a") ? "fullA" : "fullB"];
    const std::string other = pane == std::string("a") ? "b" : "a";
    SCOPED_TRACE(std::string("pane ") + pane + ": " + full.dump());
    EXPECT_TRUE(full["full"].get<bool>());
    EXPECT_EQ(full["view"]["full"], pane);
    EXPECT_NE(full["hash"].get<std::string>().find(std::string("full=") + pane), std::string::npos);
    EXPECT_TRUE(full[std::string(pane) + "Shown"].get<bool>());
    EXPECT_FALSE(full[other + "Shown"].get<bool>());
    // The pane fills the window's width and lies inside it, far larger than side by side.
    const nlohmann::json& rect = full[pane];
    EXPECT_GE(rect["left"].get<double>(), 0);
    EXPECT_GE(rect["top"].get<double>(), 0);
    EXPECT_LE(rect["right"].get<double>(), width);
    EXPECT_LE(rect["bottom"].get<double>(), height);
    EXPECT_GE(rect["width"].get<double>(), width - 64);
    EXPECT_GT(area(rect), 2 * area(side[pane]));
  }
  // Escape (after the button of pane b) and the button again (after pane a's) go back to the two
  // panes as they were.
  for (const char* back : {"escaped", "back"}) {
    const nlohmann::json& state = out[back];
    SCOPED_TRACE(back);
    EXPECT_FALSE(state["full"].get<bool>());
    EXPECT_EQ(state["view"]["full"], nullptr);
    EXPECT_TRUE(state["aShown"].get<bool>() && state["bShown"].get<bool>());
    for (const char* pane : {"a", "b"})
      for (const char* edge : {"left", "width", "height"})
        EXPECT_NEAR(state[pane][edge].get<double>(), side[pane][edge].get<double>(), 0.5);
    EXPECT_NEAR(state["view"]["zoom"].get<double>(), side["view"]["zoom"].get<double>(), 1e-9);
  }
}

}  // namespace
}  // namespace gib::reports
