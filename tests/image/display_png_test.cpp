#include "image/display_png.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

#include "common/input_error.h"
#include "image/display.h"
#include "support/temp_dir.h"

// OpenImageIO writes the grey and alpha PNGs here: gibench itself writes only RGB.

namespace gib::image {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A picture whose every byte differs from its neighbours'.
DisplayPicture pattern(int width, int height) {
  DisplayPicture picture(width, height);
  for (std::size_t i = 0; i < picture.rgb.size(); ++i) picture.rgb[i] = std::uint8_t(i * 7 % 256);
  return picture;
}

void writeWithOiio(const fs::path& path, int width, int height, int channels,
                   const std::vector<std::uint8_t>& values) {
  auto output = OIIO::ImageOutput::create("png");
  ASSERT_TRUE(output);
  ASSERT_TRUE(
      output->open(path.string(), OIIO::ImageSpec(width, height, channels, OIIO::TypeUInt8)));
  ASSERT_TRUE(output->write_image(OIIO::TypeUInt8, values.data()));
  ASSERT_TRUE(output->close());
}

TEST(DisplayPng, WritesAndReadsTheBytesUnchanged) {
  const test::TempDir dir;
  const DisplayPicture written = pattern(7, 5);
  writeDisplayPng(dir / "p.png", written);
  const DisplayPicture read = readDisplayPng(dir / "p.png");
  EXPECT_EQ(read.width, 7);
  EXPECT_EQ(read.height, 5);
  EXPECT_EQ(read.rgb, written.rgb);
  EXPECT_EQ(read.pixel(6, 4)[2], written.rgb.back());
}

TEST(DisplayPng, ReadsWhatWritePngWroteAsItsEightBitValues) {
  const test::TempDir dir;
  Image image(3, 2);
  for (float& value : image.data()) value = 0.5f;
  image.pixel(2, 1)[0] = 1.0f;
  writePng(dir / "display.png", image);
  const DisplayPicture read = readDisplayPng(dir / "display.png");
  ASSERT_EQ(read.width, 3);
  ASSERT_EQ(read.height, 2);
  // 0.5 through the sRGB curve is 187.5 of 255 (rounded either way); 1.0 is white.
  EXPECT_NEAR(read.pixel(0, 0)[0], 188, 1);
  EXPECT_EQ(read.pixel(2, 1)[0], 255);
  EXPECT_EQ(read.pixel(2, 1)[1], read.pixel(0, 0)[0]);
}

TEST(DisplayPng, GreyIsRepeatedAndAlphaIsCompositedOverWhite) {
  const test::TempDir dir;
  writeWithOiio(dir / "grey.png", 2, 1, 1, {10, 200});
  const DisplayPicture grey = readDisplayPng(dir / "grey.png");
  EXPECT_EQ(grey.rgb, (std::vector<std::uint8_t>{10, 10, 10, 200, 200, 200}));
  // Opaque, then fully transparent: its colour, then white.
  writeWithOiio(dir / "alpha.png", 2, 1, 4, {10, 20, 30, 255, 10, 20, 30, 0});
  const DisplayPicture alpha = readDisplayPng(dir / "alpha.png");
  EXPECT_EQ(alpha.rgb, (std::vector<std::uint8_t>{10, 20, 30, 255, 255, 255}));
}

TEST(DisplayPng, MissingOrForeignFilesAreInputErrorsNamingThem) {
  const test::TempDir dir;
  try {
    readDisplayPng(dir / "missing.png");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("missing.png"));
    EXPECT_THAT(e.what(), HasSubstr("no such file"));
  }
  std::ofstream(dir / "text.png") << "not a picture";
  EXPECT_THROW(readDisplayPng(dir / "text.png"), InputError);
  EXPECT_THROW(writeDisplayPng(dir / "none" / "p.png", pattern(1, 1)), InputError);
  DisplayPicture wrong = pattern(2, 2);
  wrong.rgb.pop_back();
  EXPECT_THROW(writeDisplayPng(dir / "p.png", wrong), std::invalid_argument);
}

}  // namespace
}  // namespace gib::image
