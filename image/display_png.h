// Pictures as they are shown: the 8-bit sRGB values of the PNGs writePng (image/display.h)
// writes, read and written without any colour transform. For assembling pictures from PNGs that
// are already display-referred (a figure's panels composited into one PNG, reports/
// figure_composite.h): putting them through the display transform again would change them.
// Never for measuring, which reads the scene-linear EXR.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace gib::image {

struct DisplayPicture {
  DisplayPicture() = default;
  // Filled with one grey level (255: white).
  DisplayPicture(int width, int height, std::uint8_t fill = 255);

  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes per pixel, row 0 at the top; width × height × 3

  std::uint8_t* pixel(int x, int y) { return rgb.data() + offset(x, y); }
  const std::uint8_t* pixel(int x, int y) const { return rgb.data() + offset(x, y); }

 private:
  std::size_t offset(int x, int y) const {
    return (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
  }
};

// Reads a PNG as 8-bit RGB: grey is repeated into R, G and B, an alpha channel is composited over
// white (how a page shows it), 16-bit values are rounded to 8 bits. Throws gib::InputError naming
// the file when it is missing, unreadable or not a PNG.
DisplayPicture readDisplayPng(const std::filesystem::path& path);

// Writes the bytes as an 8-bit RGB PNG, unchanged; atomically (a temporary name, then renamed).
// Throws gib::InputError for a missing or unwritable directory, std::invalid_argument for an
// empty picture or one whose byte count does not match its size.
void writeDisplayPng(const std::filesystem::path& path, const DisplayPicture& picture);

}  // namespace gib::image
