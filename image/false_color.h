// False-colour rendering of scalar maps (error maps, p-values) for people to look at, with a
// colour bar that carries the scale.
#pragma once

#include "image/image.h"

namespace gib::image {

// Maps channel 0 of `scalar` through the magma colour map over [low, high] (values outside are
// clamped, non-finite values take the top colour) and appends a colour bar below it labelled
// with `low` and `high`. The result is linear Rec.709, so
// writePng with the Standard view reproduces the colour map's sRGB values.
Image falseColorWithBar(const Image& scalar, float low, float high);

// The magma colour map at t in [0, 1], as display-encoded sRGB in [0, 1].
void magmaSrgb(float t, float rgb[3]);

}  // namespace gib::image
