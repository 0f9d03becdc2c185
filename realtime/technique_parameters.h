// Parameters that several techniques take, declared once each so that a name means one thing
// with one range and one default wherever it appears (`atlas`, `seed`, `light_samples`).
#pragma once

#include "common/parameters.h"

#include <string>

namespace gib::rt {

// A square texture atlas's texels per side, a power of two from 64 to 1024. The default is the
// resolution of the document the technique reproduces (the book's 128 for stochastic radiosity,
// 256 for the light path map's panes), so it is the caller's.
ParameterSpec atlasParameter(int default_resolution, std::string doc);

// The seed of a technique's random choices, 0 by default: a run is the same every time, and
// another seed gives an independent run.
ParameterSpec seedParameter(std::string doc);

// Points over the area lights and directions over the sky, each lit with its own shadow test:
// the light samples of every technique that lights surfaces directly (16 by default).
ParameterSpec lightSamplesParameter();

}  // namespace gib::rt
