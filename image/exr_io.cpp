#include "image/exr_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "common/input_error.h"
#include "common/join.h"
#include "image/atomic_write.h"

namespace gib::image {
namespace {

namespace fs = std::filesystem;

// Channel suffixes by channel count; the reader recognises the same sets.
constexpr std::array<std::array<std::string_view, 4>, 5> kSuffixes = {{
    {},
    {"Y"},
    {"Y", "A"},
    {"R", "G", "B"},
    {"R", "G", "B", "A"},
}};

// See the Metadata comment in exr_io.h.
bool isMetadataKey(std::string_view key) {
  const std::size_t slash = key.find('/');
  return slash != std::string_view::npos && slash > 0 && slash + 1 < key.size() &&
         key.substr(0, slash).find(':') == std::string_view::npos;
}

std::string channelName(const std::string& layer, std::string_view suffix) {
  return layer.empty() ? std::string(suffix) : layer + "." + std::string(suffix);
}

// Writing problems are bugs in the caller, not bad user input.
void checkLayers(const std::vector<Layer>& layers) {
  if (layers.empty()) throw std::invalid_argument("writeExr: no layers to write");
  if (layers[0].image.pixelCount() == 0)
    throw std::invalid_argument("writeExr: OpenEXR cannot store an empty image");
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const Layer& layer = layers[i];
    const int channels = layer.image.channels();
    if (channels < 1 || channels > 4)
      throw std::invalid_argument("writeExr: layer '" + layer.name + "' has " +
                                  std::to_string(channels) + " channels; 1 to 4 are supported");
    if (layer.image.width() != layers[0].image.width() ||
        layer.image.height() != layers[0].image.height())
      throw std::invalid_argument("writeExr: layer '" + layer.name +
                                  "' differs in size from layer '" + layers[0].name + "'");
    if (!layer.name.empty() && layer.name.back() == '.')
      throw std::invalid_argument("writeExr: layer name '" + layer.name + "' ends with '.'");
    for (std::size_t j = 0; j < i; ++j)
      if (layers[j].name == layer.name)
        throw std::invalid_argument("writeExr: two layers named '" + layer.name + "'");
  }
}

void checkMetadata(const Metadata& metadata) {
  // OpenEXR limits attribute names to 255 bytes.
  constexpr std::size_t kMaxKeyLength = 255;
  for (const auto& [key, value] : metadata) {
    if (!isMetadataKey(key) || key.size() > kMaxKeyLength)
      throw std::invalid_argument("writeExr: metadata key '" + key +
                                  "' is not of the form '<namespace>/<name>'");
    if (value.empty() || value.find('\0') != std::string::npos)
      throw std::invalid_argument("writeExr: metadata value of '" + key +
                                  "' is empty or contains NUL");
  }
}

OIIO::ImageSpec makeSpec(const std::vector<Layer>& layers, const Metadata& metadata) {
  OIIO::ImageSpec spec(layers[0].image.width(), layers[0].image.height(), 0, OIIO::TypeFloat);
  for (const Layer& layer : layers)
    for (int c = 0; c < layer.image.channels(); ++c)
      spec.channelnames.push_back(channelName(layer.name, kSuffixes[layer.image.channels()][c]));
  spec.nchannels = int(spec.channelnames.size());
  spec.alpha_channel = -1;
  spec.attribute("compression", "zip");
  // OpenImageIO stamps the current time into capDate unless DateTime is set. An empty capDate
  // (which readers, OpenImageIO included, skip) keeps the file free of time: equal inputs give
  // byte-identical files (docs/architecture.md, "Randomness").
  spec.attribute("DateTime", "");
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  return spec;
}

// Interleaves rows [y0, y1) of every layer into `values` (all channels of a pixel together).
void interleaveRows(const std::vector<Layer>& layers, int total_channels, int y0, int y1,
                    std::vector<float>& values) {
  const auto width = std::size_t(layers[0].image.width());
  const std::size_t pixels = width * std::size_t(y1 - y0);
  values.resize(pixels * std::size_t(total_channels));
  std::size_t first = 0;
  for (const Layer& layer : layers) {
    const auto channels = std::size_t(layer.image.channels());
    const float* source = layer.image.data().data() + std::size_t(y0) * width * channels;
    for (std::size_t p = 0; p < pixels; ++p)
      std::copy_n(source + p * channels, channels,
                  values.data() + p * std::size_t(total_channels) + first);
    first += channels;
  }
}

// OpenImageIO's messages may span lines; ours are one line (docs/architecture.md, "Errors").
std::string oneLine(std::string message) {
  while (!message.empty() && message.back() == '\n') message.pop_back();
  std::replace(message.begin(), message.end(), '\n', ' ');
  return message;
}

// Reading.

[[noreturn]] void throwUnreadable(const fs::path& path, const std::string& reason) {
  throw InputError("cannot read '" + path.string() + "': " + oneLine(reason) +
                   "; check the path and that the file is a complete OpenEXR image");
}

// An attribute's little-endian 32-bit integers; `bytes` holds at least 4·count.
std::vector<std::int64_t> littleEndianInts(const std::string& bytes, std::size_t count,
                                           bool is_signed) {
  std::vector<std::int64_t> values;
  for (std::size_t i = 0; i < count; ++i) {
    std::uint32_t v = 0;
    for (int b = 3; b >= 0; --b) v = v << 8 | std::uint8_t(bytes[4 * i + std::size_t(b)]);
    values.push_back(is_signed ? std::int64_t(std::int32_t(v)) : std::int64_t(v));
  }
  return values;
}

// The size of an attribute type that OpenEXR reads field by field, whatever size the attribute
// declares; 0 for the types that it reads by their declared size (string, vectors, unknown types)
// or that hold their own lengths (chlist, preview; checked by what they hold).
std::uint32_t fixedAttributeSize(const std::string& type) {
  static const std::array<std::pair<std::string_view, std::uint32_t>, 24> kSizes = {{
      {"box2i", 16},
      {"box2f", 16},
      {"chromaticities", 32},
      {"compression", 1},
      {"deepImageState", 1},
      {"double", 8},
      {"envmap", 1},
      {"float", 4},
      {"int", 4},
      {"keycode", 28},
      {"lineOrder", 1},
      {"m33d", 72},
      {"m33f", 36},
      {"m44d", 128},
      {"m44f", 64},
      {"rational", 8},
      {"tiledesc", 9},
      {"timecode", 8},
      {"v2d", 16},
      {"v2f", 8},
      {"v2i", 8},
      {"v3d", 24},
      {"v3f", 12},
      {"v3i", 12},
  }};
  for (const auto& [name, size] : kSizes)
    if (type == name) return size;
  return 0;
}

// A `chlist` attribute as OpenEXR reads it: per channel a NUL-terminated name of at most 255
// characters and 16 bytes, until an empty name. OpenEXR reads until that empty name, not by the
// declared size, so a list that ends elsewhere than at the declared size would make OpenEXR read
// the rest of the header from another place than this check does. The number of channels, or
// none when the list does not end exactly at the declared size.
std::optional<std::int64_t> framedChannelCount(const std::string& chlist) {
  std::int64_t count = 0;
  std::size_t at = 0;
  while (at < chlist.size() && chlist[at] != '\0') {
    const std::size_t end = chlist.find('\0', at);
    if (end == std::string::npos || end - at > 255) return std::nullopt;
    at = end + 1 + 16;
    ++count;
  }
  if (at + 1 != chlist.size()) return std::nullopt;  // the empty name is the last byte
  return count;
}

// Checked factor by factor, so that the product cannot overflow.
bool exceedsValues(std::int64_t width, std::int64_t height, std::int64_t channels,
                   std::size_t max_values) {
  const auto w = std::size_t(width), h = std::size_t(height), c = std::size_t(channels);
  return w > max_values || h > max_values / w || c > max_values / w / h;
}

// Throws when a declared extent holds more than `max_values` values; an extent with a factor of
// 0 or less is undeclared here (OpenEXR judges what it means) and passes.
void refuseIfTooLarge(const fs::path& path, const std::string& what, std::int64_t width,
                      std::int64_t height, std::int64_t channels, std::size_t max_values) {
  if (width <= 0 || height <= 0 || channels <= 0 ||
      !exceedsValues(width, height, channels, max_values))
    return;
  throw InputError(fmt::format(
      "cannot read '{}': its header declares {} of {}×{} pixels of {} channels, more than gibench "
      "reads ({} values); crop or downscale the image, or check that the file is not corrupt",
      path.string(), what, width, height, channels, max_values));
}

}  // namespace

