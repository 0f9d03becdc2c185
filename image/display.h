// PNG pictures for people to look at (reports, quick checks): never for measuring, which uses
// the scene-linear EXR (docs/architecture.md, "Conventions", Images). The display transform comes
// from the project's OpenColorIO config, color/config.ocio, compiled into the library.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/image.h"

namespace gib::image {

struct DisplaySettings {
  // Scene-linear values are multiplied by 2^exposure_stops before the view transform.
  float exposure_stops = 0.0f;
  // A view of the config's "sRGB" display: "Standard" (sRGB curve, clipped at 1) or "Filmic"
  // (highlights compressed, 16 shows as white); see color/config.ocio.
  std::string view = "Standard";
};

// Writes an 8-bit sRGB PNG (RGB, no alpha) of a 1-, 3- or 4-channel image (grey is repeated,
// alpha ignored): exposure, then the display transform from scene_linear to display "sRGB" with
// the given view, then rounding to 8 bits. Pixels with a NaN or infinite channel show as magenta
// (255, 0, 255), so that a renderer bug is visible instead of hidden as black. Written under a
// temporary name and renamed, like writeExr. Throws gib::InputError for a missing or unwritable
// directory, an unknown view (the message lists the views) or a non-finite exposure.
void writePng(const std::filesystem::path& path, const Image& image,
              const DisplaySettings& settings = {});

// The views of display "sRGB", in config order: {"Standard", "Filmic"}.
std::vector<std::string> displayViews();

}  // namespace gib::image
