// Scene-linear images for the report's image viewer (reports/assets/report.js): exposure, zoom
// and pixel readout need the linear values, not a display-referred PNG. Each image is stored as
// IEEE half floats (enough for radiance up to 65504 with 11 significant bits), base64-encoded, in
// a small script that registers them under a name: a report opened from disk (file://, where the
// browser refuses fetch and XMLHttpRequest) loads them with a plain <script src>. The format is
// documented in docs/results-schema.md ("Viewer data").
#pragma once

#include "image/image.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace gib::image {

struct ViewerLayer {
  std::string name;  // "image", "reference", "stderr", "flip": the viewer's handle
  const Image* image = nullptr;
};

// The script text: `(window.gibViewerData = window.gibViewerData || {})["<id>"] = {...};` with,
// per layer, its width, height, channel count and the half floats pixel after pixel (channels
// interleaved, row 0 at the top) in base64. Layers with a null or empty image are left out.
std::string viewerDataScript(std::string_view id, const std::vector<ViewerLayer>& layers);

// Writes viewerDataScript atomically.
void writeViewerData(const std::filesystem::path& path, std::string_view id,
                     const std::vector<ViewerLayer>& layers);

// The image reduced by a whole factor (box filter: the mean of each factor × factor block; a
// partial block at the right or bottom edge averages what it has) so that it is at most
// `max_width` pixels wide; the image itself when it already is. For thumbnails.
Image downsampleToWidth(const Image& image, int max_width);

}  // namespace gib::image
