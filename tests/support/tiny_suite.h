// The suite the command-line tests run: small enough for seconds per run.
#pragma once

namespace gib::test {

// Small enough for seconds per run: a 32x32 Cornell box, a 1024-spp reference with a convergence
// series, and the direct technique with two shadow filters, with a paper value and a figure.
inline constexpr const char* kTinySuite = R"(name = "tiny"
description = "a tiny suite for the tests"

[defaults]
width = 32
height = 32
metrics = ["mse", "relmse", "flip"]
frames = 2
warmup = 0

[defaults.reference]
spp = 1024

[tolerances]
relmse = { relative = 0.1 }

[[case]]
scene = "cornell"
technique = "reference"
checkpoints = [4, 16, 64]

[[case]]
scene = "cornell"
technique = "direct"
set = { shadow = ["hard", "pcf"], light_samples = 2 }

[[paper]]
job = "cornell-direct/shadow=pcf"
quantity = "frame"
value = 3.5
unit = "ms"
source = "a made-up paper"

[[figure]]
name = "shadows"
title = "Hard and PCF shadows beside the reference"

[[figure.panel]]
job = "cornell-direct/shadow=hard"
image = "image"
caption = "hard"

[[figure.panel]]
job = "cornell-direct/shadow=pcf"
image = "image"
caption = "PCF"
metric = "frame"

[[figure.panel]]
job = "cornell-direct/shadow=pcf"
image = "reference"
caption = "reference"
metric = "none"
)";

}  // namespace gib::test
