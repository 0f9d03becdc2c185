// The fixed display mapping under which PSNR and SSIM are measured: clamp to [0, 1], then the
// sRGB transfer curve. It is the "Standard" view of color/config.ocio, so these metrics score
// what a person sees in the PNGs the harness writes.
#pragma once

#include <algorithm>
#include <cmath>

namespace gib::metrics {

inline float displayEncode(float linear) {
  float v = std::clamp(linear, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

}  // namespace gib::metrics
