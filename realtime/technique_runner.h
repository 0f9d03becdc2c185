// Runs a technique the way the harness measures it: a fresh context, the scene uploaded once,
// prepare(), the iterations of an iterative technique, warm-up frames, then measured frames under
// the pass profiler; the last frame read back as linear float RGB.
#pragma once

#include "image/image.h"
#include "realtime/gl/context.h"
#include "realtime/gl/pass_record.h"
#include "realtime/technique.h"
#include "scene/scene.h"

#include <functional>
#include <map>
#include <optional>
#include <string>

namespace gib::rt {

struct TechniqueRunSettings {
  int width = 512;
  int height = 512;
  int warmup_frames = 2;
  int frames = 8;  // measured
  // CPU time around glFinish per pass; default: on for software renderers (llvmpipe's timer
  // queries miss vertex work), off on a GPU.
  std::optional<bool> precise;
  int iterations = 1;  // step() calls before the frames, for iterative techniques
  gl::ContextOptions context;
};

struct TechniqueRunResult {
  image::Image image;  // RGB, pixel (0,0) top left
  ProfileRecord profile;
  double upload_ms = 0;   // scene upload, wall clock around glFinish
  double prepare_ms = 0;  // Technique::prepare
  double iterate_ms = 0;  // all step() calls
  int iterations = 0;
  scene::PathClass path_class;
  gl::GlIdentity gl;
};

// Throws gib::InputError for impossible settings (no frames, a size out of range), and
// std::runtime_error listing GL errors when debug output is on and GL reported any.
TechniqueRunResult runTechnique(const scene::Scene& scene, const TechniqueInfo& info,
                                const ParameterValues& parameters,
                                const TechniqueRunSettings& settings);

// The metadata of a technique's output beyond scene::outputMetadata: GL identity, frames, clock,
// preparation times.
std::map<std::string, std::string> techniqueRunMetadata(const TechniqueRunResult& result,
                                                        const TechniqueRunSettings& settings);

}  // namespace gib::rt
