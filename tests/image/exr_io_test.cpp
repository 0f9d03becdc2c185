#include "image/exr_io.h"

#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "common/input_error.h"
#include "support/temp_dir.h"

// OpenImageIO appears here (and not only in image/) to check our files with an independent
// writer and reader: files that other tools produce, and what our writer puts on disk.

namespace gib::image {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// Values that a lossy or converting path would change: fractions, denormals, -0, infinities, NaN.
Image patternImage(int width, int height, int channels, float seed) {
  Image image(width, height, channels);
  const std::span<float> values = image.data();
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = seed + float(i) * 0.1234567f - float(i % 7) * 1.0e-3f;
  values[0] = -0.0f;
  values[1] = std::numeric_limits<float>::denorm_min();
  values[2] = std::numeric_limits<float>::infinity();
  values[3] = std::numeric_limits<float>::quiet_NaN();
  return image;
}

void expectBitIdentical(const Image& actual, const Image& expected) {
  ASSERT_TRUE(actual.sameSize(expected));
  EXPECT_EQ(std::memcmp(actual.data().data(), expected.data().data(),
                        expected.data().size() * sizeof(float)),
            0);
}

std::string fileBytes(const fs::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

void writeWithOiio(const fs::path& path, const OIIO::ImageSpec& spec,
                   const std::vector<float>& values) {
  auto output = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(output);
  ASSERT_TRUE(output->open(path.string(), spec)) << output->geterror();
  ASSERT_TRUE(output->write_image(OIIO::TypeFloat, values.data())) << output->geterror();
  ASSERT_TRUE(output->close());
}

TEST(ExrIo, MultiLayerRoundTripIsBitExact) {
  const test::TempDir dir;
  const std::vector<Layer> layers = {
      {"", patternImage(5, 3, 3, 1.0f)},
      {"variance", patternImage(5, 3, 3, 2.0f)},
      {"albedo", patternImage(5, 3, 4, 3.0f)},
      {"samples", patternImage(5, 3, 1, 4.0f)},
  };
  const Metadata metadata = {
      {"gibench/scene_hash", "0123456789abcdef0123456789abcdef"},
      {"gibench/parameters", "{\"bounces\": 3, \"path\": \"a/b:c\"}\nsecond line"},
      {"gibench/version", "0.1.0 (é, ü)"},
      {"other.tool/key:with:colons", "x"},
  };
  writeExr(dir / "multi.exr", layers, metadata);

  const ExrFile file = readExr(dir / "multi.exr");
  ASSERT_EQ(file.layers.size(), layers.size());
  for (const Layer& layer : layers) {
    SCOPED_TRACE("layer '" + layer.name + "'");
    const Image* image = file.findLayer(layer.name);
    ASSERT_NE(image, nullptr);
    expectBitIdentical(*image, layer.image);
  }
  expectBitIdentical(file.rgb(), layers[0].image);
  EXPECT_EQ(file.metadata, metadata);
  EXPECT_EQ(file.findLayer("missing"), nullptr);
}

TEST(ExrIo, WritesFloatZipChannelsNamedByLayer) {
  const test::TempDir dir;
  writeExr(dir / "a.exr", {{"", Image(2, 2)}, {"variance", Image(2, 2)}}, {});
  auto input = OIIO::ImageInput::open((dir / "a.exr").string());
  ASSERT_TRUE(input);
  const OIIO::ImageSpec& spec = input->spec();
  EXPECT_EQ(spec.format, OIIO::TypeFloat);
  EXPECT_TRUE(spec.channelformats.empty());
  EXPECT_EQ(spec.get_string_attribute("compression"), "zip");
  EXPECT_THAT(spec.channelnames, ::testing::UnorderedElementsAre("R", "G", "B", "variance.R",
                                                                 "variance.G", "variance.B"));
}

TEST(ExrIo, EqualInputsGiveIdenticalFiles) {
  const test::TempDir dir;
  const std::vector<Layer> layers = {{"", patternImage(8, 8, 3, 1.0f)}};
  const Metadata metadata = {{"gibench/seed", "7"}};
  writeExr(dir / "first.exr", layers, metadata);
  writeExr(dir / "second.exr", layers, metadata);
  EXPECT_EQ(fileBytes(dir / "first.exr"), fileBytes(dir / "second.exr"));
}

TEST(ExrIo, OverwritesAnExistingFile) {
  const test::TempDir dir;
  writeExr(dir / "a.exr", {{"", Image(2, 2, 3, 1.0f)}}, {});
  writeExr(dir / "a.exr", {{"", Image(3, 1, 3, 2.0f)}}, {});
  const ExrFile file = readExr(dir / "a.exr");
  EXPECT_EQ(file.rgb().width(), 3);
  EXPECT_EQ(file.rgb().pixel(0, 0)[0], 2.0f);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

TEST(ExrIo, ReadsPlainRgbaFileFromOpenImageIO) {
  const test::TempDir dir;
  OIIO::ImageSpec spec(3, 2, 4, OIIO::TypeHalf);  // Half on disk: converted on reading.
  std::vector<float> values(3 * 2 * 4);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = float(i) * 0.25f;
  writeWithOiio(dir / "rgba.exr", spec, values);

  const ExrFile file = readExr(dir / "rgba.exr");
  ASSERT_EQ(file.layers.size(), 1u);
  const Image& rgba = file.rgb();
  ASSERT_EQ(rgba.channels(), 4);
  EXPECT_EQ(rgba.width(), 3);
  EXPECT_EQ(rgba.height(), 2);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(rgba.data()[i], values[i]);
  EXPECT_TRUE(file.metadata.empty());  // DateTime and other standard attributes are not ours.
}

TEST(ExrIo, ReadRgbTakesRgbByNameAndLeavesAlphaOut) {
  // Blender's layout: R, G, B and an alpha that is not 1.
  const test::TempDir dir;
  OIIO::ImageSpec spec(3, 2, 4, OIIO::TypeFloat);
  spec.channelnames = {"R", "G", "B", "A"};
  std::vector<float> values(3 * 2 * 4);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.5f + float(i) * 0.125f;
  writeWithOiio(dir / "rgba.exr", spec, values);

  const Image rgb = readRgb(dir / "rgba.exr");
  ASSERT_EQ(rgb.channels(), 3);
  ASSERT_EQ(rgb.pixelCount(), 6u);
  for (std::size_t p = 0; p < rgb.pixelCount(); ++p)
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(rgb.data()[p * 3 + c], values[p * 4 + c]);
}

TEST(ExrIo, ReadRgbNamesTheMissingChannels) {
  const test::TempDir dir;
  auto readRgbError = [](const fs::path& path) -> std::string {
    try {
      readRgb(path);
    } catch (const InputError& error) {
      return error.what();
    }
    return "no InputError";
  };
  OIIO::ImageSpec spec(2, 1, 3, OIIO::TypeFloat);
  spec.channelnames = {"R", "G", "A"};
  writeWithOiio(dir / "no_blue.exr", spec, {1, 2, 3, 4, 5, 6});
  const std::string no_blue = readRgbError(dir / "no_blue.exr");
  EXPECT_THAT(no_blue, HasSubstr("no_blue.exr' has no B channel;"));
  EXPECT_EQ(no_blue.find('\n'), std::string::npos);  // one line
  writeExr(dir / "variance.exr", {{"variance", Image(2, 2)}}, {});
  EXPECT_THAT(readRgbError(dir / "variance.exr"), HasSubstr("has no R, G, B channels;"));
}

TEST(ExrIo, ReadsLuminanceFileAsGreyRgb) {
  const test::TempDir dir;
  OIIO::ImageSpec spec(2, 1, 1, OIIO::TypeFloat);
  spec.channelnames = {"Y"};
  writeWithOiio(dir / "y.exr", spec, {0.25f, 0.75f});

  const ExrFile file = readExr(dir / "y.exr");
  const Image& rgb = file.rgb();
  ASSERT_EQ(rgb.channels(), 3);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(rgb.pixel(0, 0)[c], 0.25f);
    EXPECT_EQ(rgb.pixel(1, 0)[c], 0.75f);
  }
}

TEST(ExrIo, ReadsUnrecognisedChannelsAsSingleChannelLayers) {
  const test::TempDir dir;
  OIIO::ImageSpec spec(1, 1, 7, OIIO::TypeFloat);
  spec.channelnames = {"B", "G", "R", "Z", "normal.X", "normal.Y", "normal.Z"};
  writeWithOiio(dir / "aov.exr", spec, {3, 2, 1, 10, 20, 30, 40});

  const ExrFile file = readExr(dir / "aov.exr");
  const Image& rgb = file.rgb();
  ASSERT_EQ(rgb.channels(), 3);
  EXPECT_EQ(rgb.pixel(0, 0)[0], 1.0f);
  EXPECT_EQ(rgb.pixel(0, 0)[2], 3.0f);
  ASSERT_NE(file.findLayer("Z"), nullptr);
  EXPECT_EQ(file.findLayer("Z")->pixel(0, 0)[0], 10.0f);
  ASSERT_NE(file.findLayer("normal.Y"), nullptr);
  EXPECT_EQ(file.findLayer("normal.Y")->pixel(0, 0)[0], 30.0f);
}

TEST(ExrIo, PlacesDataWindowInsideDisplayWindow) {
  const test::TempDir dir;
  OIIO::ImageSpec spec(1, 1, 3, OIIO::TypeFloat);  // Data window: the pixel (2, 1) only.
  spec.x = 2;
  spec.y = 1;
  spec.full_width = 4;
  spec.full_height = 3;
  writeWithOiio(dir / "crop.exr", spec, {1, 2, 3});

  const ExrFile file = readExr(dir / "crop.exr");
  const Image& rgb = file.rgb();
  ASSERT_EQ(rgb.width(), 4);
  ASSERT_EQ(rgb.height(), 3);
  EXPECT_EQ(rgb.pixel(2, 1)[1], 2.0f);
  EXPECT_EQ(rgb.pixel(0, 0)[0], 0.0f);
  EXPECT_EQ(rgb.pixel(3, 2)[2], 0.0f);
}

TEST(ExrIo, ReadingMissingFileThrowsInputError) {
  const test::TempDir dir;
  try {
    readExr(dir / "missing.exr");
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("cannot read '"));
    EXPECT_THAT(error.what(), HasSubstr("missing.exr"));
  }
}

TEST(ExrIo, ReadingNonExrFileThrowsInputError) {
  const test::TempDir dir;
  std::ofstream(dir / "text.exr") << "not an image\n";
  EXPECT_THROW(readExr(dir / "text.exr"), InputError);
  EXPECT_THROW(readExr(dir.path()), InputError);  // A directory.
}

TEST(ExrIo, ReadingTruncatedFileThrowsInputError) {
  const test::TempDir dir;
  writeExr(dir / "full.exr", {{"", patternImage(64, 64, 3, 1.0f)}}, {});
  const std::string bytes = fileBytes(dir / "full.exr");
  std::ofstream(dir / "cut.exr", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_THROW(readExr(dir / "cut.exr"), InputError);
}

TEST(ExrIo, AnImageOfMoreValuesThanTheCapIsRefusedBeforeItsPixelsAreRead) {
  const test::TempDir dir;
  writeExr(dir / "a.exr", {{"", patternImage(64, 32, 3, 1.0f)}}, {});
  EXPECT_EQ(readExr(dir / "a.exr", 64 * 32 * 3).rgb().width(), 64);
  try {
    readExr(dir / "a.exr", 64 * 32 * 3 - 1);
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("64×32 pixels of 3 channels, more than gibench reads"));
    EXPECT_THAT(error.what(), HasSubstr("a.exr"));
  }
}

// Found by fuzzing (fuzz/corpus/exr/regression-channel-list-beyond-its-size.exr): OpenEXR reads a
// channel list up to its empty name and a fixed-size attribute by its fields, whatever size they
// declare. A size that disagrees put OpenEXR's reading of the header elsewhere than the check's
// walk, which then missed an attribute declaring a gigabyte (7 s per read under the sanitizers).
TEST(ExrIo, AnAttributeWhoseContentDisagreesWithItsSizeIsRefused) {
  const test::TempDir dir;
  writeExr(dir / "a.exr", {{"", patternImage(4, 4, 3, 1.0f)}}, {});
  const std::string bytes = fileBytes(dir / "a.exr");
  const auto withSize = [&](const std::string& attribute, std::int32_t size) {
    std::string changed = bytes;
    const std::size_t at = changed.find(attribute);
    EXPECT_NE(at, std::string::npos) << attribute;
    std::memcpy(changed.data() + at + attribute.size(), &size, 4);
    std::ofstream(dir / "changed.exr", std::ios::binary) << changed;
    return dir / "changed.exr";
  };
  const std::string channels = std::string("channels") + '\0' + "chlist" + '\0';
  std::int32_t list_size = 0;
  std::memcpy(&list_size, bytes.data() + bytes.find(channels) + channels.size(), 4);
  EXPECT_NO_THROW(checkExrHeader(withSize(channels, list_size)));
  for (const std::int32_t size : {list_size - 1, list_size - 18}) {
    try {
      checkExrHeader(withSize(channels, size));
      FAIL() << "no exception at size " << size;
    } catch (const InputError& error) {
      EXPECT_THAT(error.what(), HasSubstr("attribute 'channels': its channel list does not end"));
    }
  }
  try {
    checkExrHeader(withSize(std::string("dataWindow") + '\0' + "box2i" + '\0', 17));
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("'dataWindow' declares 17 bytes; a box2i holds 16"));
  }
}