void checkExrHeader(const fs::path& path, std::size_t max_values) {
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  const std::uintmax_t file_size = fs::file_size(path, ec);
  if (!in || ec) throwUnreadable(path, "cannot open it");
  const auto damaged = [&](const std::string& what) {
    throwUnreadable(path, "its header is damaged (" + what + ")");
  };
  std::array<unsigned char, 8> start{};
  if (!in.read(reinterpret_cast<char*>(start.data()), 8)) damaged("shorter than a header");
  if (start[0] != 0x76 || start[1] != 0x2f || start[2] != 0x31 || start[3] != 0x01)
    throwUnreadable(path, "not an OpenEXR file (wrong magic number)");
  const bool multipart = (start[5] & 0x10) != 0;  // version flags, bit 12
  // A NUL-terminated name of at most 255 characters; empty at the end of a header.
  const auto readName = [&]() {
    std::string name;
    for (char c; in.get(c);) {
      if (c == '\0') return name;
      if (name.size() == 255) damaged("a name longer than 255 characters");
      name.push_back(c);
    }
    damaged("it ends inside a name");
    return name;
  };
  for (int header = 0;; ++header) {
    std::string name = readName();
    if (name.empty()) {
      if (header == 0 && !multipart) damaged("no attributes");
      break;  // a single-part file's header ends; in a multi-part one, the empty header
    }
    // The attributes that size OpenEXR's buffers; 0 where the header does not say.
    std::int64_t width = 0, height = 0, channels = 0, tile_width = 0, tile_height = 0,
                 display_width = 0, display_height = 0;
    for (; !name.empty(); name = readName()) {
      const std::string type = readName();
      if (type.empty()) damaged("attribute '" + name + "' has no type");
      unsigned char size_bytes[4];
      if (!in.read(reinterpret_cast<char*>(size_bytes), 4))
        damaged("it ends inside '" + name + "'");
      const std::uint32_t size = std::uint32_t(size_bytes[0]) | std::uint32_t(size_bytes[1]) << 8 |
                                 std::uint32_t(size_bytes[2]) << 16 |
                                 std::uint32_t(size_bytes[3]) << 24;
      const auto offset = std::uintmax_t(in.tellg());
      if (size > 0x7fffffffu || size > file_size - offset)
        damaged("attribute '" + name + "' declares " + std::to_string(size) +
                " bytes, more than the file holds");
      // OpenEXR reads these by what they hold rather than by the declared size: a size that
      // disagrees would put its reading elsewhere in the file than this walk (found by fuzzing:
      // a channel list longer than its size hid, from this check, an attribute of a gigabyte).
      const std::uint32_t fixed = fixedAttributeSize(type);
      if (fixed != 0 && size != fixed)
        damaged("attribute '" + name + "' declares " + std::to_string(size) + " bytes; a " + type +
                " holds " + std::to_string(fixed));
      const bool read = type == "chlist" || type == "preview" ||
                        ((name == "dataWindow" || name == "displayWindow") && type == "box2i") ||
                        (name == "tiles" && type == "tiledesc");
      if (!read) {
        in.seekg(std::streamoff(size), std::ios::cur);
        continue;
      }
      std::string value(size, '\0');
      if (!in.read(value.data(), std::streamsize(size))) damaged("it ends inside '" + name + "'");
      if (type == "chlist") {
        const std::optional<std::int64_t> count = framedChannelCount(value);
        if (!count)
          damaged("attribute '" + name + "': its channel list does not end at its size, " +
                  std::to_string(size) + " bytes");
        if (name == "channels") channels = *count;
      } else if (type == "preview") {
        // Width and height, then 4 bytes per pixel, which OpenEXR allocates by the two numbers.
        const auto extent =
            size >= 8 ? littleEndianInts(value, 2, false) : std::vector<std::int64_t>{-1, -1};
        if (size < 8 || std::uint64_t(extent[0]) * std::uint64_t(extent[1]) * 4 + 8 != size)
          damaged("attribute '" + name + "': its preview image does not fill its size, " +
                  std::to_string(size) + " bytes");
      } else if (type == "box2i") {
        const auto box = littleEndianInts(value, 4, true);  // xMin, yMin, xMax, yMax
        (name == "dataWindow" ? width : display_width) = box[2] - box[0] + 1;
        (name == "dataWindow" ? height : display_height) = box[3] - box[1] + 1;
      } else {
        const auto tile = littleEndianInts(value, 2, false);  // xSize, ySize (then a mode byte)
        tile_width = tile[0];
        tile_height = tile[1];
      }
    }
    // What the attributes mean is OpenEXR's to check (an empty window, a tile of 0 pixels);
    // the sizes are checked here, since OpenEXR allocates by them when it opens the file.
    refuseIfTooLarge(path, "an image", width, height, channels, max_values);
    refuseIfTooLarge(path, "tiles", tile_width, tile_height, channels, max_values);
    // The layers are images of the display window (readExr), which may be far larger than the
    // data window (found by fuzzing: 24×16 pixels of data in a window 16 776 208 high).
    refuseIfTooLarge(path, "a display window", display_width, display_height, channels, max_values);
    if (!multipart) break;
  }
}

