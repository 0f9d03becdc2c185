// The fixed display mapping under which PSNR and SSIM are measured: clamp to [0, 1], then the
// sRGB transfer curve. It is the "Standard" view of color/config.ocio, so these metrics score
// what a person sees in the PNGs the harness writes.
#pragma once

namespace gib::metrics {

// sRGB encoding of clamp(linear, 0, 1). The power segment is read from a table indexed by the
// float's exponent and top mantissa bits and interpolated linearly (relative error below 1e-7,
// a float's precision), because powf per channel dominated PSNR and SSIM.
float displayEncode(float linear);

// The same with std::pow, for tests of the table.
float displayEncodeExact(float linear);

}  // namespace gib::metrics