// The header check applies the cap before OpenEXR opens the file, which allocates its line and
// tile buffers by the data window and the tile size (found by fuzzing: most of the time went to
// allocating buffers for windows that mutated headers declared).
TEST(ExrIo, TheHeaderCheckAppliesTheCapToTheDataWindowAndTheTileSize) {
  const test::TempDir dir;
  writeExr(dir / "a.exr", {{"", patternImage(64, 32, 3, 1.0f)}}, {});
  EXPECT_NO_THROW(checkExrHeader(dir / "a.exr", 64 * 32 * 3));
  try {
    checkExrHeader(dir / "a.exr", 64 * 32 * 3 - 1);
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("declares an image of 64×32 pixels of 3 channels"));
  }
  // An 8×8 image stored in one 64×64 tile: the image is within a cap of 8·8·3, the tile is not.
  OIIO::ImageSpec spec(8, 8, 3, OIIO::TypeFloat);
  spec.tile_width = spec.tile_height = 64;
  writeWithOiio(dir / "tiled.exr", spec, std::vector<float>(8 * 8 * 3, 0.5f));
  EXPECT_NO_THROW(checkExrHeader(dir / "tiled.exr", 64 * 64 * 3));
  try {
    readExr(dir / "tiled.exr", 8 * 8 * 3);
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("declares tiles of 64×64 pixels of 3 channels"));
  }
}