namespace {

// Channels of one layer in the order the Image stores them.
struct LayerChannels {
  std::string name;
  std::vector<int> indices;  // Into the file's channels; one index may repeat (Y as grey).
};

std::string prefixOf(std::string_view channel) {
  const std::size_t dot = channel.rfind('.');
  return dot == std::string_view::npos ? std::string() : std::string(channel.substr(0, dot));
}

// Groups the file's channels into layers (rules in exr_io.h): R,G,B[,A] of a prefix, or a prefix
// with only Y[,A], form one layer; any other channel becomes a one-channel layer named by its full
// channel name.
std::vector<LayerChannels> groupChannels(const std::vector<std::string>& names) {
  std::vector<std::string> prefixes;
  for (const std::string& name : names)
    if (std::find(prefixes.begin(), prefixes.end(), prefixOf(name)) == prefixes.end())
      prefixes.push_back(prefixOf(name));
  // The main layer first, the others in file order.
  std::stable_partition(prefixes.begin(), prefixes.end(),
                        [](const std::string& prefix) { return prefix.empty(); });

  std::vector<LayerChannels> layers;
  std::vector<bool> used(names.size(), false);
  for (const std::string& prefix : prefixes) {
    auto find = [&](std::string_view suffix) {
      for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == channelName(prefix, suffix)) return int(i);
      return -1;
    };
    const int r = find("R"), g = find("G"), b = find("B"), a = find("A"), y = find("Y");
    const auto size = std::count_if(names.begin(), names.end(), [&](const std::string& name) {
      return prefixOf(name) == prefix;
    });
    LayerChannels layer{prefix, {}};
    if (r >= 0 && g >= 0 && b >= 0) {
      layer.indices = {r, g, b};
    } else if (y >= 0 && size == (a >= 0 ? 2 : 1)) {
      // Luminance: the main layer is always RGB, so it becomes grey.
      layer.indices = prefix.empty() ? std::vector<int>{y, y, y} : std::vector<int>{y};
    } else {
      continue;
    }
    if (a >= 0) layer.indices.push_back(a);
    for (int index : layer.indices) used[std::size_t(index)] = true;
    layers.push_back(std::move(layer));
  }
  for (std::size_t i = 0; i < names.size(); ++i)
    if (!used[i]) layers.push_back({names[i], {int(i)}});
  return layers;
}

