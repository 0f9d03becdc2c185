// Irradiance records computed by rasterization (course notes 001, "From ray tracing to
// rasterization"): around each record of a round, the directly lit scene (a radiance atlas) drawn
// through one wide camera along the normal (`plane`, with the notes' border compensation) or the
// five faces of a hemicube, a layer per face and one instanced draw per batch; a compute pass
// sums each record's views into its irradiance, harmonic mean distance and gradients
// (record_sum.comp.glsl), written into the records' storage buffer.
#pragma once

#include "realtime/atlas/atlas_mesh.h"
#include "realtime/gl/objects.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string_view>

namespace gib::rt {

// The passes RecordSampler::sample opens, inside its caller's.
inline constexpr std::string_view kRecordViewsPass = "record views";
inline constexpr std::string_view kRecordSumsPass = "record sums";

struct RecordSamplingSettings {
  int sampling = 0;             // gpu::kRecordSampling*
  int size = 64;                // pixels per side of each face
  float plane_fov_degrees = 0;  // plane sampling's aperture
  bool extend_border = true;    // plane sampling: the notes' border compensation
};

class RecordSampler {
 public:
  // `extent`: the scene's, for the views' near and far planes.
  RecordSampler(const RecordSamplingSettings& settings, float extent);

  // Fills irradiance, R (unclamped) and gradients of records [first, first + count) of
  // `records` (an IrradianceRecord storage buffer whose positions and normals are set) from views
  // of `mesh` textured with `radiance_atlas`; where nothing is drawn the views see `background`
  // at no finite distance.
  void sample(const GpuScene& scene, const atlas::AtlasMesh& mesh,
              const gl::Texture& radiance_atlas, const gl::Buffer& records, int first, int count,
              gl::PassProfiler& profiler, const glm::vec3& background = glm::vec3(0.0f));

  int faces() const { return faces_; }
  int recordsPerBatch() const { return batch_; }
  // Sample pixels of one record above its horizon (the hemicube's side faces count half).
  int pixelsPerRecord() const;

 private:
  RecordSamplingSettings settings_;
  int faces_;
  float half_width_;
  int batch_;
  std::optional<gl::LayeredTarget> views_;  // RGBA32F: radiance, distance
  gl::Program view_program_, sum_program_;
};

}  // namespace gib::rt
