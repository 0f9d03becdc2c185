#include "image/display_png.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

#include "common/input_error.h"
#include "image/atomic_write.h"

namespace gib::image {

namespace {

namespace fs = std::filesystem;

std::string oneLine(std::string message) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  while (!message.empty() && message.back() == ' ') message.pop_back();
  return message;
}

[[noreturn]] void throwUnreadable(const fs::path& path, const std::string& reason) {
  throw InputError("cannot read '" + path.string() + "': " + oneLine(reason) +
                   "; give an existing PNG file");
}

}  // namespace

DisplayPicture::DisplayPicture(int width_, int height_, std::uint8_t fill)
    : width(width_), height(height_) {
  if (width_ < 0 || height_ < 0)
    throw std::invalid_argument("DisplayPicture: negative size " + std::to_string(width_) + "x" +
                                std::to_string(height_));
  rgb.assign(std::size_t(width_) * std::size_t(height_) * 3, fill);
}

DisplayPicture readDisplayPng(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) throwUnreadable(path, "no such file");
  if (fs::is_directory(status)) throwUnreadable(path, "it is a directory");

  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create("png");
  if (!input) throw std::logic_error("OpenImageIO has no PNG reader");
  OIIO::ImageSpec spec;
  if (!input->open(path.string(), spec)) throwUnreadable(path, input->geterror());
  const int channels = spec.nchannels;
  if (channels < 1 || channels > 4) throwUnreadable(path, std::to_string(channels) + " channels");
  std::vector<std::uint8_t> values(std::size_t(spec.width) * std::size_t(spec.height) *
                                   std::size_t(channels));
  if (!input->read_image(0, 0, 0, channels, OIIO::TypeUInt8, values.data()))
    throwUnreadable(path, input->geterror());

  // Grey (+ alpha) or RGB (+ alpha); OpenImageIO hands alpha over associated (premultiplied), so
  // over white a pixel is its colour plus what alpha leaves of the white.
  const bool alpha = channels == 2 || channels == 4;
  const int colours = alpha ? channels - 1 : channels;
  DisplayPicture picture(spec.width, spec.height, 0);
  for (std::size_t p = 0; p < std::size_t(spec.width) * std::size_t(spec.height); ++p) {
    const std::uint8_t* source = values.data() + p * std::size_t(channels);
    const int white = alpha ? 255 - source[colours] : 0;
    for (int c = 0; c < 3; ++c)
      picture.rgb[p * 3 + std::size_t(c)] =
          std::uint8_t(std::min(255, source[colours == 1 ? 0 : c] + white));
  }
  return picture;
}

void writeDisplayPng(const fs::path& path, const DisplayPicture& picture) {
  if (picture.width <= 0 || picture.height <= 0)
    throw std::invalid_argument("writeDisplayPng: the picture is empty");
  if (picture.rgb.size() != std::size_t(picture.width) * std::size_t(picture.height) * 3)
    throw std::invalid_argument("writeDisplayPng: " + std::to_string(picture.rgb.size()) +
                                " bytes for a picture of " + std::to_string(picture.width) + "x" +
                                std::to_string(picture.height));
  const OIIO::ImageSpec spec(picture.width, picture.height, 3, OIIO::TypeUInt8);
  // Encoded into memory, then written with every I/O error checked (as writeExr does).
  std::vector<unsigned char> encoded;
  {
    OIIO::Filesystem::IOVecOutput memory(encoded);
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create("png");
    if (!output) throw std::logic_error("OpenImageIO has no PNG writer");
    if (!output->set_ioproxy(&memory)) throw std::logic_error("PNG writer without IOProxy");
    if (!output->open(path.string(), spec) ||
        !output->write_image(OIIO::TypeUInt8, picture.rgb.data()) || !output->close())
      throw InputError("cannot write '" + path.string() + "': " + oneLine(output->geterror()) +
                       "; check that the directory is writable");
  }
  detail::writeBytesAtomically(path,
                               {reinterpret_cast<const char*>(encoded.data()), encoded.size()});
}

}  // namespace gib::image
