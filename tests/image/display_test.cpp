#include "image/display.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>

#include "common/input_error.h"
#include "support/temp_dir.h"

// OpenImageIO appears here (and not only in image/) to decode the PNGs independently.

namespace gib::image {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using Rgb8 = std::array<int, 3>;

// 8-bit rounding of the sRGB curve allows one code value either way.
constexpr int kQuantisationTolerance = 1;

std::vector<Rgb8> readPng(const fs::path& path) {
  auto input = OIIO::ImageInput::open(path.string());
  if (!input) ADD_FAILURE() << "cannot open " << path;
  if (!input) return {};
  const OIIO::ImageSpec& spec = input->spec();
  EXPECT_EQ(input->format_name(), std::string("png"));
  EXPECT_EQ(spec.nchannels, 3);  // No alpha.
  EXPECT_EQ(spec.format, OIIO::TypeUInt8);
  std::vector<std::uint8_t> bytes(std::size_t(spec.width) * spec.height * spec.nchannels);
  EXPECT_TRUE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeUInt8, bytes.data()));
  std::vector<Rgb8> pixels;
  for (std::size_t i = 0; i + 2 < bytes.size(); i += 3)
    pixels.push_back({bytes[i], bytes[i + 1], bytes[i + 2]});
  return pixels;
}

// A one-row image of grey pixels.
Image greyRow(const std::vector<float>& values) {
  Image image(int(values.size()), 1, 3);
  for (std::size_t x = 0; x < values.size(); ++x)
    for (int c = 0; c < 3; ++c) image.pixel(int(x), 0)[c] = values[x];
  return image;
}

TEST(Display, ConfigLoadsWithStandardAndFilmicViews) {
  EXPECT_THAT(displayViews(), ::testing::ElementsAre("Standard", "Filmic"));
}

TEST(Display, StandardViewIsTheSrgbCurve) {
  const test::TempDir dir;
  writePng(dir / "grey.png", greyRow({0.18f, 1.0f, 0.0f, 4.0f, -1.0f}));
  const std::vector<Rgb8> pixels = readPng(dir / "grey.png");
  ASSERT_EQ(pixels.size(), 5u);
  // sRGB(0.18) = 1.055 * 0.18^(1/2.4) - 0.055 = 0.4614 -> 117.7.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixels[0][c], 118, kQuantisationTolerance);
  EXPECT_EQ(pixels[1], (Rgb8{255, 255, 255}));
  EXPECT_EQ(pixels[2], (Rgb8{0, 0, 0}));
  EXPECT_EQ(pixels[3], (Rgb8{255, 255, 255}));  // Clipped.
  EXPECT_EQ(pixels[4], (Rgb8{0, 0, 0}));
}

TEST(Display, OneStopOfExposureDoublesRadiance) {
  const test::TempDir dir;
  writePng(dir / "half.png", greyRow({0.09f}), {.exposure_stops = 1.0f});
  writePng(dir / "full.png", greyRow({0.18f}));
  EXPECT_EQ(readPng(dir / "half.png"), readPng(dir / "full.png"));
}

TEST(Display, FilmicViewCompressesHighlights) {
  const test::TempDir dir;
  writePng(dir / "filmic.png", greyRow({0.0f, 0.18f, 1.0f, 4.0f, 16.0f}), {.view = "Filmic"});
  const std::vector<Rgb8> pixels = readPng(dir / "filmic.png");
  ASSERT_EQ(pixels.size(), 5u);
  EXPECT_EQ(pixels[0][0], 0);
  // Strictly increasing past 1, white only at 16 (config.ocio: y = log2(1 + 4x) / log2(65)).
  for (std::size_t i = 1; i < pixels.size(); ++i) EXPECT_LT(pixels[i - 1][0], pixels[i][0]);
  EXPECT_LT(pixels[2][0], 200);
  EXPECT_EQ(pixels[4][0], 255);
}

TEST(Display, NonFinitePixelsShowMagenta) {
  const test::TempDir dir;
  Image image = greyRow({0.5f, 0.5f, 0.5f, 0.5f});
  image.pixel(0, 0)[1] = std::numeric_limits<float>::quiet_NaN();
  image.pixel(1, 0)[0] = std::numeric_limits<float>::infinity();
  image.pixel(2, 0)[2] = -std::numeric_limits<float>::infinity();
  writePng(dir / "bad.png", image);
  const std::vector<Rgb8> pixels = readPng(dir / "bad.png");
  ASSERT_EQ(pixels.size(), 4u);
  for (int x = 0; x < 3; ++x) EXPECT_EQ(pixels[x], (Rgb8{255, 0, 255})) << x;
  EXPECT_NE(pixels[3], (Rgb8{255, 0, 255}));
}

TEST(Display, GreyImageRepeatsItsChannel) {
  const test::TempDir dir;
  writePng(dir / "y.png", Image(2, 2, 1, 0.18f));
  for (const Rgb8& pixel : readPng(dir / "y.png"))
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixel[c], 118, kQuantisationTolerance);
}

TEST(Display, UnknownViewThrowsInputErrorListingViews) {
  const test::TempDir dir;
  try {
    writePng(dir / "a.png", Image(2, 2), {.view = "ACES"});
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'ACES'"));
    EXPECT_THAT(error.what(), HasSubstr("Standard, Filmic"));
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(Display, WritingIntoMissingDirectoryThrowsAndLeavesNoFile) {
  const test::TempDir dir;
  EXPECT_THROW(writePng(dir / "missing" / "a.png", Image(2, 2)), InputError);
  EXPECT_THROW(writePng(dir / "a.png", Image(2, 2), {.exposure_stops = NAN}), InputError);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

}  // namespace
}  // namespace gib::image
