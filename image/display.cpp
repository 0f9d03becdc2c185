#include "image/display.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "common/input_error.h"
#include "image/display_png.h"

namespace OCIO = OCIO_NAMESPACE;

namespace gib::image {
namespace detail {
// The text of color/config.ocio, generated into the build tree by image/CMakeLists.txt.
extern const std::string_view kEmbeddedOcioConfig;
}  // namespace detail

namespace {

namespace fs = std::filesystem;

constexpr const char* kDisplay = "sRGB";
// Shown for pixels with a NaN or infinite channel.
constexpr std::uint8_t kNonFiniteRgb[3] = {255, 0, 255};

// Parsed once; a config that fails to load is a defect of the build, not of user input.
OCIO::ConstConfigRcPtr config() {
  static const OCIO::ConstConfigRcPtr loaded = [] {
    std::istringstream text{std::string(detail::kEmbeddedOcioConfig)};
    try {
      OCIO::ConstConfigRcPtr parsed = OCIO::Config::CreateFromStream(text);
      parsed->validate();
      return parsed;
    } catch (const OCIO::Exception& error) {
      throw std::logic_error(std::string("the embedded color/config.ocio is invalid: ") +
                             error.what());
    }
  }();
  return loaded;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

OCIO::ConstCPUProcessorRcPtr displayProcessor(const fs::path& path, const std::string& view) {
  const std::vector<std::string> views = displayViews();
  if (std::find(views.begin(), views.end(), view) == views.end())
    throw InputError("cannot write '" + path.string() + "': unknown view '" + view +
                     "'; choose one of the views " + joined(views));
  return config()
      ->getProcessor(OCIO::ROLE_SCENE_LINEAR, kDisplay, view.c_str(), OCIO::TRANSFORM_DIR_FORWARD)
      ->getDefaultCPUProcessor();
}

// Packed RGB of the exposed image; non-finite pixels are zeroed (OCIO gets clean input) and
// marked so that they can be painted magenta after the transform.
std::vector<float> exposedRgb(const Image& image, float scale, std::vector<bool>& non_finite) {
  std::vector<float> rgb(image.pixelCount() * 3);
  non_finite.assign(image.pixelCount(), false);
  const int channels = image.channels();
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const std::size_t index = std::size_t(y) * std::size_t(image.width()) + std::size_t(x);
      const float* source = image.pixel(x, y);
      float* target = rgb.data() + index * 3;
      for (int c = 0; c < 3; ++c) target[c] = source[channels >= 3 ? c : 0];
      if (!std::isfinite(target[0]) || !std::isfinite(target[1]) || !std::isfinite(target[2])) {
        non_finite[index] = true;
        std::fill_n(target, 3, 0.0f);
        continue;
      }
      // A huge exposure may overflow a finite value; it is bright, not broken.
      for (int c = 0; c < 3; ++c)
        target[c] = std::clamp(target[c] * scale, -std::numeric_limits<float>::max(),
                               std::numeric_limits<float>::max());
    }
  }
  return rgb;
}

std::vector<std::uint8_t> quantize(const std::vector<float>& display,
                                   const std::vector<bool>& non_finite) {
  std::vector<std::uint8_t> bytes(display.size());
  for (std::size_t i = 0; i < display.size(); ++i) {
    const float value = std::isfinite(display[i]) ? std::clamp(display[i], 0.0f, 1.0f) : 0.0f;
    bytes[i] = std::uint8_t(std::lround(value * 255.0f));
  }
  for (std::size_t p = 0; p < non_finite.size(); ++p)
    if (non_finite[p]) std::copy_n(kNonFiniteRgb, 3, bytes.data() + p * 3);
  return bytes;
}

}  // namespace

std::vector<std::string> displayViews() {
  const OCIO::ConstConfigRcPtr loaded = config();
  std::vector<std::string> views;
  for (int i = 0; i < loaded->getNumViews(kDisplay); ++i)
    views.emplace_back(loaded->getView(kDisplay, i));
  return views;
}

void writePng(const fs::path& path, const Image& image, const DisplaySettings& settings) {
  if (image.channels() != 1 && image.channels() != 3 && image.channels() != 4)
    throw std::invalid_argument("writePng: images with " + std::to_string(image.channels()) +
                                " channels have no colour interpretation");
  if (image.pixelCount() == 0) throw std::invalid_argument("writePng: the image is empty");
  if (!std::isfinite(settings.exposure_stops))
    throw InputError("cannot write '" + path.string() + "': exposure " +
                     std::to_string(settings.exposure_stops) + " is not a finite number of stops");
  const OCIO::ConstCPUProcessorRcPtr processor = displayProcessor(path, settings.view);

  // Step 1: exposure, in scene-linear.
  std::vector<bool> non_finite;
  std::vector<float> rgb = exposedRgb(image, std::exp2(settings.exposure_stops), non_finite);
  // Step 2: the view transform to display-encoded sRGB.
  OCIO::PackedImageDesc description(rgb.data(), image.width(), image.height(), 3);
  processor->apply(description);
  // Step 3: 8 bits, magenta where the input was not finite.
  DisplayPicture picture;
  picture.width = image.width();
  picture.height = image.height();
  picture.rgb = quantize(rgb, non_finite);
  writeDisplayPng(path, picture);
}

}  // namespace gib::image
