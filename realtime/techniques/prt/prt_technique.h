// `prt`: diffuse pre-computed radiance transfer (book §8.3, Figs. 8.4 and 8.5; Sloan, Kautz &
// Snyder 2002; CPCA after Sloan et al. 2003). Prepared once: the scene re-tessellated into
// regular vertices (prt_mesh.h), each vertex's RGB transfer vector over `sh_bands` bands of
// spherical harmonics by CPU ray casting with interreflections up to `bounces` (prt_transfer.h),
// the vectors compressed by CPCA, and the environment projected onto the same basis. Per frame:
// the lighting rotated about +y, its dot products with every cluster's mean and basis vectors on
// the CPU (eq. 8.5), and one draw whose vertex shader sums them with the vertex's weights. The
// frame starts with `direct`'s SurfaceLighting (the environment seen directly, emitters, and the
// scene's spot and area lights) and the PRT draw adds the environment's light.
// Path class LD{0,bounces}E. See README.md beside this file.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/gl/program.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/prt/cpca.h"
#include "realtime/technique.h"
#include "realtime/techniques/prt/prt_mesh.h"

#include <glm/vec3.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace gib::rt {

inline constexpr std::string_view kLightProjectionPass = "light projection";
inline constexpr std::string_view kPrtVerticesPass = "prt vertices";

struct PrtSettings {
  int bands = 6;
  int rays = 256;
  int bounces = 1;
  bool compress = true;  // false: every vertex its own vector (compression=none)
  int clusters = 16;
  int pca_vectors = 8;
  float max_edge = 0.5f;
  float light_rotation_deg = 0.0f;  // per frame, about +y
  std::uint32_t seed = 0;
};

// The preprocessing's times and counts, and the error terms (README.md, "Errors").
struct PrtPreprocessing {
  double ray_caster_ms = 0, transfer_ms = 0, compression_ms = 0, projection_ms = 0;
  std::size_t rays_cast = 0, rays_hit = 0;
  double sh_truncation_error = 0, cpca_error = 0, cpca_radiance_error = 0, monte_carlo_error = 0;
};

class PrtTechnique final : public Technique {
 public:
  explicit PrtTechnique(const ParameterValues& parameters);

  void provide(const TechniqueServices& services) override { services_ = services; }
  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override;
  std::vector<TechniqueStatistic> statistics() const override;
  std::vector<TechniqueStatistic> finalStatistics() const override;

  // The compressed vectors (for tests): one cluster per vertex and no basis with compress false.
  const prt::CpcaResult& compressed() const { return compressed_; }
  const prt::PrtMesh& mesh() const { return mesh_; }

 private:
  PrtSettings settings_;
  TechniqueServices services_;
  SurfaceLighting surface_lighting_;
  const GpuScene* scene_ = nullptr;
  prt::PrtMesh mesh_;
  prt::CpcaResult compressed_;
  std::vector<glm::vec3> lighting_;  // the environment's bands² RGB coefficients, world frame
  PrtPreprocessing preprocessing_;

  // The frame's lighting and its dot products (prt_projection.h).
  std::vector<glm::vec3> rotated_;
  std::vector<glm::vec4> projections_;
  double projection_cpu_ms_ = 0;  // summed over frames
  int frames_ = 0;

  gl::Program program_;
  std::optional<gl::VertexArray> empty_vertex_array_;
  gl::Buffer positions_, corners_, clusters_, weights_, projection_buffer_;
};

TechniqueInfo prtTechniqueInfo();

}  // namespace gib::rt
