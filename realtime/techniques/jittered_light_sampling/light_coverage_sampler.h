// Hardware sampling of an area light's visibility (Fournier & Péroche §4): from a point, the
// light and the occluders in front of it are rasterized into a small image whose pixels sample
// the light; the image is read back and its visible samples are weighted by the solid angle they
// stand for. Four schemes: an occlusion query (count the light's unoccluded pixel centres, each
// worth the same), regular (pixel centres, each weighted by its own solid angle), and jittered
// with 1, 4 or 8 samples per pixel, one in each stratum (unbiased, and progressive).
//
// The frustum: the image plane is the light's plane, its axes along the light's first edge, its
// window the light's bounding rectangle there. So the pixels are a grid on the light itself (no
// pixel is wasted beside a rectangular light), and a pixel's solid angle at x is the integral of
// cos θ'/r² over its cell. Edges parallel to the light's first edges, the light's and the
// occluders', are then aligned with the sampling grid: the case §6.1 sets up on purpose.
#pragma once

#include "realtime/gl/objects.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gib::rt {

enum class CoverageScheme { kOcclusionQuery, kRegular, kJittered };

struct CoverageSettings {
  CoverageScheme scheme = CoverageScheme::kJittered;
  int size = 48;              // the image is size × size pixels (the paper: 32, 48, 64)
  int samples_per_pixel = 1;  // jittered: 1, 4 or 8
  std::uint32_t seed = 0;     // jittered positions are a hash of (seed, point, pixel, sample)
};

// The scheme's name as the command line and results write it: occlusion_query, regular,
// jittered1, jittered4, jittered8.
std::string coverageSchemeName(const CoverageSettings& settings);
// Parses such a name into `settings` (scheme and samples); throws InputError naming the choices.
void parseCoverageScheme(const std::string& name, CoverageSettings& settings);
// Every scheme name, in the paper's order.
const std::vector<std::string>& coverageSchemeNames();
// Throws InputError unless size is in [kMinCoverageSize, kMaxCoverageSize].
void validateCoverageSize(int size);
inline constexpr int kMinCoverageSize = 4;
inline constexpr int kMaxCoverageSize = 256;

// Wall-clock milliseconds of the three phases of one point's sample (the paper's Fig. 9): drawing
// the light and the occluders (finished with glFinish), reading the image or query back, and
// weighting the pixels on the CPU.
struct CoveragePhaseTimes {
  double render_ms = 0;
  double read_back_ms = 0;
  double weight_ms = 0;
};

// Clears `framebuffer` (no bits, far depth) and draws a coverage image into each of its
// `instances` layers with the current program and coverage triangles: the light's (vertices
// [0, light_vertices)) OR their sample bits in and write the light's depth, then the occluders'
// (up to all_vertices) in front of it take theirs out (AND NOT), without writing depth, so that
// one occluder's partial pixel does not hide another's (§4.2.2, with integer logic operations).
void drawCoverage(const gl::Framebuffer& framebuffer, int size, GLsizei light_vertices,
                  GLsizei all_vertices, GLsizei instances);

class LightCoverageSampler {
 public:
  // `light` and `occluders` are triangles (three world-space corners each); the light's are
  // coplanar. Needs a current GL context.
  LightCoverageSampler(const std::vector<glm::vec3>& light, const std::vector<glm::vec3>& occluders,
                       const CoverageSettings& settings);

  // The solid angle of the light that x sees past the occluders, as the scheme estimates it.
  // `point` names x in the jitter hash, so each point draws its own positions.
  double visibleSolidAngle(const glm::dvec3& x, std::uint32_t point, CoveragePhaseTimes* times);

 private:
  struct View;
  View viewFrom(const glm::dvec3& x) const;
  void draw(const View& view, std::uint32_t point);
  double weigh(const View& view, std::uint32_t point) const;

  CoverageSettings settings_;
  GLsizei light_vertices_ = 0;
  GLsizei occluder_vertices_ = 0;
  glm::dvec3 plane_point_{0.0};
  glm::dvec3 plane_normal_{0.0};
  glm::dvec3 first_edge_{0.0};
  std::vector<glm::dvec3> light_corners_;
  gl::Buffer triangles_;
  std::optional<gl::LayeredTarget> coverage_;  // 8-bit
  gl::VertexArray vertex_array_;
  gl::Program program_;
  gl::Query visible_samples_;
  std::vector<std::uint8_t> pixels_;
  std::uint64_t query_count_ = 0;
};

}  // namespace gib::rt