// Copies the data window's pixels (all channels interleaved) into per-layer images of the
// display window's size.
std::vector<Layer> scatter(const OIIO::ImageSpec& spec, const std::vector<float>& values,
                           const std::vector<LayerChannels>& groups) {
  std::vector<Layer> layers;
  for (const LayerChannels& group : groups) {
    Image image(spec.full_width, spec.full_height, int(group.indices.size()));
    const int x0 = std::max(spec.x, spec.full_x);
    const int x1 = std::min(spec.x + spec.width, spec.full_x + spec.full_width);
    const int y0 = std::max(spec.y, spec.full_y);
    const int y1 = std::min(spec.y + spec.height, spec.full_y + spec.full_height);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        const float* source = values.data() + (std::size_t(y - spec.y) * std::size_t(spec.width) +
                                               std::size_t(x - spec.x)) *
                                                  std::size_t(spec.nchannels);
        float* target = image.pixel(x - spec.full_x, y - spec.full_y);
        for (std::size_t c = 0; c < group.indices.size(); ++c) target[c] = source[group.indices[c]];
      }
    }
    layers.push_back({group.name, std::move(image)});
  }
  return layers;
}

Metadata readMetadata(const OIIO::ImageSpec& spec) {
  Metadata metadata;
  for (const OIIO::ParamValue& attribute : spec.extra_attribs) {
    const std::string name = attribute.name().string();
    if (attribute.type() == OIIO::TypeString && isMetadataKey(name))
      metadata[name] = attribute.get_string();
  }
  return metadata;
}

}  // namespace

const Image* ExrFile::findLayer(std::string_view name) const {
  for (const Layer& layer : layers)
    if (layer.name == name) return &layer.image;
  return nullptr;
}

const Image& ExrFile::rgb() const {
  const Image* image = findLayer("");
  if (!image)
    throw InputError(
        "the EXR file has no R, G, B (or Y) channels; write the image with RGB "
        "channels or name the layer to use");
  return *image;
}

