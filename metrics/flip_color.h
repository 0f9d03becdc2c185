// FLIP's colour spaces, inline because they run per pixel inside the filters' loops: linear
// Rec.709 RGB, CIE XYZ, the opponent space YyCxCz the contrast sensitivity filters work in, and
// CIELab with the Hunt adjustment for the colour distance. Private to metrics/flip*.cpp.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace gib::metrics::flip_detail {

// Rec.709 primaries with a D65 white (IEC 61966-2-1, the sRGB standard), in the exact rational
// form NVlabs/flip uses, so that white RGB (1, 1, 1) maps to exactly the white point below.
inline constexpr float kRgbToXyz[3][3] = {
    {float(10135552.0 / 24577794.0), float(8788810.0 / 24577794.0), float(4435075.0 / 24577794.0)},
    {float(2613072.0 / 12288897.0), float(8788810.0 / 12288897.0), float(887015.0 / 12288897.0)},
    {float(1425312.0 / 73733382.0), float(8788810.0 / 73733382.0), float(70074185.0 / 73733382.0)}};
// The inverse of kRgbToXyz, to the precision NVlabs/flip states it.
inline constexpr float kXyzToRgb[3][3] = {{3.241003275f, -1.537398934f, -0.498615861f},
                                          {-0.969224334f, 1.875930071f, 0.041554224f},
                                          {0.055639423f, -0.204011202f, 1.057148933f}};
// D65 white, XYZ of RGB (1, 1, 1): the row sums of kRgbToXyz. FLIP normalises by it both in
// YyCxCz and in CIELab (FLIP paper, colour pipeline).
inline constexpr double kWhiteXExact = (10135552.0 + 8788810.0 + 4435075.0) / 24577794.0;
inline constexpr double kWhiteZExact = (1425312.0 + 8788810.0 + 70074185.0) / 73733382.0;
inline constexpr float kWhiteX = float(kWhiteXExact);
inline constexpr float kWhiteZ = float(kWhiteZExact);
inline constexpr float kInvWhiteX = float(1.0 / kWhiteXExact);
inline constexpr float kInvWhiteZ = float(1.0 / kWhiteZExact);

struct Opponent {
  float y, cx, cz;  // YyCxCz: achromatic, red-green, blue-yellow
};
struct Lab {
  float l, a, b;
};

// Linear RGB → YyCxCz (Zhang & Wandell's S-CIELAB opponent space, used by FLIP because it is
// linear in XYZ, so filtering in it is filtering the light): the CIELab formulas without the cube
// root.
inline Opponent linearRgbToOpponent(float r, float g, float b) {
  const float x = (kRgbToXyz[0][0] * r + kRgbToXyz[0][1] * g + kRgbToXyz[0][2] * b) * kInvWhiteX;
  const float y = kRgbToXyz[1][0] * r + kRgbToXyz[1][1] * g + kRgbToXyz[1][2] * b;
  const float z = (kRgbToXyz[2][0] * r + kRgbToXyz[2][1] * g + kRgbToXyz[2][2] * b) * kInvWhiteZ;
  return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

// YyCxCz → linear RGB, then clamped to [0, 1]: the filtered colour must be a displayable one
// before the colour distance (FLIP paper, colour pipeline).
inline void opponentToClampedLinearRgb(const Opponent& o, float rgb[3]) {
  const float y = (o.y + 16.0f) * (1.0f / 116.0f);
  const float x = (y + o.cx * (1.0f / 500.0f)) * kWhiteX;
  const float z = (y - o.cz * (1.0f / 200.0f)) * kWhiteZ;
  for (int i = 0; i < 3; ++i) {
    const float v = kXyzToRgb[i][0] * x + kXyzToRgb[i][1] * y + kXyzToRgb[i][2] * z;
    rgb[i] = std::clamp(v, 0.0f, 1.0f);
  }
}

// Cube root of a positive float: an estimate from a third of the exponent bits (Kahan's
// constant) refined by two Halley steps in double. Within 1 ulp of cbrtf over CIELab's range and
// about four times faster; six of them per pixel were a fifth of HDR-FLIP's time.
inline float cubeRoot(float t) {
  double y = std::bit_cast<float>(std::bit_cast<std::uint32_t>(t) / 3 + 0x2A5137A0u);
  const double td = t;
  for (int step = 0; step < 2; ++step) {
    const double y3 = y * y * y;
    y *= (y3 + 2.0 * td) / (2.0 * y3 + td);
  }
  return float(y);
}

// CIELab's f(t): cube root above (6/29)³, its tangent line below (CIE 15).
inline float labCompand(float t) {
  constexpr float kDelta = 6.0f / 29.0f;
  constexpr float kDeltaCube = kDelta * kDelta * kDelta;
  return t > kDeltaCube ? cubeRoot(t) : t * (1.0f / (3.0f * kDelta * kDelta)) + 4.0f / 29.0f;
}

// Linear RGB → CIELab (D65 white), then the Hunt adjustment: chroma scaled by 0.01·L, since
// colours look less colourful as they get darker (FLIP paper, colour pipeline).
inline Lab linearRgbToHuntLab(const float rgb[3]) {
  float xyz[3];
  for (int i = 0; i < 3; ++i)
    xyz[i] = kRgbToXyz[i][0] * rgb[0] + kRgbToXyz[i][1] * rgb[1] + kRgbToXyz[i][2] * rgb[2];
  const float fx = labCompand(xyz[0] * kInvWhiteX);
  const float fy = labCompand(xyz[1]);
  const float fz = labCompand(xyz[2] * kInvWhiteZ);
  const float l = 116.0f * fy - 16.0f;
  const float hunt = 0.01f * l;
  return {l, hunt * 500.0f * (fx - fy), hunt * 200.0f * (fy - fz)};
}

// HyAB (Abasi et al. 2020): city-block distance in lightness plus Euclidean distance in the
// chromatic plane, which FLIP prefers to ΔE for large colour differences.
inline float hyAb(const Lab& p, const Lab& q) {
  const float da = p.a - q.a;
  const float db = p.b - q.b;
  return std::fabs(p.l - q.l) + std::sqrt(da * da + db * db);
}

}  // namespace gib::metrics::flip_detail
