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
#include <vector>

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
  // Iteration counts (ascending, each ≤ iterations) after which an iterative technique's image is
  // also captured, unprofiled: an error-against-iterations series from one run.
  std::vector<int> capture_after;
  gl::ContextOptions context;
  TechniqueServices services;  // lent to the technique before prepare()
  // Also rasterise the camera's G-buffer after the frames (unprofiled) and return what each pixel
  // centre sees, for the harness to compare with the reference's primary rays.
  bool capture_primary_surfaces = false;
};

// What the rasteriser sees through each pixel centre (RGBA, pixel (0,0) top left): world position
// with the distance along the ray in w (negative where no surface is seen), and the geometric
// normal with the material index in w. The layout ref::comparePrimarySurfaces reads.
struct PrimarySurfaces {
  image::Image position;
  image::Image normal;
};

// The image after a number of iterations, and the iteration time spent to get there.
struct IterationCapture {
  int iterations = 0;
  double iterate_ms = 0;  // the step() calls up to here, not the captures' frames
  image::Image image;
};

struct TechniqueRunResult {
  image::Image image;  // RGB, pixel (0,0) top left
  ProfileRecord profile;
  // Each step() as one profiled unit named "iteration" (empty unless the technique iterates).
  ProfileRecord iteration_profile;
  std::vector<IterationCapture> captures;  // one per TechniqueRunSettings::capture_after
  std::vector<AuxiliaryImage> auxiliary;   // Technique::auxiliaryImages after the last frame
  std::vector<TechniqueStatistic> statistics;
  std::optional<image::Image> region;  // Technique::measuredRegion after the last frame
  double upload_ms = 0;                // scene upload, wall clock around glFinish
  double prepare_ms = 0;               // Technique::prepare
  double iterate_ms = 0;               // all step() calls
  int iterations = 0;
  std::optional<PrimarySurfaces> primary;  // when capture_primary_surfaces
  scene::PathClass path_class;
  // Technique::imageObscurance: set when `image` is an obscurance W, not radiance.
  std::optional<scene::ObscuranceDefinition> obscurance;
  gl::GlIdentity gl;
};

// Throws gib::InputError for impossible settings (no frames, a size out of range);
// gib::EnvironmentError, one line beginning "technique '<name>': ", when the GL implementation
// fails it (no context, a shader it rejects, a texture it cannot allocate); and
// std::runtime_error listing GL errors when debug output is on and GL reported any.
TechniqueRunResult runTechnique(const scene::Scene& scene, const TechniqueInfo& info,
                                const ParameterValues& parameters,
                                const TechniqueRunSettings& settings);

// The metadata of a technique's output beyond scene::outputMetadata: GL identity, frames, clock,
// preparation times.
std::map<std::string, std::string> techniqueRunMetadata(const TechniqueRunResult& result,
                                                        const TechniqueRunSettings& settings);

}  // namespace gib::rt
