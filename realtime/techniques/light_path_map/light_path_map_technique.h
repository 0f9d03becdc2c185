// `light_path_map`: indirect illumination of static geometry under moving lights by light path
// maps (Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, §8.4).
//
// Preprocessing (prepare): entry points sampled uniformly over the surface area, random walks from
// them traced on the CPU with the harness's ray caster (Embree), their visited points connected
// as virtual spot lights to every exit point (atlas texel, realtime/atlas/) they see through a
// shadow map on the GPU, each cluster's pane (the exit radiance caused by unit irradiance at its
// entry points) summed into one layer of a pane array. Rendering (render): the direct light by the
// shared shadow-mapped lighting; the irradiance of every entry point from the same shadow maps;
// per cluster the mean of its members'; the `panes_used` highest-weighted clusters' panes weighted
// and summed per texel; the camera view of that atlas added. See README.md beside this file.
#pragma once

#include "realtime/atlas/atlas_layout.h"
#include "realtime/atlas/atlas_mesh.h"
#include "realtime/atlas/atlas_textures.h"
#include "realtime/gbuffer/gbuffer.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/gl/stream_buffer.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/render_target.h"
#include "realtime/technique.h"
#include "realtime/techniques/light_path_map/entry_points.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace gib::rt {

// Passes of a frame besides the g-buffer and the direct lighting's.
inline constexpr std::string_view kEntryIrradiancePass = "entry irradiance";  // inside "lights"
inline constexpr std::string_view kPaneSelectionPass = "pane selection";
inline constexpr std::string_view kIndirectAtlasPass = "indirect atlas";
inline constexpr std::string_view kIndirectViewPass = "indirect view";
inline constexpr std::string_view kCompositePass = "composite";

struct LightPathMapSettings {
  int entry_points = 4096;
  int paths_per_entry = 2;
  int clusters = 256;
  bool kmeans = false;  // clustering=kmeans: Lloyd's iterations from the kd-tree's clusters
  int panes_used = 32;
  int atlas_resolution = 256;
  int vpl_shadow_map_size = 256;
  bool moving_light = false;   // motion=light
  bool indirect_only = false;  // output=indirect: the light path map's own image
  std::uint32_t seed = 0;
  int max_walk_vertices = 0;  // > 0: walks end there (1: first indirect bounce only; for tests)
  ShadowSettings shadow;      // the direct light's and the entry points' visibility
  int light_samples = 16;
};

// What prepare() measured, for the book's breakdown (0.12 s + 0.17 s + 8.21 s).
struct LightPathMapPreprocessing {
  double ray_caster_ms = 0;     // building the ray caster's BVH
  double light_tracing_ms = 0;  // entry points, clustering and the random walks on the CPU
  double lpm_ms = 0;            // the panes on the GPU (shadow maps and atlas passes), finished
  std::int64_t path_vertices = 0;
  std::size_t virtual_lights = 0;  // shadow maps drawn: entry points once, not once per path
  std::int64_t pane_bytes = 0;     // the pane array as GL allocated it
};

class LightPathMapTechnique final : public Technique {
 public:
  // Throws gib::InputError for counts that do not fit each other (more clusters than entry
  // points, more panes used than clusters).
  explicit LightPathMapTechnique(const ParameterValues& parameters);
  explicit LightPathMapTechnique(const LightPathMapSettings& settings);

  void provide(const TechniqueServices& services) override { services_ = services; }
  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override;
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;

  // For tests: a fixed offset of every point light sample when motion is off (a light moved
  // without preprocessing again), the clusters and their current weights.
  void setLightOffset(const glm::vec3& offset) { fixed_light_offset_ = offset; }
  const std::vector<lpm::EntryPoint>& entryPoints() const { return entries_; }
  const std::vector<int>& clusterOfEntry() const { return cluster_of_entry_; }
  const LightPathMapPreprocessing& preprocessing() const { return preprocessing_; }
  // The entry points' irradiance of the last frame (RGB per entry point) and the clusters'
  // weights made from it (the mean over members, before the 1/N of the combination).
  const std::vector<glm::vec3>& entryIrradiance() const { return entry_irradiance_; }
  const std::vector<glm::vec3>& clusterWeights() const { return cluster_weights_; }
  // Cluster c's pane (exit radiance per atlas texel, row 0 at the bottom) read back.
  std::vector<glm::vec3> pane(int cluster) const;
  const atlas::AtlasTexels& atlasTexels() const { return texels_; }

 private:
  void buildPanes(const lpm::LightWalks& walks);
  void uploadEntryPoints();
  void selectPanes();
  void renderIndirect(gl::PassProfiler& profiler);

  LightPathMapSettings settings_;
  TechniqueServices services_;
  const GpuScene* scene_ = nullptr;
  int width_ = 0, height_ = 0;
  glm::vec3 fixed_light_offset_{0.0f};
  std::vector<atlas::AtlasTriangle> triangles_;
  atlas::AtlasTexels texels_;
  float texel_side_ = 0;  // world length of an atlas texel's side
  std::optional<atlas::AtlasTextures> atlas_;
  std::optional<atlas::AtlasMesh> mesh_;
  std::vector<lpm::EntryPoint> entries_;
  std::vector<int> cluster_of_entry_;
  std::vector<int> cluster_size_;
  LightPathMapPreprocessing preprocessing_;
  std::optional<SurfaceLighting> surface_lighting_;
  std::optional<RenderTarget> indirect_view_;
  int entry_side_ = 0;
  gl::Texture entry_position_, entry_normal_, entry_irradiance_texture_;
  gl::Framebuffer entry_framebuffer_;
  gl::FullScreenPass entry_point_pass_, entry_directional_pass_;
  gl::Texture panes_, indirect_;
  gl::Framebuffer indirect_framebuffer_;
  gl::StreamBuffer selected_panes_;  // the frame's gpu::SelectedPane records
  std::size_t selected_offset_ = 0, selected_bytes_ = 0;
  int selected_count_ = 0;
  std::vector<glm::vec3> entry_irradiance_, cluster_weights_;
  gl::FullScreenPass combine_pass_, composite_pass_;
  gl::Program view_program_, entry_dots_program_;
  // Attribute-less: the dots read the entry textures. Made in prepare, as every GL object is
  // (TechniqueInfo::create does no GL work).
  std::optional<gl::VertexArray> dots_vertex_array_;
};

TechniqueInfo lightPathMapTechniqueInfo();

}  // namespace gib::rt
