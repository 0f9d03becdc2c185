// The Cornell box spectra, copied from the Cornell Program of Computer Graphics' "Cornell Box
// Data" page (https://www.graphics.cornell.edu/online/box/data.html, section "Surface
// reflectances" and "Light source"). Cross-checked value by value against three independent
// transcriptions (Iris' test_util/cornell_box.c, raysect's Cornell box demo, Mitsuba-format
// spectra in a spectral ray tracer): all 3 × 76 reflectances agree.
#include "scene/cornell_spectra.h"

#include <array>

namespace gib::scene {

namespace {

constexpr float kReflectanceFirstNm = 400.0f;
constexpr float kReflectanceStepNm = 4.0f;
constexpr std::size_t kReflectanceSamples = 76;  // 400, 404, ..., 700 nm

using Reflectances = std::array<float, kReflectanceSamples>;

// Each row holds ten samples and is labelled with the wavelength of its first one.
constexpr Reflectances kWhite = {
    0.343, 0.445, 0.551, 0.624, 0.665, 0.687, 0.708, 0.723, 0.715, 0.710,  // 400 nm
    0.745, 0.758, 0.739, 0.767, 0.777, 0.765, 0.751, 0.745, 0.748, 0.729,  // 440 nm
    0.745, 0.757, 0.753, 0.750, 0.746, 0.747, 0.735, 0.732, 0.739, 0.734,  // 480 nm
    0.725, 0.721, 0.733, 0.725, 0.732, 0.743, 0.744, 0.748, 0.728, 0.716,  // 520 nm
    0.733, 0.726, 0.713, 0.740, 0.754, 0.764, 0.752, 0.736, 0.734, 0.741,  // 560 nm
    0.740, 0.732, 0.745, 0.755, 0.751, 0.744, 0.731, 0.733, 0.744, 0.731,  // 600 nm
    0.712, 0.708, 0.729, 0.730, 0.727, 0.707, 0.703, 0.729, 0.750, 0.760,  // 640 nm
    0.751, 0.739, 0.724, 0.730, 0.740, 0.737,                              // 680 nm
};

constexpr Reflectances kGreen = {
    0.092, 0.096, 0.098, 0.097, 0.098, 0.095, 0.095, 0.097, 0.095, 0.094,  // 400 nm
    0.097, 0.098, 0.096, 0.101, 0.103, 0.104, 0.107, 0.109, 0.112, 0.115,  // 440 nm
    0.125, 0.140, 0.160, 0.187, 0.229, 0.285, 0.343, 0.390, 0.435, 0.464,  // 480 nm
    0.472, 0.476, 0.481, 0.462, 0.447, 0.441, 0.426, 0.406, 0.373, 0.347,  // 520 nm
    0.337, 0.314, 0.285, 0.277, 0.266, 0.250, 0.230, 0.207, 0.186, 0.171,  // 560 nm
    0.160, 0.148, 0.141, 0.136, 0.130, 0.126, 0.123, 0.121, 0.122, 0.119,  // 600 nm
    0.114, 0.115, 0.117, 0.117, 0.118, 0.120, 0.122, 0.128, 0.132, 0.139,  // 640 nm
    0.144, 0.146, 0.150, 0.152, 0.157, 0.159,                              // 680 nm
};

constexpr Reflectances kRed = {
    0.040, 0.046, 0.048, 0.053, 0.049, 0.050, 0.053, 0.055, 0.057, 0.056,  // 400 nm
    0.059, 0.057, 0.061, 0.061, 0.060, 0.062, 0.062, 0.062, 0.061, 0.062,  // 440 nm
    0.060, 0.059, 0.057, 0.058, 0.058, 0.058, 0.056, 0.055, 0.056, 0.059,  // 480 nm
    0.057, 0.055, 0.059, 0.059, 0.058, 0.059, 0.061, 0.061, 0.063, 0.063,  // 520 nm
    0.067, 0.068, 0.072, 0.080, 0.090, 0.099, 0.124, 0.154, 0.192, 0.255,  // 560 nm
    0.287, 0.349, 0.402, 0.443, 0.487, 0.513, 0.558, 0.584, 0.620, 0.606,  // 600 nm
    0.609, 0.651, 0.612, 0.610, 0.650, 0.638, 0.627, 0.620, 0.630, 0.628,  // 640 nm
    0.642, 0.639, 0.657, 0.639, 0.635, 0.642,                              // 680 nm
};

SampledSpectrum makeReflectance(const Reflectances& values) {
  SampledSpectrum spectrum;
  for (std::size_t i = 0; i < kReflectanceSamples; ++i) {
    spectrum.wavelengths_nm.push_back(kReflectanceFirstNm +
                                      kReflectanceStepNm * static_cast<float>(i));
    spectrum.values.push_back(values[i]);
  }
  return spectrum;
}

}  // namespace

SampledSpectrum cornellWhite() {
  return makeReflectance(kWhite);
}
SampledSpectrum cornellGreen() {
  return makeReflectance(kGreen);
}
SampledSpectrum cornellRed() {
  return makeReflectance(kRed);
}

SampledSpectrum cornellLight() {
  // The page gives the light's spectrum at four wavelengths only; it is linear in between and,
  // like every SampledSpectrum, zero outside 400–700 nm.
  return SampledSpectrum{{400.0f, 500.0f, 600.0f, 700.0f}, {0.0f, 8.0f, 15.6f, 18.4f}};
}

}  // namespace gib::scene
