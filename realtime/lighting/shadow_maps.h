// The shadow maps of a batch of light samples (book §4.1), the layers of one array texture so
// that one pass can light a point with every sample of the batch: a cube of 90° faces around a
// point sample (the book's "six spot lights" for omnidirectional lights; faces the sample cannot
// light are cleared, not drawn), or an orthographic map over the scene's bounding sphere for a
// directional sample. Every face of a batch is drawn by one multi-draw (layered rendering), each
// face only the triangle chunks it may see (view_culling.h).
// Hard and PCF maps hold depth and are read with hardware comparison; a variance shadow map holds
// (d, d²), box-filtered by a compute pass over the whole batch.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/gl/stream_buffer.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/lighting/light_samples.h"
#include "realtime/pass_declarations.h"

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace gib::rt {

namespace gl {
class PassProfiler;
}

enum class ShadowFilter { kHard, kPcf, kVariance };

// The passes ShadowMaps::render opens, inside its caller's pass.
inline constexpr std::string_view kShadowMapPass = "shadow map";
inline constexpr std::string_view kShadowMapFilterPass = "shadow map filter";  // variance only

struct ShadowSettings {
  ShadowFilter filter = ShadowFilter::kHard;
  int size = 512;           // texels per side (of each cube face)
  int pcf_radius = 0;       // PCF taps: (2r+1)² bilinear comparisons one texel apart
  float normal_offset = 1;  // receiver offset along its normal, in texels
  int blur_radius = 2;      // variance shadow map: (2r+1)² box, the book's 5×5
  float min_variance = 1e-6f;
  // The shadow pass selects each instance's layer in the vertex shader where the GL can, else in
  // a geometry shader; true takes the geometry shader anyway (tests compare the two).
  bool layer_from_geometry_shader = false;
  // Each face draws only the triangle chunks it may see (view_culling.h); false draws every
  // triangle into every face (tests compare the two).
  bool cull_faces = true;
  // Samples per batch; 0 chooses by memory (shadowBatchCapacity). Tests set 1, the per-sample
  // passes of before batching, to compare.
  int batch_capacity = 0;
};

// Samples per batch for `sample_count` samples with these maps: settings.batch_capacity if set,
// else as many as fit a memory budget for one kind's maps (256 MiB); at most gpu::kMaxLightBatch
// and at least one.
int shadowBatchCapacity(const ShadowSettings& settings, std::size_t sample_count);

// The samples in the batches a caller renders: each batch one kind (lookups are compiled per
// kind), at most `capacity` samples, in the samples' order within a kind (points first).
std::vector<std::span<const LightSample>> lightSampleBatches(std::span<const LightSample> samples,
                                                             int capacity);

class ShadowMaps {
 public:
  // `capacity`: samples per batch at most (1..gpu::kMaxLightBatch).
  ShadowMaps(const ShadowSettings& settings, const GpuScene& scene, int capacity);

  // Declares the passes of render() under `parent`.
  static void declarePasses(PassDeclarations& passes, std::string_view parent);

  int capacity() const { return capacity_; }

  // Renders the maps of `batch` (one kind, 1..capacity() samples; std::invalid_argument else)
  // into the first layers, inside the caller's profiler passes, and keeps the samples for lookups.
  void render(const GpuScene& scene, std::span<const LightSample> batch,
              gl::PassProfiler& profiler);
  // Sets the lookup uniforms of shadow_lookup.glsl that are the same for every batch (planes,
  // size, offsets, filter settings) in `program`; once, when the program is built.
  void setLookupConstants(const gl::Program& program) const;
  // Binds the last batch's maps (kShadowMapUnit) and samples (kLightSamplesBinding) and sets the
  // sample count of `program`, which must be the variant for the batch's kind.
  void bindForLookup(const gl::Program& program) const;
  LightSampleKind batchKind() const { return batch_kind_; }
  // The last batch's maps as lookups read them: depth, or the filtered moments of a variance
  // shadow map (layers 6k..6k+5 the cube of sample k; k for a directional one).
  const gl::Texture& lookupMaps() const;

  // The GLSL defines of this filter, for programs that read the maps.
  std::string defines(LightSampleKind kind) const;

 private:
  // The maps of one kind: depth (and moments) arrays and the layered framebuffer over them.
  struct Layers {
    gl::Texture depth, moments, scratch;  // moments and scratch for variance shadow maps
    std::optional<gl::Framebuffer> framebuffer;
    gl::Program depth_program, blur_program;
  };
  Layers& layers(LightSampleKind kind);
  // Filters the `face_count` faces the last shadow pass drew (its face list bound).
  void blur(LightSampleKind kind, int face_count, gl::PassProfiler& profiler);
  glm::mat4 flatViewProjection(const LightSample& sample) const;

  ShadowSettings settings_;
  int capacity_;
  float near_, far_;  // cube faces
  glm::vec3 centre_;  // bounding sphere of the scene
  float radius_;
  Layers cube_, flat_;  // made on first use: a scene may have one kind only
  // Per batch, a round of their own: the samples (gpu::GpuLightSample, a uniform block at
  // samples_offset_), the layers the shadow pass draws (gpu::ShadowFace) and its multi-draw
  // records, per face the triangle chunks it may see (view_culling.h).
  gl::StreamBuffer stream_;
  std::size_t samples_offset_ = 0;
  int batch_size_ = 0;
  LightSampleKind batch_kind_ = LightSampleKind::kPoint;
};

}  // namespace gib::rt
