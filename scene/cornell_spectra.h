// The measured spectra of the Cornell box, as published by the Cornell Program of Computer
// Graphics, "Cornell Box Data" (https://www.graphics.cornell.edu/online/box/data.html).
// spectrum.h turns them into the Rec.709 values of the built-in `cornell` scene.
#pragma once

#include "scene/spectrum.h"

namespace gib::scene {

// Lambertian reflectances in [0, 1], 400–700 nm every 4 nm (76 samples).
SampledSpectrum cornellWhite();  // floor, ceiling, back wall and both blocks
SampledSpectrum cornellGreen();  // right wall (seen from the camera)
SampledSpectrum cornellRed();    // left wall

// The light's emission, relative spectral radiance at 400, 500, 600 and 700 nm.
SampledSpectrum cornellLight();

}  // namespace gib::scene