// Found by fuzzing (fuzz/corpus/exr/regression-display-window-beyond-the-cap.exr): the layers
// are images of the display window, so 24×16 pixels of data in a window 16 776 208 high made the
// reader allocate 4.8 GB after the data window had passed the cap.
TEST(ExrIo, ADisplayWindowBeyondTheCapIsRefusedThoughItsDataWindowIsSmall) {
  const test::TempDir dir;
  OIIO::ImageSpec spec(8, 8, 3, OIIO::TypeFloat);
  spec.full_width = 8;
  spec.full_height = 1024;
  writeWithOiio(dir / "tall.exr", spec, std::vector<float>(8 * 8 * 3, 0.5f));
  const std::size_t cap = 8 * 1024 * 3 - 1;  // the data window's 192 values are within it
  for (const bool header_only : {true, false}) {
    try {
      if (header_only)
        checkExrHeader(dir / "tall.exr", cap);
      else
        readExr(dir / "tall.exr", cap);
      FAIL() << "no exception";
    } catch (const InputError& error) {
      EXPECT_THAT(error.what(), HasSubstr("declares a display window of 8×1024 pixels"));
    }
  }
  EXPECT_EQ(readExr(dir / "tall.exr", cap + 1).rgb().height(), 1024);
}

// A corrupt header that declares a huge data window over a tiny file (what fuzzing produces)
// must be refused, not allocated: 2^20 × 2^20 RGB floats would be 12 TiB. The header check, which
// readExr runs before OpenEXR opens the file and allocates by its windows, refuses it by the cap,
// and reading gives that refusal (any input error would not do: OpenEXR failing on the data after
// allocating gives one too).
TEST(ExrIo, AHeaderDeclaringAHugeImageIsAnInputError) {
  const test::TempDir dir;
  writeExr(dir / "small.exr", {{"", patternImage(4, 4, 3, 1.0f)}}, {});
  std::string bytes = fileBytes(dir / "small.exr");
  // The dataWindow attribute: its name, its type "box2i", the size 16, then xMin, yMin, xMax, yMax
  // as little-endian int32.
  const std::string name = std::string("dataWindow") + '\0' + "box2i" + '\0';
  const std::size_t at = bytes.find(name);
  ASSERT_NE(at, std::string::npos);
  const std::size_t box = at + name.size() + 4;
  const std::int32_t huge = (1 << 20) - 1;
  std::memcpy(bytes.data() + box + 8, &huge, 4);
  std::memcpy(bytes.data() + box + 12, &huge, 4);
  std::ofstream(dir / "huge.exr", std::ios::binary) << bytes;
  const auto refusal = ThrowsMessage<InputError>(
      HasSubstr("its header declares an image of 1048576×1048576 pixels of 3 channels"));
  EXPECT_THAT([&] { checkExrHeader(dir / "huge.exr"); }, refusal);
  EXPECT_THAT([&] { readRgb(dir / "huge.exr"); }, refusal);
}

