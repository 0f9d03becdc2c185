// The report viewer's data file: what a browser decodes from it must be the image's values to
// half precision, under the id the page asks for; and thumbnails average whole blocks.
#include "image/viewer_data.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <regex>

namespace gib::image {
namespace {

std::vector<std::uint8_t> decodeBase64(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> bytes;
  std::uint32_t bits = 0;
  int count = 0;
  for (char c : text) {
    if (c == '=') break;
    bits = (bits << 6) | std::uint32_t(alphabet.find(c));
    count += 6;
    if (count >= 8) {
      count -= 8;
      bytes.push_back(std::uint8_t((bits >> count) & 0xff));
    }
  }
  return bytes;
}

// IEEE 754 binary16 to float, written out so the test does not share the writer's conversion.
float halfToFloat(std::uint16_t bits) {
  const int exponent = (bits >> 10) & 0x1f, mantissa = bits & 0x3ff;
  const float sign = bits & 0x8000 ? -1.0f : 1.0f;
  if (exponent == 0) return sign * std::ldexp(float(mantissa), -24);
  if (exponent == 31) return mantissa ? NAN : sign * INFINITY;
  return sign * std::ldexp(1.0f + float(mantissa) / 1024.0f, exponent - 15);
}

// The half floats of one layer of a data script, as floats.
std::vector<float> layerValues(const std::string& script, const std::string& layer) {
  const std::regex pattern("\"" + layer + "\": \\{[^}]*\"half\": \"([^\"]*)\"");
  std::smatch match;
  if (!std::regex_search(script, match, pattern)) return {};
  const std::vector<std::uint8_t> bytes = decodeBase64(match[1]);
  std::vector<float> values;
  for (std::size_t i = 0; i + 1 < bytes.size(); i += 2) {
    values.push_back(halfToFloat(std::uint16_t(bytes[i] | (bytes[i + 1] << 8))));
  }
  return values;
}

TEST(ViewerData, EveryLayerDecodesToItsValuesAtHalfPrecision) {
  Image radiance(5, 3);  // 45 values: a length that is not a multiple of 3 bytes exercises padding
  float next = 0.001f;
  for (float& v : radiance.data()) v = (next *= 1.25f);  // 0.00125 to 23
  Image flip(5, 3, 1, 0.25f);
  const std::string script = viewerDataScript(
      "jobs/a/viewer.js", {{"image", &radiance}, {"flip", &flip}, {"empty", nullptr}});
  EXPECT_NE(script.find("[\"jobs/a/viewer.js\"]"), std::string::npos);
  EXPECT_NE(script.find("\"width\": 5, \"height\": 3, \"channels\": 3"), std::string::npos);
  EXPECT_EQ(script.find("\"empty\""), std::string::npos);  // a missing layer is left out
  const std::vector<float> values = layerValues(script, "image");
  ASSERT_EQ(values.size(), radiance.data().size());
  for (std::size_t i = 0; i < values.size(); ++i)
    EXPECT_NEAR(values[i], radiance.data()[i], radiance.data()[i] * 1e-3) << i;  // 11-bit mantissa
  const std::vector<float> flips = layerValues(script, "flip");
  ASSERT_EQ(flips.size(), 15u);
  for (float v : flips) EXPECT_EQ(v, 0.25f);
}

TEST(ViewerData, FiniteValuesBeyondHalfRangeAreClampedAndNonFiniteOnesKept) {
  Image image(4, 1, 1);
  image.data()[0] = 1e6f;
  image.data()[1] = -1e6f;
  image.data()[2] = NAN;
  image.data()[3] = INFINITY;
  const std::vector<float> values = layerValues(viewerDataScript("x", {{"v", &image}}), "v");
  ASSERT_EQ(values.size(), 4u);
  EXPECT_EQ(values[0], 65504.0f);  // a firefly stays a bright finite pixel
  EXPECT_EQ(values[1], -65504.0f);
  EXPECT_TRUE(std::isnan(values[2]));  // a renderer bug still shows as one
  EXPECT_TRUE(std::isinf(values[3]));
}

TEST(ViewerData, AnIdCannotEndTheScriptOrItsString) {
  const std::string script = viewerDataScript("a\"b</script>", {});
  EXPECT_EQ(script.find("</script>"), std::string::npos);
  EXPECT_EQ(script.find("a\"b"), std::string::npos);
}

TEST(ViewerData, ThumbnailsAverageWholeBlocks) {
  Image image(10, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 10; ++x) image.pixel(x, y)[0] = float(x + 10 * y);
  const Image small = downsampleToWidth(image, 4);  // factor 3: 4 × 2, the last column partial
  ASSERT_EQ(small.width(), 4);
  ASSERT_EQ(small.height(), 2);
  EXPECT_FLOAT_EQ(small.pixel(0, 0)[0], (0 + 1 + 2 + 10 + 11 + 12 + 20 + 21 + 22) / 9.0f);
  EXPECT_FLOAT_EQ(small.pixel(3, 1)[0], (39.0f));       // only pixel (9, 3)
  EXPECT_EQ(downsampleToWidth(image, 16).width(), 10);  // already small enough
}

}  // namespace
}  // namespace gib::image
