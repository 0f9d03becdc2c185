// Suite files: TOML that lists the cases of a run (README, "Suites", has an annotated example).
//
//   name = "smoke"                        # required: letters, digits, '.', '_', '-'
//   description = "…"                     # optional
//
//   [defaults]                            # optional: what every case inherits
//   width = 128                           # optional, both or neither; default the scene's size
//   height = 128
//   metrics = ["relmse", "flip"]          # metric names (`gibench list metrics`) or "all";
//                                         # a string may hold a comma-separated list; default "all"
//   frames = 8                            # measured frames per technique job, >= 1; default 8
//   warmup = 2                            # frames rendered before them, >= 0; default 2
//   repeats = 3                           # whole runs of a technique job (fresh GL context each,
//                                         # interleaved with other jobs'), 1 to 100; default 1
//
//   [defaults.reference]                  # the reference each case is measured against
//   spp = 1024                            # >= 1; default 1024
//   seed = 0                              # >= 0; default 0
//   min_bounces = 0                       # optional path class; absent: the technique's own
//   max_bounces = 1                       #   (Technique::pathClass()); "unlimited" for all paths
//   paths = "LS+DE"                       # or a path expression instead of the bounces
//
//   [[case]]                              # one or more
//   name = "chamber-direct"               # optional, unique; default "<scene>-<technique>"
//   scene = "chamber"                     # a built-in scene or a .toml scene file (relative to
//                                         # this file)
//   scene_set = { detail = [1, 2] }       # optional built-in scene parameters
//   technique = "direct"                  # a catalogue name, or "reference" for the reference
//                                         # alone
//   set = { shadow = ["hard", "pcf"], light_samples = 16 }   # optional technique parameters
//   checkpoints = [1, 4, 16]              # optional series of positive, increasing integers
//   width = 256                           # any [defaults] key overrides the default for this
//   [case.reference]                      #   case; [case.reference] overrides key by key
//   spp = 4096
//
// In `set` and `scene_set` a scalar is a fixed value and an array a sweep: the case expands into
// the cartesian product of its sweeps. Values are strings or numbers (canonicalised by the
// parameter table, so 4 and 4.0 are the same integer); a vector parameter is "x,y,z" or
// [x, y, z], and a sweep of vectors an array of those. Every value is checked against the
// technique's or scene's parameter table when the file is read; a scene file is only checked to
// exist here (it is loaded, with its own errors, when the suite runs). A reference case takes no
// `set`, frames, warmup and repeats do not apply to it, and its checkpoints (spp counts) are at
// most its reference spp. A case expanding into more than 10 000 jobs is refused as a likely
// mistake. [tolerances], [[paper]] and [[chart]] are described in suites/suite_annotations.h,
// [[figure]] in suites/suite_figures.h.
#pragma once

#include "suites/suite.h"

#include <filesystem>

namespace gib::suites {

// Reads and validates a suite file. Every problem throws gib::InputError with one line
// "<file>:<line>:<column>: <problem>; <fix>" (common/toml_reader.h), <file> as given; a missing
// file reads "<file>: suite file not found; check the path".
Suite loadSuiteFile(const std::filesystem::path& path);

}  // namespace gib::suites
