// `irradiance_cache_splatting`: Ward's irradiance cache reformulated for the GPU (course notes
// 001). Records are placed by the notes' traversal on the CPU over the read-back G-buffer
// (realtime/irradiance_cache/record_placement.h), computed by rasterizing the directly lit scene
// around them (plane sampling with border compensation, or a hemicube; record_sampler.h), and
// interpolated by splatting: each record's zone of influence drawn as a screen-aligned quad whose
// fragments evaluate Ward's full weight and the gradient-extrapolated irradiance, summed by
// additive blending and divided by the summed weight in one full-screen pass. Records are kept
// across frames (the scene is static). Direct light and emission as `direct` renders them. See
// README.md beside this file.
#pragma once

#include "realtime/atlas/atlas_mesh.h"
#include "realtime/atlas/direct_radiance_atlas.h"
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/irradiance_cache/record_placement.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/technique.h"
#include "realtime/techniques/irradiance_cache_splatting/record_sampler.h"

#include <optional>
#include <vector>

namespace gib::rt {

class IrradianceCacheSplattingTechnique final : public Technique {
 public:
  explicit IrradianceCacheSplattingTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override { return {0, 2}; }
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;

  // The records of the last build, R clamped (tests compare them with the CPU cache's lookups).
  const std::vector<gpu::IrradianceRecord>& records() const { return records_; }
  const SurfaceImage& surfaces() const { return surfaces_; }
  // Splats `records` instead from the next frame on (tests splat fields they know).
  void replaceRecords(std::vector<gpu::IrradianceRecord> records);

 private:
  void buildRecords(gl::PassProfiler& profiler);
  void splat(Frame& frame);

  RecordPlacementSettings placement_;
  RecordSamplingSettings sampling_;
  int atlas_resolution_;
  int light_samples_;
  bool reuse_records_;
  SurfaceLighting surface_lighting_;
  const GpuScene* scene_ = nullptr;
  atlas::DirectRadianceAtlas atlas_;
  std::optional<atlas::AtlasMesh> mesh_;
  std::optional<RecordSampler> sampler_;
  SurfaceImage surfaces_;
  std::vector<gpu::IrradianceRecord> records_;
  gl::Buffer round_buffer_, records_buffer_;
  gl::Texture sums_;
  gl::Framebuffer sums_target_;
  gl::Program splat_program_;
  gl::VertexArray empty_vertex_array_;
  gl::FullScreenPass normalize_;
  int rounds_ = 0;
  double detection_ms_ = 0, sampling_ms_ = 0, records_ms_ = 0;
};

TechniqueInfo irradianceCacheSplattingTechniqueInfo();

}  // namespace gib::rt
