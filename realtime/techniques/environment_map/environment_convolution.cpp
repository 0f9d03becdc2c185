#include "realtime/techniques/environment_map/environment_convolution.h"

#include "common/input_error.h"
#include "realtime/gl/finished_time.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/shader_library.h"
#include "realtime/techniques/environment_map/environment_map_shared.h"
#include "scene/scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::rt {

namespace {

constexpr double kPi = std::numbers::pi;

// The overlaps of n equal cells of [0, 1] with m equal cells: per cell j of the m, the cells i
// of the n that meet it and the length of [i/n, (i+1)/n] ∩ [j/m, (j+1)/m] in [0, 1]'s units.
struct Overlap {
  int from = 0;
  double length = 0;
};
std::vector<std::vector<Overlap>> overlaps(int n, int m) {
  std::vector<std::vector<Overlap>> result(static_cast<std::size_t>(m));
  for (int j = 0; j < m; ++j) {
    const double lo = double(j) / m, hi = double(j + 1) / m;
    for (int i = int(lo * n); i < n && double(i) / n < hi; ++i) {
      const double length = std::min(hi, double(i + 1) / n) - std::max(lo, double(i) / n);
      if (length > 0) result[std::size_t(j)].push_back({i, length});
    }
  }
  return result;
}

}  // namespace

DownsampledEnvironment downsampleEnvironment(const scene::EnvironmentMap& map, int height) {
  DownsampledEnvironment out;
  out.height = height;
  out.width = 2 * out.height;
  // Solid angles are separable on a latitude-longitude grid: a cell θ ∈ [θ0, θ1], φ ∈ [φ0, φ1]
  // subtends (cos θ0 − cos θ1)·(φ1 − φ0). So each down cell's mean weighs the map's columns by
  // their overlap in φ and its rows by their overlap's ∫ sin θ dθ.
  const auto columns = overlaps(map.width, out.width);
  const auto rows = overlaps(map.height, out.height);
  std::vector<glm::dvec3> row_means(std::size_t(map.height) * std::size_t(out.width));
  for (int y = 0; y < map.height; ++y)
    for (int X = 0; X < out.width; ++X) {
      glm::dvec3 sum(0.0);
      for (const Overlap& o : columns[std::size_t(X)])
        sum += o.length * glm::dvec3(map.texel(o.from, y));
      row_means[std::size_t(y) * std::size_t(out.width) + std::size_t(X)] = sum * double(out.width);
    }
  out.radiance.resize(std::size_t(out.width) * std::size_t(out.height));
  out.cells.resize(out.radiance.size());
  for (int Y = 0; Y < out.height; ++Y) {
    const double theta0 = kPi * Y / out.height, theta1 = kPi * (Y + 1) / out.height;
    for (int X = 0; X < out.width; ++X) {
      glm::dvec3 sum(0.0);
      double weight = 0;
      for (const Overlap& o : rows[std::size_t(Y)]) {
        // The overlap [a, b] in θ of map row o.from and down row Y.
        const double a = std::max(theta0, kPi * o.from / map.height);
        const double b = a + kPi * o.length;
        const double w = std::cos(a) - std::cos(b);
        sum += w * row_means[std::size_t(o.from) * std::size_t(out.width) + std::size_t(X)];
        weight += w;
      }
      const std::size_t i = std::size_t(Y) * std::size_t(out.width) + std::size_t(X);
      out.radiance[i] = glm::vec4(glm::vec3(sum / weight), 1.0f);
      // ∫ ω dω over the cell, ω = (sinθ cosφ, cosθ, sinθ sinφ), dω = sinθ dθ dφ.
      const double phi0 = 2 * kPi * X / out.width, phi1 = 2 * kPi * (X + 1) / out.width;
      const double sin2 =
          0.5 * (theta1 - theta0) - 0.25 * (std::sin(2 * theta1) - std::sin(2 * theta0));
      const double sin_cos =
          0.5 * (std::sin(theta1) * std::sin(theta1) - std::sin(theta0) * std::sin(theta0));
      out.cells[i] =
          glm::vec4(float(sin2 * (std::sin(phi1) - std::sin(phi0))), float(sin_cos * (phi1 - phi0)),
                    float(sin2 * (std::cos(phi0) - std::cos(phi1))),
                    float((std::cos(theta0) - std::cos(theta1)) * (phi1 - phi0)));
    }
  }
  return out;
}

EnvironmentConvolution::EnvironmentConvolution(const scene::EnvironmentMap& map, int source_height,
                                               int height, const std::vector<float>& exponents) {
  if (exponents.size() > std::size_t(gpu::kMaxGlossyMaps))
    throw InputError(fmt::format(
        "the scene's glossy meshes use {} distinct Phong exponents; environment_map convolves "
        "at most {} glossy maps: give the glossy materials fewer distinct exponents",
        exponents.size(), gpu::kMaxGlossyMaps));
  const int layers = 1 + int(exponents.size());
  maps_ = gl::Texture::make2DArray(GL_RGBA32F, 2 * height, height, layers);
  // Bilinear between texel centres; round in azimuth, clamped at the poles.
  maps_.setFilter(GL_LINEAR, GL_LINEAR);
  maps_.setWrap(GL_CLAMP_TO_EDGE);
  glTextureParameteri(maps_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  const gl::Program program = gl::buildProgram(
      {{GL_COMPUTE_SHADER, "realtime/techniques/environment_map/convolve.comp.glsl"}});
  milliseconds_ = gl::finishedMilliseconds([&] {
    const DownsampledEnvironment source = downsampleEnvironment(map, source_height);
    source_texels_ = source.width * source.height;
    gl::Texture radiance = gl::Texture::make2D(GL_RGBA32F, source.width, source.height);
    radiance.upload(&source.radiance[0].x, GL_RGBA);
    gl::Texture cells = gl::Texture::make2D(GL_RGBA32F, source.width, source.height);
    cells.upload(&source.cells[0].x, GL_RGBA);
    program.use();
    radiance.bind(gpu::kConvolutionRadianceUnit);
    cells.bind(gpu::kConvolutionCellsUnit);
    glBindImageTexture(gpu::kImageDestinationUnit, maps_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       GL_RGBA32F);
    const auto groups = [](int n) {
      return GLuint((n + gpu::kConvolutionGroupSize - 1) / gpu::kConvolutionGroupSize);
    };
    for (int layer = 0; layer < layers; ++layer) {
      program.set("u_layer", layer);
      program.set("u_exponent", layer == 0 ? -1.0f : exponents[std::size_t(layer - 1)]);
      gl::dispatchCompute(groups(2 * height), groups(height), 1);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  });
}

void EnvironmentConvolution::bind() const {
  maps_.bind(gpu::kConvolvedMapsUnit);
}

int EnvironmentConvolution::convolvedTexels() const {
  return maps_.width() * maps_.height() * maps_.depth();
}

image::Image EnvironmentConvolution::layerImage(int layer, float intensity) const {
  const int w = maps_.width(), h = maps_.height();
  std::vector<float> texels(std::size_t(w) * std::size_t(h) * 4);
  glGetTextureSubImage(maps_.id(), 0, 0, 0, layer, w, h, 1, GL_RGBA, GL_FLOAT,
                       GLsizei(texels.size() * sizeof(float)), texels.data());
  image::Image out(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        out.pixel(x, y)[c] =
            intensity *
            texels[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * 4 + std::size_t(c)];
  return out;
}

}  // namespace gib::rt
