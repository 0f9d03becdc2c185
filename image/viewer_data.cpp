#include "image/viewer_data.h"

#include "image/output_files.h"

#include <Imath/half.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace gib::image {

namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const std::uint32_t v = (std::uint32_t(bytes[i]) << 16) | (std::uint32_t(bytes[i + 1]) << 8) |
                            std::uint32_t(bytes[i + 2]);
    for (int shift : {18, 12, 6, 0}) out += kAlphabet[(v >> shift) & 63];
  }
  if (const std::size_t rest = bytes.size() - i; rest > 0) {
    std::uint32_t v = std::uint32_t(bytes[i]) << 16;
    if (rest == 2) v |= std::uint32_t(bytes[i + 1]) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += rest == 2 ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

// Little-endian half floats: what a JavaScript Uint16Array reads on every platform a browser
// runs on.
std::vector<std::uint8_t> halfBytes(const Image& image) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(image.data().size() * 2);
  constexpr float kHalfMax = 65504.0f;
  for (float value : image.data()) {
    // A finite value beyond the half range (a firefly) stays finite: only NaN and infinity, a
    // renderer's bug, reach the viewer as such (it shows them magenta).
    if (std::isfinite(value)) value = std::clamp(value, -kHalfMax, kHalfMax);
    const std::uint16_t bits = half(value).bits();
    bytes.push_back(std::uint8_t(bits & 0xff));
    bytes.push_back(std::uint8_t(bits >> 8));
  }
  return bytes;
}

// Ids are job slugs and store keys; quoting keeps any other character from ending the string.
std::string jsString(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\' || c == '<' || static_cast<unsigned char>(c) < 0x20)
      out += fmt::format("\\u{:04x}", static_cast<unsigned char>(c));
    else
      out += c;
  }
  return out + "\"";
}

}  // namespace

std::string viewerDataScript(std::string_view id, const std::vector<ViewerLayer>& layers) {
  std::string entries;
  for (const ViewerLayer& layer : layers) {
    if (!layer.image || layer.image->pixelCount() == 0) continue;
    const Image& image = *layer.image;
    entries +=
        fmt::format("{}{}: {{\"width\": {}, \"height\": {}, \"channels\": {}, \"half\": \"{}\"}}",
                    entries.empty() ? "" : ",\n  ", jsString(layer.name), image.width(),
                    image.height(), image.channels(), base64(halfBytes(image)));
  }
  return fmt::format(
      "// GI Bench viewer data (docs/results-schema.md, \"Viewer data\"): linear values as "
      "half floats.\n(window.gibViewerData = window.gibViewerData || {{}})[{}] = {{\"layers\": "
      "{{\n  {}\n}}}};\n",
      jsString(id), entries);
}

void writeViewerData(const std::filesystem::path& path, std::string_view id,
                     const std::vector<ViewerLayer>& layers) {
  writeTextFile(path, viewerDataScript(id, layers));
}

Image downsampleToWidth(const Image& image, int max_width) {
  if (max_width <= 0 || image.width() <= max_width) return image;
  const int factor = (image.width() + max_width - 1) / max_width;
  const int width = (image.width() + factor - 1) / factor;
  const int height = (image.height() + factor - 1) / factor;
  const int channels = image.channels();
  Image out(width, height, channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int x1 = std::min(image.width(), (x + 1) * factor);
      const int y1 = std::min(image.height(), (y + 1) * factor);
      float* sum = out.pixel(x, y);
      for (int sy = y * factor; sy < y1; ++sy)
        for (int sx = x * factor; sx < x1; ++sx)
          for (int c = 0; c < channels; ++c) sum[c] += image.pixel(sx, sy)[c];
      const float count = float((x1 - x * factor) * (y1 - y * factor));
      for (int c = 0; c < channels; ++c) sum[c] /= count;
    }
  return out;
}

}  // namespace gib::image
