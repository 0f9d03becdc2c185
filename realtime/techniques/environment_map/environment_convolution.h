// The convolved environment maps of book §4.2.2: the irradiance E(n) of every normal direction,
// and per Phong exponent the glossy lobe's integral about every reflected direction, summed over
// a downsampled copy of the environment by a compute pass when the technique is prepared (the
// environment is static), and read by one texture lookup per pixel (environment.frag.glsl).
#pragma once

#include "image/image.h"
#include "realtime/gl/objects.h"
#include "scene/environment_map.h"

#include <glm/vec4.hpp>

#include <vector>

namespace gib::scene {
struct Scene;
}

namespace gib::rt {

// The environment resampled to `height` rows (2 × height columns) of cells: each cell's radiance
// is the solid-angle-weighted mean of the map's texels over it, before the map's intensity (the
// map's texels are piecewise constant, so ∫ L dω over the sphere is kept; a cell inside one texel
// has that texel's value, so a map with fewer rows, a constant sky's 2 × 1, is refined exactly).
// Beside it, per cell, the integral of the direction over the cell, xyz = ∫_cell ω dω in closed
// form, and w = its solid angle ∫_cell dω.
struct DownsampledEnvironment {
  int width = 0, height = 0;
  std::vector<glm::vec4> radiance;  // rgb, row-major from the zenith row; w 1
  std::vector<glm::vec4> cells;
};
DownsampledEnvironment downsampleEnvironment(const scene::EnvironmentMap& map, int height);

class EnvironmentConvolution {
 public:
  // Downsamples `map` to `source_height` rows and sums the maps at `height` rows (2 × height
  // columns) on the GPU, one dispatch per layer, waiting for them. Throws gib::InputError for
  // more exponents than gpu::kMaxGlossyMaps.
  EnvironmentConvolution(const scene::EnvironmentMap& map, int source_height, int height,
                         const std::vector<float>& exponents);

  // Binds the maps (an RGBA32F 2D array, linear filtering, wrapping round in azimuth) at
  // gpu::kConvolvedMapsUnit.
  void bind() const;

  // Wall time of the downsampling, the upload and the dispatches, to their end.
  double milliseconds() const { return milliseconds_; }
  int sourceTexels() const { return source_texels_; }
  // Texels of all the layers, each a sum over sourceTexels() cells.
  int convolvedTexels() const;
  int layers() const { return maps_.depth(); }
  // Layer `layer` of the maps (RGB, row 0 the zenith) times `intensity`.
  image::Image layerImage(int layer, float intensity) const;

 private:
  gl::Texture maps_;
  double milliseconds_ = 0;
  int source_texels_ = 0;
};

}  // namespace gib::rt
