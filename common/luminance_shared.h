// Luminance of linear Rec.709 RGB, Y = 0.2126 R + 0.7152 G + 0.0722 B (docs/architecture.md,
// "Conventions"): the one definition of the weights, read by C++ (gib::kLuminanceRed, …) and,
// through the realtime layer's shader embedding, by GLSL (which also gets luminance()). Doubles, so
// that C++ metrics get the weights exactly; float users round them as they always did.
#pragma once

#ifdef __cplusplus
namespace gib {
#endif

const double kLuminanceRed = 0.2126;
const double kLuminanceGreen = 0.7152;
const double kLuminanceBlue = 0.0722;

#ifdef __cplusplus
}  // namespace gib
#else
float luminance(vec3 c) {
  return dot(c, vec3(float(kLuminanceRed), float(kLuminanceGreen), float(kLuminanceBlue)));
}
#endif
