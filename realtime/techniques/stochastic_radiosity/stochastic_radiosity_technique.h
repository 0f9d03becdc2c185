// `stochastic_radiosity`: diffuse global illumination by stochastic iteration with random texel
// shooting on the GPU (Barsi & Jakab, "Stream Processing in Global Illumination"; book §7.1).
// The radiance lives in a texture atlas (realtime/atlas/); each iteration (step()) selects one
// texel with probability proportional to the luminance of its power, draws the scene from it
// into a visibility map (hemicube or hemispherical projection), and updates every texel's
// reflected radiance in texture space with the running average of the paper's eq. (2). A frame
// draws the camera view with bilinear lookups of the atlas plus emission.
//
// Passes of an iteration: selection, visibility, update, mipmap (the power pyramid for the next
// selection; GPU selection only); of a frame: view. See README.md beside this file.
#pragma once

#include "realtime/atlas/atlas_layout.h"
#include "realtime/atlas/atlas_mesh.h"
#include "realtime/atlas/atlas_textures.h"
#include "realtime/gl/fullscreen_pass.h"
#include "realtime/technique.h"
#include "realtime/techniques/stochastic_radiosity/shooter_visibility.h"
#include "realtime/techniques/stochastic_radiosity/texel_selection.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace gib::rt {

inline constexpr std::string_view kSelectionPass = "selection";    // of an iteration
inline constexpr std::string_view kVisibilityPass = "visibility";  // of an iteration
inline constexpr std::string_view kUpdatePass = "update";          // of an iteration
inline constexpr std::string_view kMipmapPass = "mipmap";          // of an iteration, GPU selection
inline constexpr std::string_view kViewPass = "view";              // of a frame

struct StochasticRadiositySettings {
  int atlas_resolution = 128;
  SelectionMethod selection = SelectionMethod::kGpu;
  ShooterProjection projection = ShooterProjection::kHemicube;
  int visibility_size = 256;
  int tessellation = 0;
  std::uint32_t seed = 0;
};

class StochasticRadiosityTechnique final : public Technique {
 public:
  explicit StochasticRadiosityTechnique(const ParameterValues& parameters);
  explicit StochasticRadiosityTechnique(const StochasticRadiositySettings& settings);

  void prepare(const GpuScene& scene, int width, int height) override;
  void render(Frame& frame) override;
  bool iterative() const override { return true; }
  void step(gl::PassProfiler& profiler) override;
  int iterations() const override { return iteration_; }
  scene::PathClass pathClass() const override { return {0, scene::PathClass::kUnlimited}; }
  std::vector<AuxiliaryImage> auxiliaryImages() override;
  std::vector<TechniqueStatistic> statistics() const override;

  // For tests: the baked atlas and the current radiance of every texel (emission + injected +
  // reflected), row 0 at the bottom like the atlas texels.
  const atlas::AtlasTexels& atlasTexels() const { return texels_; }
  std::vector<glm::vec3> atlasRadiance() const;
  // The same as an image, top row first (the auxiliary image "atlas").
  image::Image atlasImage() const;

  // The uniform random number of iteration m (1-based): the same for every run with this seed,
  // so a frame sequence does not flicker (book §7.1.2).
  static float selectionValue(std::uint32_t seed, int iteration);

 private:
  void runUpdatePass();

  StochasticRadiositySettings settings_;
  const GpuScene* scene_ = nullptr;
  std::vector<atlas::AtlasTriangle> triangles_;
  atlas::AtlasLayout layout_;
  atlas::AtlasTexels texels_;
  std::optional<atlas::AtlasTextures> atlas_;
  std::optional<atlas::AtlasMesh> mesh_;
  std::optional<TexelSelection> selection_;
  std::optional<ShooterVisibility> visibility_;
  gl::Texture source_;                     // L^e + injected direct light
  std::array<gl::Texture, 2> reflected_;   // ping-pong L̃^r
  std::array<gl::Framebuffer, 2> update_;  // reflected_[k] + power level 0
  gl::Framebuffer source_framebuffer_;
  int current_ = 0;  // reflected_[current_] holds the estimate
  int iteration_ = 0;
  gl::FullScreenPass update_pass_;
  gl::Program view_program_;
};

TechniqueInfo stochasticRadiosityTechniqueInfo();

}  // namespace gib::rt
