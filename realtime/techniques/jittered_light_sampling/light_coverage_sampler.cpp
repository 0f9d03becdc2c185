#include "realtime/techniques/jittered_light_sampling/light_coverage_sampler.h"

#include "common/input_error.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/techniques/jittered_light_sampling/jittered_light_sampling_shared.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace gib::rt {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

// The point's camera, as coverage_view.glsl builds it on the GPU (here in double, for the
// weights): origin x, looking along the light plane's normal towards it, image plane
// axes U (the light's first edge) and V, window [u0, u1] × [v0, v1] in the light's plane at
// distance d.
struct LightCoverageSampler::View {
  bool sees_plane = false;
  glm::dvec3 x{0.0};
  double d = 0;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
};

const std::vector<std::string>& coverageSchemeNames() {
  static const std::vector<std::string> names = {"occlusion_query", "regular", "jittered1",
                                                 "jittered4", "jittered8"};
  return names;
}

std::string coverageSchemeName(const CoverageSettings& s) {
  switch (s.scheme) {
    case CoverageScheme::kOcclusionQuery:
      return "occlusion_query";
    case CoverageScheme::kRegular:
      return "regular";
    case CoverageScheme::kJittered:
      return fmt::format("jittered{}", s.samples_per_pixel);
  }
  return "";
}

void parseCoverageScheme(const std::string& name, CoverageSettings& s) {
  if (name == "occlusion_query") {
    s.scheme = CoverageScheme::kOcclusionQuery;
  } else if (name == "regular") {
    s.scheme = CoverageScheme::kRegular;
  } else if (name == "jittered1" || name == "jittered4" || name == "jittered8") {
    s.scheme = CoverageScheme::kJittered;
    s.samples_per_pixel = name.back() - '0';
  } else {
    throw InputError(fmt::format("unknown sampling scheme '{}'; give one of {}", name,
                                 fmt::join(coverageSchemeNames(), ", ")));
  }
}

void validateCoverageSize(int size) {
  if (size < kMinCoverageSize || size > kMaxCoverageSize)
    throw InputError(
        fmt::format("sampling size {} is out of range; give {}..{} pixels a side (the "
                    "paper used 32, 48 and 64)",
                    size, kMinCoverageSize, kMaxCoverageSize));
}

void drawCoverage(const gl::Framebuffer& framebuffer, int size, GLsizei light_vertices,
                  GLsizei all_vertices, GLsizei instances) {
  const GLuint zero[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  glClearNamedFramebufferuiv(framebuffer.id(), GL_COLOR, 0, zero);
  glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &far_depth);
  framebuffer.bind();
  // The light's samples are OR-ed in wherever it lies, its depth written; then the occluders in
  // front of it clear theirs (AND NOT), leaving the light's depth.
  const gl::PipelineScope light_state(
      {.depth_test = GL_ALWAYS, .logic_op = GL_OR, .viewport = gl::PixelRect{0, 0, size, size}});
  gl::drawArraysInstanced(GL_TRIANGLES, 0, light_vertices, instances);
  if (all_vertices > light_vertices) {
    const gl::PipelineScope occluder_state(
        {.depth_test = GL_LESS, .depth_write = false, .logic_op = GL_AND_INVERTED});
    gl::drawArraysInstanced(GL_TRIANGLES, light_vertices, all_vertices - light_vertices, instances);
  }
}

LightCoverageSampler::LightCoverageSampler(const std::vector<glm::vec3>& light,
                                           const std::vector<glm::vec3>& occluders,
                                           const CoverageSettings& settings)
    : settings_(settings) {
  validateCoverageSize(settings.size);
  if (light.size() < 3 || light.size() % 3 != 0 || occluders.size() % 3 != 0)
    throw std::invalid_argument("light and occluders must be lists of triangles");
  plane_point_ = glm::dvec3(light[0]);
  first_edge_ = glm::normalize(glm::dvec3(light[1]) - plane_point_);
  plane_normal_ = glm::normalize(
      glm::cross(glm::dvec3(light[1]) - plane_point_, glm::dvec3(light[2]) - plane_point_));
  for (const glm::vec3& c : light) light_corners_.push_back(glm::dvec3(c));

  std::vector<glm::vec4> corners;
  for (const glm::vec3& c : light) corners.emplace_back(c, 1.0f);
  for (const glm::vec3& c : occluders) corners.emplace_back(c, 1.0f);
  light_vertices_ = GLsizei(light.size());
  occluder_vertices_ = GLsizei(occluders.size());
  triangles_ = gl::Buffer::fromVector(corners, 0);

  coverage_.emplace(GL_R8UI, settings.size, 1);  // one point at a time: one layer
  program_ = gl::buildProgram(
      {{GL_VERTEX_SHADER, "realtime/techniques/jittered_light_sampling/coverage.vert.glsl"},
       {GL_GEOMETRY_SHADER, "realtime/techniques/jittered_light_sampling/coverage.geom.glsl"},
       {GL_FRAGMENT_SHADER, "realtime/techniques/jittered_light_sampling/coverage.frag.glsl"}});
  const int samples = settings.scheme == CoverageScheme::kJittered ? settings.samples_per_pixel : 0;
  if (samples > gpu::kMaxSamplesPerPixel)
    throw std::invalid_argument("at most 8 jittered samples per pixel fit the coverage image");
  program_.set("u_size", settings.size);
  program_.set("u_samples", samples);
  program_.set("u_seed", settings.seed);
  program_.set("u_light_vertices", light_vertices_);
  visible_samples_ = gl::Query(GL_SAMPLES_PASSED);
  pixels_.resize(std::size_t(settings.size) * settings.size);
}