// Found by fuzzing (fuzz/corpus/exr/regression-attribute-size-beyond-file.exr): OpenEXR allocates
// an attribute at its declared size before reading it, which took seconds and a gigabyte.
TEST(ExrIo, AHeaderAttributeLargerThanTheFileIsRefusedBeforeOpenExrReadsIt) {
  const test::TempDir dir;
  writeExr(dir / "small.exr", {{"", patternImage(4, 4, 3, 1.0f)}}, {{"gibench/note", "x"}});
  EXPECT_NO_THROW(checkExrHeader(dir / "small.exr"));
  std::string bytes = fileBytes(dir / "small.exr");
  const std::string name = std::string("gibench/note") + '\0' + "string" + '\0';
  const std::size_t at = bytes.find(name);
  ASSERT_NE(at, std::string::npos);
  const std::int32_t huge = 1 << 30;
  std::memcpy(bytes.data() + at + name.size(), &huge, 4);
  std::ofstream(dir / "damaged.exr", std::ios::binary) << bytes;
  try {
    readExr(dir / "damaged.exr");
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("attribute 'gibench/note' declares 1073741824 bytes"));
  }
  // Cut inside the header: the framing check names it.
  std::ofstream(dir / "cut.exr", std::ios::binary) << bytes.substr(0, at + 5);
  EXPECT_THROW(checkExrHeader(dir / "cut.exr"), InputError);
}

