// `irradiance_cache`: Ward's irradiance cache on the CPU, the baseline the GPU splatting is
// measured against (course notes 001, "Irradiance caching: ray tracing and octrees"). Primary
// rays, direct light from the same light samples as the GPU techniques with shadow rays, records
// placed by the notes' traversal (realtime/irradiance_cache/record_placement.h) and computed by
// Ward & Heckbert's stratified hemisphere sampling with Embree rays (each hit lit directly: one
// indirect bounce), stored in an octree and interpolated by lookups. Every stage runs on all
// cores and is deterministic. The image is uploaded to the frame's target, and the profiler's CPU
// clock times it. See README.md beside this file.
#pragma once

#include "realtime/irradiance_cache/record_octree.h"
#include "realtime/irradiance_cache/record_placement.h"
#include "realtime/lighting/light_samples.h"
#include "realtime/technique.h"

#include <memory>
#include <optional>
#include <vector>

namespace gib::rt {

class IrradianceCacheTechnique final : public Technique {
 public:
  explicit IrradianceCacheTechnique(const ParameterValues& parameters);

  void provide(const TechniqueServices& services) override { services_ = services; }
  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  bool timedOnCpu() const override { return true; }
  scene::PathClass pathClass() const override { return {0, 2}; }
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;

  const std::vector<gpu::IrradianceRecord>& records() const { return records_; }
  const SurfaceImage& surfaces() const { return surfaces_; }
  // The interpolated irradiance per pixel (GL row order), from the last frame.
  const std::vector<glm::vec3>& irradiance() const { return irradiance_; }

 private:
  // What each pixel's primary ray met: the surfaces, their material, and the direct light.
  void traceSurfaces();
  void buildRecords();
  gpu::IrradianceRecord computeRecord(const glm::vec3& p, const glm::vec3& n,
                                      std::uint64_t stream) const;
  // What light sample `s` delivers at p (unit normal n) as E·cos θ if nothing is in the way, and
  // the shadow ray that decides it; zero, and no ray, where it cannot light p.
  glm::vec3 unshadowedIrradiance(std::size_t s, const glm::vec3& p, const glm::vec3& n,
                                 scene::Ray& shadow) const;
  void interpolate();
  struct SurfaceHit {
    glm::vec3 normal;
    const scene::Material* material;
  };
  SurfaceHit surfaceHit(const scene::RayHit& hit) const;
  void tabulateTriangles();

  RecordPlacementSettings placement_;
  int record_rays_;
  int light_samples_;
  int threads_;
  bool reuse_records_;
  std::uint64_t seed_;
  TechniqueServices services_;
  const GpuScene* scene_ = nullptr;
  std::unique_ptr<scene::RayCaster> caster_;
  std::vector<std::uint32_t> mesh_offsets_;  // the first triangle of each mesh in triangles_
  std::vector<glm::vec4> triangles_;         // unit geometric normal, w the material index
  std::vector<gpu::GpuLightSample> samples_;
  std::vector<std::uint8_t> directional_;
  SurfaceImage surfaces_;
  std::vector<glm::vec3> albedo_, own_light_, irradiance_;
  std::vector<gpu::IrradianceRecord> records_;
  std::optional<RecordOctree> octree_;  // records_, for the lookups
  int rounds_ = 0;
  double caster_ms_ = 0, surfaces_ms_ = 0, records_ms_ = 0, interpolation_ms_ = 0;
  double rays_ = 0;  // record rays and their shadow rays in the last build
};

TechniqueInfo irradianceCacheTechniqueInfo();

}  // namespace gib::rt