LightCoverageSampler::View LightCoverageSampler::viewFrom(const glm::dvec3& x) const {
  View view;
  view.x = x;
  const double signed_distance = glm::dot(plane_point_ - x, plane_normal_);
  view.d = std::abs(signed_distance);
  if (view.d < 1e-9) return view;  // in the light's plane: it subtends nothing
  view.sees_plane = true;
  const glm::dvec3 forward = signed_distance > 0 ? plane_normal_ : -plane_normal_;
  const glm::dvec3 back = -forward;
  const glm::dvec3 right = first_edge_;
  const glm::dvec3 up = glm::cross(back, right);  // right-handed: right × up = back
  view.u0 = view.v0 = std::numeric_limits<double>::infinity();
  view.u1 = view.v1 = -std::numeric_limits<double>::infinity();
  for (const glm::dvec3& c : light_corners_) {
    const double u = glm::dot(c - x, right), v = glm::dot(c - x, up);
    view.u0 = std::min(view.u0, u);
    view.u1 = std::max(view.u1, u);
    view.v0 = std::min(view.v0, v);
    view.v1 = std::max(view.v1, v);
  }
  return view;
}

void LightCoverageSampler::draw(const View& view, std::uint32_t point) {
  program_.use();
  const glm::vec3 x(view.x);
  program_.set("u_point_position", x);
  program_.set("u_point", point);
  triangles_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kCoverageTrianglesBinding);
  vertex_array_.bind();
  if (settings_.scheme != CoverageScheme::kOcclusionQuery) {
    drawCoverage(coverage_->framebuffer(), settings_.size, light_vertices_,
                 light_vertices_ + occluder_vertices_, 1);
    return;
  }
  // §4.1.1: occluders set up the depth buffer, then the query counts the light's pixels that
  // pass the depth test.
  const float far_depth = 1.0f;
  glClearNamedFramebufferfv(coverage_->framebuffer().id(), GL_DEPTH, 0, &far_depth);
  coverage_->framebuffer().bind();
  // Depth alone: the occluders' written, then the light's tested against it.
  constexpr std::array<bool, 4> kNoColor = {false, false, false, false};
  const gl::PipelineScope occluder_state(
      {.depth_test = GL_LESS,
       .color_write = kNoColor,
       .viewport = gl::PixelRect{0, 0, settings_.size, settings_.size}});
  if (occluder_vertices_ > 0) gl::drawArrays(GL_TRIANGLES, light_vertices_, occluder_vertices_);
  const gl::PipelineScope light_state(
      {.depth_test = GL_LESS, .depth_write = false, .color_write = kNoColor});
  glBeginQuery(GL_SAMPLES_PASSED, visible_samples_.id());
  gl::drawArrays(GL_TRIANGLES, 0, light_vertices_);
  glEndQuery(GL_SAMPLES_PASSED);
}

double LightCoverageSampler::weigh(const View& view, std::uint32_t point) const {
  const int n = settings_.size;
  const double du = (view.u1 - view.u0) / n, dv = (view.v1 - view.v0) / n;
  if (settings_.scheme == CoverageScheme::kOcclusionQuery) {
    // Every pixel worth the same: the window's solid angle over its pixel count.
    const double window =
        gpu::windowSolidAngle(glm::vec4(view.u0, view.v0, view.u1, view.v1), float(view.d));
    return double(query_count_) * window / (double(n) * n);
  }
  // Eq. (3) without the receiver's cosine: a sample at (u, v) of the plane at distance d stands
  // for the solid angle d·A/r³ of its stratum's area A, evaluated where the sample lies, which
  // makes the jittered estimate unbiased.
  const int samples =
      settings_.scheme == CoverageScheme::kJittered ? settings_.samples_per_pixel : 0;
  const double stratum_area = du * dv / std::max(samples, 1);
  double sum = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const std::uint32_t pixel = std::uint32_t(y * n + x);
      const std::uint8_t bits = pixels_[pixel];
      for (int k = 0; bits >> k; ++k) {
        if (!((bits >> k) & 1u)) continue;
        const glm::vec2 offset =
            gpu::coverageSampleOffset(settings_.seed, point, pixel, k, samples);
        const double u = view.u0 + (x + double(offset.x)) * du;
        const double v = view.v0 + (y + double(offset.y)) * dv;
        const double r2 = u * u + v * v + view.d * view.d;
        sum += stratum_area * view.d / (r2 * std::sqrt(r2));
      }
    }
  return sum;
}

double LightCoverageSampler::visibleSolidAngle(const glm::dvec3& x, std::uint32_t point,
                                               CoveragePhaseTimes* times) {
  const View view = viewFrom(x);
  if (!view.sees_plane) {
    if (times) *times = {};
    return 0;
  }
  auto start = Clock::now();
  draw(view, point);
  glFinish();
  const double render_ms = millisecondsSince(start);

  start = Clock::now();
  if (settings_.scheme == CoverageScheme::kOcclusionQuery) {
    query_count_ = visible_samples_.result();
  } else {
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(coverage_->color().id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE,
                      GLsizei(pixels_.size()), pixels_.data());
  }
  const double read_back_ms = millisecondsSince(start);

  start = Clock::now();
  const double omega = weigh(view, point);
  if (times) *times = {render_ms, read_back_ms, millisecondsSince(start)};
  return omega;
}

}  // namespace gib::rt