TEST(ExrIo, WritingIntoMissingDirectoryThrowsAndLeavesNoFile) {
  const test::TempDir dir;
  try {
    writeExr(dir / "missing" / "a.exr", {{"", Image(2, 2)}}, {});
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("does not exist"));
    EXPECT_THAT(error.what(), HasSubstr("a.exr"));
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(ExrIo, FailedRenameLeavesNoTemporaryFile) {
  const test::TempDir dir;
  fs::create_directories(dir / "taken.exr" / "inside");  // A non-empty directory as the target.
  EXPECT_THROW(writeExr(dir / "taken.exr", {{"", Image(2, 2)}}, {}), InputError);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

TEST(ExrIo, RejectsMalformedMetadataAndLayers) {
  const test::TempDir dir;
  const std::vector<Layer> rgb = {{"", Image(2, 2)}};
  for (const char* key : {"noslash", "/name", "space/", "oiio:x/y", "DateTime"})
    EXPECT_THROW(writeExr(dir / "a.exr", rgb, {{key, "v"}}), std::invalid_argument) << key;
  EXPECT_THROW(writeExr(dir / "a.exr", rgb, {{"gibench/empty", ""}}), std::invalid_argument);
  EXPECT_THROW(writeExr(dir / "a.exr", {}, {}), std::invalid_argument);
  EXPECT_THROW(writeExr(dir / "a.exr", {{"", Image(2, 2)}, {"v", Image(3, 2)}}, {}),
               std::invalid_argument);
  EXPECT_THROW(writeExr(dir / "a.exr", {{"v", Image(2, 2)}, {"v", Image(2, 2)}}, {}),
               std::invalid_argument);
  EXPECT_THROW(writeExr(dir / "a.exr", {{"", Image(2, 2, 5)}}, {}), std::invalid_argument);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(ExrIo, RgbThrowsWithoutMainLayer) {
  const test::TempDir dir;
  writeExr(dir / "a.exr", {{"variance", Image(2, 2)}}, {});
  const ExrFile file = readExr(dir / "a.exr");
  EXPECT_NE(file.findLayer("variance"), nullptr);
  EXPECT_THROW(file.rgb(), InputError);
}

}  // namespace
}  // namespace gib::image
