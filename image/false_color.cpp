#include "image/false_color.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace gib::image {

namespace {

// Nine evenly spaced samples of matplotlib's magma colour map (sRGB), interpolated linearly:
// perceptually ordered from black through purple and orange to pale yellow, and readable in
// greyscale.
constexpr std::array<std::array<float, 3>, 9> kMagma = {{{0.001462f, 0.000466f, 0.013866f},
                                                         {0.078815f, 0.054184f, 0.211667f},
                                                         {0.232077f, 0.059889f, 0.437695f},
                                                         {0.390384f, 0.100379f, 0.501864f},
                                                         {0.550287f, 0.161158f, 0.505719f},
                                                         {0.716387f, 0.214982f, 0.475290f},
                                                         {0.868793f, 0.287728f, 0.409303f},
                                                         {0.967671f, 0.439703f, 0.359810f},
                                                         {0.987053f, 0.991438f, 0.749504f}}};

float srgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// A 3 × 5 pixel font for the colour bar's labels: each glyph is five rows of three bits.
struct Glyph {
  char c;
  std::array<std::uint8_t, 5> rows;
};
constexpr Glyph kGlyphs[] = {{'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}},
                             {'3', {7, 1, 7, 1, 7}}, {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}},
                             {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}}, {'8', {7, 5, 7, 5, 7}},
                             {'9', {7, 5, 7, 1, 7}}, {'.', {0, 0, 0, 0, 2}}, {'-', {0, 0, 7, 0, 0}},
                             {'+', {0, 2, 7, 2, 0}}, {'e', {0, 7, 7, 4, 7}}};

void drawText(Image& image, int x, int y, int scale, const std::string& text) {
  for (char c : text) {
    const Glyph* glyph = nullptr;
    for (const Glyph& g : kGlyphs)
      if (g.c == c) glyph = &g;
    if (glyph)
      for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 3; ++col) {
          if (!(glyph->rows[row] & (4 >> col))) continue;
          for (int dy = 0; dy < scale; ++dy)
            for (int dx = 0; dx < scale; ++dx) {
              int px = x + col * scale + dx, py = y + row * scale + dy;
              if (px < 0 || py < 0 || px >= image.width() || py >= image.height()) continue;
              float* p = image.pixel(px, py);
              p[0] = p[1] = p[2] = 1.0f;
            }
        }
    x += 4 * scale;
  }
}

void setMagma(float t, float* pixel) {
  float srgb[3];
  magmaSrgb(t, srgb);
  for (int c = 0; c < 3; ++c) pixel[c] = srgbToLinear(srgb[c]);
}

}  // namespace

void magmaSrgb(float t, float rgb[3]) {
  t = std::clamp(std::isfinite(t) ? t : 1.0f, 0.0f, 1.0f);
  float x = t * float(kMagma.size() - 1);
  auto i = std::min<std::size_t>(std::size_t(x), kMagma.size() - 2);
  float f = x - float(i);
  for (int c = 0; c < 3; ++c) rgb[c] = kMagma[i][c] * (1 - f) + kMagma[i + 1][c] * f;
}

Image falseColorWithBar(const Image& scalar, float low, float high) {
  const int width = scalar.width();
  // The label font is scaled with the image so it stays legible on large maps.
  const int scale = std::max(1, width / 256);
  const int bar_height = std::max(6, scalar.height() / 24);
  const int label_height = 7 * scale;
  Image out(width, scalar.height() + bar_height + label_height, 3, 0.0f);
  const float range = high > low ? high - low : 1.0f;

  // The map itself. Non-finite values take the top colour: they are counted and reported
  // separately, and must not look like zero error.
  for (int y = 0; y < scalar.height(); ++y)
    for (int x = 0; x < width; ++x)
      setMagma((scalar.pixel(x, y)[0] - low) / range, out.pixel(x, y));

  // The bar: low on the left, high on the right, labelled underneath.
  for (int y = scalar.height(); y < scalar.height() + bar_height; ++y)
    for (int x = 0; x < width; ++x)
      setMagma(width > 1 ? float(x) / float(width - 1) : 0.0f, out.pixel(x, y));
  const int text_y = scalar.height() + bar_height + scale;
  const std::string low_text = fmt::format("{:.3g}", low);
  const std::string high_text = fmt::format("{:.3g}", high);
  drawText(out, scale, text_y, scale, low_text);
  drawText(out, width - int(high_text.size()) * 4 * scale, text_y, scale, high_text);
  return out;
}

}  // namespace gib::image
