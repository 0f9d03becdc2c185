// `obscurances`: fake global illumination by scalar or spectral obscurances (book Ch. 10).
// Indirect light is approximated as Lᵃ·a(x)·W(x) (eq. 10.1), W the obscurance of eq. 10.2
// (scalar) or 10.4 (spectral) and Lᵃ the ambient light of eq. 10.3 or 10.5 from the scene's
// average albedo and emission (scene/obscurance.h); the direct light is the shared shadow-mapped
// surface lighting.
//
// The obscurances map lives on the atlas and is built once, in prepare(), on the GPU from global
// ray bundles by depth peeling (§10.3–10.4; realtime/depth_peeling/): for each of N directions,
// an orthographic view of the scene peeled into layers, whose consecutive layers along a pixel's
// ray are consecutive surfaces. Pairing: the surface at layer k is a patch crossed by the ray;
// its normal faces one way along the ray (towards the projection plane if it is front-facing,
// away from it if back-facing), and the next layer that way is its occluder, at distance
// d = |depth difference|, or there is none (d = ∞). Every (pixel, layer) adds its sample of
// eq. 10.6 to its patch's texel (one point each, additive blending).
//
// Normalisation (derivation in README.md): a bundle of rays s apart, its grid shifted uniformly,
// crosses a patch of area A with normal n on average A·|n·ω|/s² times; over directions ω uniform
// on the sphere E|n·ω| = 1/2 and the crossing rays' directions, turned into n's hemisphere, are
// cosine-distributed. So E[Σ samples] = N·A/(2s²)·W̄ for the patch's mean obscurance W̄, and
// W = 2s²/(N·A)·Σ samples is unbiased (tested against the reference's Embree estimate).
//
// Frame passes: the shared surface lighting, then ambient (the camera view of the ambient term,
// bilinear from the atlas) and composite (added into the frame). See README.md beside this file.
#pragma once

#include "realtime/atlas/atlas_layout.h"
#include "realtime/atlas/atlas_mesh.h"
#include "realtime/atlas/atlas_textures.h"
#include "realtime/depth_peeling/depth_peeler.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/lighting/surface_lighting.h"
#include "realtime/render_target.h"
#include "realtime/technique.h"
#include "scene/obscurance.h"

#include <cstdint>
#include <optional>
#include <string_view>

namespace gib::rt {

inline constexpr std::string_view kAmbientPass = "ambient";                // of a frame
inline constexpr std::string_view kObscuranceCompositePass = "composite";  // of a frame

enum class ObscuranceOutput {
  kFinal,       // direct + Lᵃ·a·W: the technique's image
  kObscurance,  // W itself: what the obscurance reference measures
};

struct ObscurancesSettings {
  scene::ObscuranceDefinition definition;
  int directions = 64;
  int peel_resolution = 256;
  int max_layers = 16;
  int atlas_resolution = 128;
  bool light_weighting = false;  // Fig. 10.6
  bool moving_light = false;
  ObscuranceOutput output = ObscuranceOutput::kFinal;
  std::uint32_t seed = 0;
  ShadowSettings shadow;  // the direct light's
  int light_samples = 16;
};

// What the map's construction cost and found (statistics).
struct ObscuranceMapBuild {
  double peel_ms = 0;        // depth peeling, all bundles
  double accumulate_ms = 0;  // the bundles' samples added into the atlas
  double normalize_ms = 0;
  double layers_mean = 0;  // layers per bundle
  int layers_max = 0;
  int layers_truncated = 0;  // bundles that reached max_layers (a ray may have lost surfaces)
};

class ObscurancesTechnique final : public Technique {
 public:
  explicit ObscurancesTechnique(const ParameterValues& parameters);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  scene::PathClass pathClass() const override { return {0, scene::PathClass::kUnlimited}; }
  std::optional<scene::ObscuranceDefinition> imageObscurance() const override;
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;

  const ObscurancesSettings& settings() const { return settings_; }
  // For tests: the baked atlas, and W of every texel (rgb; row 0 at the bottom like the texels).
  const atlas::AtlasTexels& atlasTexels() const { return texels_; }
  const std::vector<atlas::AtlasTriangle>& atlasTriangles() const { return triangles_; }
  const atlas::AtlasLayout& atlasLayout() const { return layout_; }
  std::vector<glm::vec3> obscuranceMap() const;
  const ObscuranceMapBuild& build() const { return build_; }
  glm::vec3 ambientLight() const { return ambient_; }

 private:
  void buildObscuranceMap();
  void drawView(const RenderTarget& target, bool show_obscurance, glm::vec3 light_offset);
  image::Image peelLayersFigure();

  ObscurancesSettings settings_;
  const GpuScene* scene_ = nullptr;
  int width_ = 0, height_ = 0;
  std::vector<atlas::AtlasTriangle> triangles_;
  atlas::AtlasLayout layout_;
  atlas::AtlasTexels texels_;
  std::optional<atlas::AtlasTextures> atlas_;
  std::optional<atlas::AtlasMesh> mesh_;
  std::optional<DepthPeeler> peeler_;
  gl::Texture sums_, source_, obscurance_;
  glm::vec3 ambient_{0.0f}, average_albedo_{0.0f};
  float d_max_ = 0;
  glm::vec3 light_position_{0.0f};
  bool has_light_position_ = false;
  ObscuranceMapBuild build_;
  std::optional<SurfaceLighting> surface_lighting_;
  std::optional<RenderTarget> ambient_view_;
  glm::vec3 last_light_offset_{0.0f};
  gl::Program accumulate_program_, view_program_;
  gl::FullScreenPass normalize_pass_, composite_pass_;
  std::optional<gl::VertexArray> points_;  // attribute-less: the points read the layers
  // The light weighting's normaliser, 1 / the area mean of 1/(|x − p|² + d_max²), for the light
  // at `weighted_light_` (recomputed only when the light moves).
  float weight_scale_ = 1.0f;
  std::optional<glm::vec3> weighted_light_;
};

TechniqueInfo obscurancesTechniqueInfo();

}  // namespace gib::rt