void writeExr(const fs::path& path, const std::vector<Layer>& layers, const Metadata& metadata) {
  checkLayers(layers);
  checkMetadata(metadata);
  const OIIO::ImageSpec spec = makeSpec(layers, metadata);

  // Encoded into memory, then written with every I/O error checked: OpenEXR writes the line offset
  // table when the file closes, from a destructor that ignores write errors, so on a full disk a
  // file could be left with a broken table although close() succeeded (found by
  // scripts/faults-disk-full.sh).
  std::vector<unsigned char> encoded;
  {
    OIIO::Filesystem::IOVecOutput memory(encoded);
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create("openexr");
    if (!output) throw std::logic_error("OpenImageIO has no OpenEXR writer");
    auto fail = [&] {
      throw InputError("cannot write '" + path.string() + "': " + oneLine(output->geterror()) +
                       "; check that the directory is writable and the disk has space");
    };
    if (!output->set_ioproxy(&memory)) throw std::logic_error("OpenEXR writer without IOProxy");
    if (!output->open(path.string(), spec)) fail();
    // Rows go out in bands, so a large multi-layer image is never copied whole as floats (this
    // keeps a 1024² reference render within its memory budget); only the compressed file is
    // held whole, in `encoded`.
    constexpr int kRowsPerBand = 64;
    std::vector<float> band;
    for (int y0 = 0; y0 < spec.height; y0 += kRowsPerBand) {
      const int y1 = std::min(y0 + kRowsPerBand, spec.height);
      interleaveRows(layers, spec.nchannels, y0, y1, band);
      if (!output->write_scanlines(y0, y1, 0, OIIO::TypeFloat, band.data())) fail();
    }
    if (!output->close()) fail();
  }
  detail::writeBytesAtomically(path,
                               {reinterpret_cast<const char*>(encoded.data()), encoded.size()});
}

ExrFile readExr(const fs::path& path, std::size_t max_values) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) throwUnreadable(path, "no such file");
  if (fs::is_directory(status)) throwUnreadable(path, "it is a directory");

  checkExrHeader(path, max_values);
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create("openexr");
  if (!input) throw std::logic_error("OpenImageIO has no OpenEXR reader");
  OIIO::ImageSpec spec;
  if (!input->open(path.string(), spec)) throwUnreadable(path, input->geterror());
  if (spec.deep) throwUnreadable(path, "deep EXR images are not supported");
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throwUnreadable(path, "its header declares an empty image");
  // Checked again as OpenImageIO reads the header (the first part's, whatever the file's layout).
  refuseIfTooLarge(path, "an image", spec.width, spec.height, spec.nchannels, max_values);
  const auto width = std::size_t(spec.width), height = std::size_t(spec.height),
             channels = std::size_t(spec.nchannels);
  // The layers hold the display window, luminance widened to grey: checked before
  // any pixel is read.
  const std::vector<LayerChannels> groups = groupChannels(spec.channelnames);
  std::size_t layer_channels = 0;
  for (const LayerChannels& group : groups) layer_channels += group.indices.size();
  if (spec.full_width <= 0 || spec.full_height <= 0)
    throwUnreadable(path, "its header declares an empty display window");
  refuseIfTooLarge(path, "a display window", spec.full_width, spec.full_height,
                   std::int64_t(layer_channels), max_values);
  std::vector<float> values(width * height * channels);
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, values.data()))
    throwUnreadable(path, input->geterror());

  ExrFile file;
  file.layers = scatter(spec, values, groups);
  file.metadata = readMetadata(spec);
  return file;
}

Image readRgb(const fs::path& path, std::size_t max_values) {
  const ExrFile file = readExr(path, max_values);
  const Image* main = file.findLayer("");
  if (!main) {
    // Without a complete R, G, B set, readExr left each of those present as a layer of its own.
    std::vector<std::string> missing;
    for (const char* name : {"R", "G", "B"})
      if (!file.findLayer(name)) missing.emplace_back(name);
    throw InputError("'" + path.string() + "' has no " + joinNames(missing, ", ") + " channel" +
                     (missing.size() > 1 ? "s" : "") +
                     "; give an EXR whose main layer has R, G and B channels (alpha may be there)");
  }
  if (main->channels() == 3) return *main;
  Image rgb(main->width(), main->height(), 3);
  const auto channels = std::size_t(main->channels());
  const std::span<const float> source = main->data();
  const std::span<float> target = rgb.data();
  for (std::size_t p = 0; p < main->pixelCount(); ++p)
    std::copy_n(source.data() + p * channels, 3, target.data() + p * 3);
  return rgb;
}

}  // namespace gib::image
