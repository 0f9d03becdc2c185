// `distance_map_specular` and the searches of realtime/distance_map/ (book §6.1-6.3): the GLSL
// searches evaluated on the GPU on a distance map the test fills itself (the box of known walls
// round o), the closed forms of the linear and secant searches on the CPU, Fresnel's
// approximation against the exact functions at known angles, the technique against the reference
// of its class on the Cornell box with a mirror sphere, and its bad input.
#include "realtime/techniques/distance_map_specular/distance_map_specular_technique.h"

#include "common/input_error.h"
#include "image/image.h"
#include "metrics/image_metrics.h"
#include "realtime/distance_map/distance_map_shared.h"
#include "realtime/gl/objects.h"
#include "realtime/gl/shader_library.h"
#include "realtime/sh/spherical_harmonics.h"
#include "realtime/technique_runner.h"
#include "reference/embree_scene.h"
#include "reference/progressive_renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/camera.h"
#include "scene/fresnel_shared.h"
#include "scene/metals.h"
#include "scene/path_expression.h"
#include "support/gl_test_context.h"
#include "support/statistical_test.h"
#include "support/technique_frame.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace gib::rt {
namespace {

// ---------------------------------------------------------------------------------------------
// A synthetic distance map: the inside of an axis-aligned box round the reference point o (the
// origin), walls at known, unequal distances, so that a ray's true hit is a closed form.

constexpr glm::vec3 kBoxMin(-2.0f, -1.5f, -2.5f), kBoxMax(3.0f, 2.5f, 1.0f);
constexpr int kMapSize = 128;
// What one bilinear lookup of the map may err by, relative to the distance D it returns, away
// from the box's edges and the cube's face seams: over a face the distance to a wall is
// D·√(1 + s² + t²), whose second derivatives in the face coordinates are at most D, so bilinear
// interpolation between texel centres h = 2/N apart errs by at most (h²/8)·2D = D/N²; and the
// sampler places the lookup to a fraction of a texel only (8-bit filter weights on a GPU;
// llvmpipe's cube lookups measured up to h/60 off, 2026-11-28), which the distance's slope (at
// most D) turns into D·h/32 allowed here. 5.5·10⁻⁴ at N = 128.
constexpr double kLookupRelative = 1.0 / (kMapSize * kMapSize) + 1.0 / (16.0 * kMapSize);
// The secant loop stops within 10⁻⁴ of the surface (|r|/|r′| in [0.9999, 1.0001], the book's).
constexpr double kSecantStop = 1.0e-4;

// The first t > 0 where x + t·R meets the box's walls from inside, and the wall's axis.
struct BoxHit {
  float t = 0;
  int axis = 0;
};
BoxHit boxHit(const glm::vec3& x, const glm::vec3& R) {
  BoxHit best{1e30f, 0};
  for (int a = 0; a < 3; ++a) {
    if (R[a] == 0.0f) continue;
    const float t = ((R[a] > 0 ? kBoxMax[a] : kBoxMin[a]) - x[a]) / R[a];
    if (t < best.t) best = {t, a};
  }
  return best;
}

// The cube face a direction reads (OpenGL's: the axis of largest magnitude).
int cubeFace(const glm::vec3& d) {
  const glm::vec3 m = glm::abs(d);
  if (m.x >= m.y && m.x >= m.z) return d.x > 0 ? 0 : 1;
  if (m.y >= m.z) return d.y > 0 ? 2 : 3;
  return d.z > 0 ? 4 : 5;
}

// Whether the map's lookup in direction d (from o) is clear, by `texels` texels, of the box's
// edges (where the bilinear filter mixes two walls) and of the cube's seams (where the array,
// sampled without seamless filtering, clamps at a face's edge).
bool clearOfEdges(const glm::vec3& d, int texels = 3) {
  const glm::vec3 u = glm::normalize(d);
  const int face = cubeFace(u), wall = boxHit(glm::vec3(0.0f), u).axis;
  const float step = 2.0f * float(texels) / float(kMapSize) * glm::length(glm::abs(u));
  for (int a = 0; a < 3; ++a)
    for (float sign : {-1.0f, 1.0f}) {
      glm::vec3 moved = u;
      moved[a] += sign * step;
      if (cubeFace(moved) != face || boxHit(glm::vec3(0.0f), glm::normalize(moved)).axis != wall)
        return false;
    }
  return true;
}

// Directions spread over the sphere (a Fibonacci spiral): fixed, and the same on every platform.
std::vector<glm::vec3> spreadDirections(int count) {
  std::vector<glm::vec3> directions;
  const double golden = 3.14159265358979 * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / count, r = std::sqrt(1.0 - z * z);
    directions.emplace_back(float(r * std::cos(golden * i)), float(r * std::sin(golden * i)),
                            float(z));
  }
  return directions;
}

// One ray for distanceMapHit: origin x (relative to o), unit R, method and steps.
struct SearchCase {
  glm::vec4 origin{0.0f};
  glm::vec4 direction{0.0f};
  glm::ivec4 settings{0};  // method, linear steps, secant steps
};

class DistanceMapSearch : public test::GlTest {
 protected:
  void SetUp() override {
    test::GlTest::SetUp();
    // The box's map: every texel the distance from o to the wall in its centre's direction.
    maps_ = gl::Texture::makeCubeArray(GL_RGBA32F, kMapSize, 1);
    maps_.setFilter(GL_LINEAR, GL_LINEAR);
    maps_.setWrap(GL_CLAMP_TO_EDGE);
    std::vector<float> texels(std::size_t(kMapSize) * kMapSize * 4);
    for (int face = 0; face < 6; ++face) {
      for (int j = 0; j < kMapSize; ++j)
        for (int i = 0; i < kMapSize; ++i) {
          const glm::vec3 d = glm::normalize(sh::cubeTexelDirection(face, i, j, kMapSize));
          float* texel = &texels[(std::size_t(j) * kMapSize + i) * 4];
          texel[0] = texel[1] = texel[2] = 1.0f;
          texel[3] = boxHit(glm::vec3(0.0f), d).t;
        }
      maps_.upload(texels.data(), GL_RGBA, 0, face);
    }
    gpu::DistanceMapBlock block{};
    block.counts = glm::ivec4(1, kMapSize, 0, 0);
    block_ = gl::Buffer(sizeof(block), &block);
    const std::string source =
        "#include \"realtime/distance_map/distance_map.glsl\"\n"
        "layout(local_size_x = 1) in;\n"
        "struct SearchCase { vec4 origin; vec4 direction; ivec4 settings; };\n"
        "layout(std430, binding = kTestFirstStorageBinding) readonly buffer Cases {\n"
        "  SearchCase cases[];\n"
        "};\n"
        "layout(std430, binding = kTestFirstStorageBinding + 1) writeonly buffer Hits {\n"
        "  vec4 hits[];\n"
        "};\n"
        "void main() {\n"
        "  SearchCase c = cases[gl_GlobalInvocationID.x];\n"
        "  hits[gl_GlobalInvocationID.x] = vec4(distanceMapHit(0, c.origin.xyz, c.direction.xyz,\n"
        "      c.settings.x, c.settings.y, c.settings.z), 1.0);\n"
        "}\n";
    program_ = gl::buildProgram({{GL_COMPUTE_SHADER, "test/search.comp.glsl"}}, "",
                                [&](std::string_view path) -> std::string_view {
                                  return path == "test/search.comp.glsl" ? std::string_view(source)
                                                                         : gl::glslFile(path);
                                });
  }

  // The hit distanceMapHit finds for each case (relative to o), on the GPU.
  std::vector<glm::vec3> search(const std::vector<SearchCase>& cases) const {
    const gl::Buffer input = gl::Buffer::fromVector(cases);
    const gl::Buffer output = gl::Buffer::fromVector(std::vector<glm::vec4>(cases.size()));
    input.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTestFirstStorageBinding);
    output.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTestFirstStorageBinding + 1);
    block_.bindBase(GL_UNIFORM_BUFFER, gpu::kDistanceMapObjectsBinding);
    maps_.bind(gpu::kDistanceMapUnit);
    program_.use();
    glDispatchCompute(GLuint(cases.size()), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> hits(cases.size());
    glGetNamedBufferSubData(output.id(), 0, GLsizeiptr(hits.size() * sizeof(glm::vec4)),
                            hits.data());
    std::vector<glm::vec3> points;
    for (const glm::vec4& h : hits) points.emplace_back(h);
    return points;
  }

  gl::Texture maps_;
  gl::Buffer block_;
  gl::Program program_;
};

// A ray from o itself needs no search: every method returns the map's point in its direction,
// the same bits, and that point is the wall's within one lookup's error.
TEST_F(DistanceMapSearch, ARayFromTheReferencePointIsExactByEveryMethod) {
  std::vector<SearchCase> cases;
  std::vector<glm::vec3> directions;
  for (const glm::vec3& d : spreadDirections(200))
    if (clearOfEdges(d)) directions.push_back(d);
  ASSERT_GT(directions.size(), 100u);
  for (const glm::vec3& d : directions)
    for (int method :
         {gpu::kSearchEnvironment, gpu::kSearchParallax, gpu::kSearchLinear, gpu::kSearchSecant})
      cases.push_back({glm::vec4(0.0f), glm::vec4(d, 0.0f), glm::ivec4(method, 15, 10, 0)});
  const std::vector<glm::vec3> hits = search(cases);
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const glm::vec3 truth = boxHit(glm::vec3(0.0f), directions[k]).t * directions[k];
    for (int m = 1; m < 4; ++m) EXPECT_EQ(hits[4 * k + m], hits[4 * k]) << "method " << m;
    EXPECT_LE(glm::length(hits[4 * k] - truth), kLookupRelative * glm::length(truth))
        << "direction " << directions[k].x << ", " << directions[k].y << ", " << directions[k].z;
  }
}

// Origins x ≠ o on a grid within 0.8 of o (the walls are 1 to 3 away).
std::vector<glm::vec3> gridOrigins() {
  std::vector<glm::vec3> origins;
  for (float x : {-0.6f, 0.0f, 0.5f})
    for (float y : {-0.5f, 0.3f})
      for (float z : {-0.4f, 0.0f, 0.45f})
        if (x != 0.0f || z != 0.0f) origins.emplace_back(x, y, z);
  return origins;
}

// Eq. 6.1 assumes the surface perpendicular to the ray: for a ray perpendicular to a wall it is
// exact (within the lookup at the face's centre), wherever x is; environment mapping is off by
// x's offset across the ray, |x − (R·x)R|.
TEST_F(DistanceMapSearch, ParallaxIsExactForARayPerpendicularToAWall) {
  std::vector<SearchCase> cases;
  for (const glm::vec3& x : gridOrigins())
    for (int a = 0; a < 3; ++a)
      for (float sign : {-1.0f, 1.0f}) {
        glm::vec3 R(0.0f);
        R[a] = sign;
        for (int method : {gpu::kSearchParallax, gpu::kSearchEnvironment})
          cases.push_back({glm::vec4(x, 0.0f), glm::vec4(R, 0.0f), glm::ivec4(method, 15, 1, 0)});
      }
  const std::vector<glm::vec3> hits = search(cases);
  for (std::size_t k = 0; k < cases.size(); k += 2) {
    const glm::vec3 x(cases[k].origin), R(cases[k].direction);
    const glm::vec3 truth = x + boxHit(x, R).t * R;
    EXPECT_LE(glm::length(hits[k] - truth), kLookupRelative * glm::length(truth));
    const float offset = glm::length(x - glm::dot(R, x) * R);
    EXPECT_NEAR(glm::length(hits[k + 1] - truth), offset, kLookupRelative * glm::length(truth));
  }
}

// From x ≠ o, rays whose true hit is clear of the box's edges and not grazing: the linear search
// alone errs by up to a step; secant steps converge to the analytic hit, the mean error never
// growing with the steps, and after 8 steps (the book's 15 linear steps) every hit lies within
// what the stopping rule and the lookup allow, (10⁻⁴ + lookup)·|r| radially, that times
// (r̂·n)/|R·n| along the ray. 4 linear steps reach only d = 7|x| along the ray: a ray they do not
// bracket falls back to environment mapping (its error stays), so there only the mean's fall is
// held.
TEST_F(DistanceMapSearch, SecantStepsConvergeToTheWallsHit) {
  struct Ray {
    glm::vec3 x, R;
    glm::vec3 truth;
    double tolerance;
  };
  std::vector<Ray> rays;
  const std::vector<glm::vec3> origins = gridOrigins();
  const std::vector<glm::vec3> directions = spreadDirections(120);
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const glm::vec3 x = origins[k % origins.size()], R = directions[k];
    const BoxHit hit = boxHit(x, R);
    const glm::vec3 truth = x + hit.t * R;
    if (!clearOfEdges(truth) || std::abs(R[hit.axis]) < 0.3f) continue;
    const glm::vec3 radial = glm::normalize(truth);
    const double tolerance = (kSecantStop + kLookupRelative) * glm::length(truth) *
                             std::abs(radial[hit.axis]) / std::abs(R[hit.axis]);
    rays.push_back({x, R, truth, tolerance});
  }
  ASSERT_GT(rays.size(), 40u);
  const std::vector<int> secant_steps = {0, 1, 2, 4, 8};
  std::vector<SearchCase> cases;
  for (int linear_steps : {4, 15})
    for (int steps : secant_steps)
      for (const Ray& ray : rays)
        cases.push_back({glm::vec4(ray.x, 0.0f), glm::vec4(ray.R, 0.0f),
                         glm::ivec4(gpu::kSearchSecant, linear_steps, steps, 0)});
  const std::vector<glm::vec3> hits = search(cases);
  std::size_t k = 0;
  for (int linear_steps : {4, 15}) {
    double previous = 1e30;
    for (int steps : secant_steps) {
      double sum = 0;
      for (const Ray& ray : rays) {
        const double error = glm::length(hits[k++] - ray.truth);
        sum += error;
        if (steps == 8 && linear_steps == 15) {
          EXPECT_LE(error, ray.tolerance) << linear_steps << "/" << steps;
        }
      }
      const double mean = sum / double(rays.size());
      std::printf("linear %d, secant %d: mean error %.3g over %zu rays\n", linear_steps, steps,
                  mean, rays.size());
      // Float rounding of the same converged hits may move the mean by a few ulps.
      EXPECT_LE(mean, previous * (1.0 + 1e-5)) << linear_steps << "/" << steps;
      if (steps == 0) {
        EXPECT_GT(mean, 1e-2) << "the linear search alone stops a step off";
      }
      previous = mean;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The closed forms on the CPU: the shared functions the shaders run.

// A CPU replica of the march and secant loop of distance_map.glsl over an exact distance
// function `distance(direction)` (the map without sampling): the errors |d − d_true| of the
// linear search's overshooting sample and of each secant step.
template <typename Distance>
std::optional<std::vector<double>> secantErrors(const glm::dvec3& x, const glm::dvec3& R,
                                                int linear_steps, int secant_steps, double truth,
                                                Distance distance) {
  bool under = false, over = false;
  double d_l = 0, d_p = 0, l_ratio = 0, p_ratio = 0;
  for (int i = 0; i < linear_steps && !(under && over); ++i) {
    const double d =
        gpu::linearSearchParameter(float(glm::length(x)), (float(i) + 0.5f) / float(linear_steps));
    const glm::dvec3 r = x + R * d;
    const double ratio = glm::length(r) / distance(r);
    if (ratio < 1.0) {
      d_l = d, l_ratio = ratio, under = true;
    } else {
      d_p = d, p_ratio = ratio, over = true;
    }
  }
  if (!(under && over)) return std::nullopt;
  std::vector<double> errors = {std::abs(d_p - truth)};
  for (int i = 0; i < secant_steps; ++i) {
    const double d = gpu::secantParameter(float(d_l), float(d_p), float(l_ratio), float(p_ratio));
    errors.push_back(std::abs(d - truth));
    const glm::dvec3 r = x + R * d;
    const double ratio = glm::length(r) / distance(r);
    if (ratio < 1.0 - kSecantStop) {
      d_l = d, l_ratio = ratio;
    } else if (ratio > 1.0 + kSecantStop) {
      d_p = d, p_ratio = ratio;
    } else {
      break;
    }
  }
  return errors;
}

// The distance from o (the origin) along direction d to the sphere |p − c| = ρ round it, and
// from x along unit R.
double sphereExit(const glm::dvec3& x, const glm::dvec3& R, const glm::dvec3& c, double rho) {
  const glm::dvec3 oc = x - c;
  const double b = glm::dot(oc, R), cc = glm::dot(oc, oc) - rho * rho;
  return -b + std::sqrt(b * b - cc);
}

// Eq. 6.2 as corrected (|l|/|l′|, |p|/|p′|) puts its point on the line through l′ and p′: on a
// plane that line is the plane's trace in the plane of o, x and R, so one step from any bracket
// is the exact hit (the printed |l′|/|l′| and |p′|/|p′| would give 0/0). Float arithmetic: the
// shared function takes floats, 10⁻⁵ relative.
TEST(DistanceMapSecant, OneStepIsExactOnAPlane) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 1.0, -0.2));
  const double offset = 2.5;  // the plane n·p = 2.5, o = 0 in front of it
  // A direction that never meets the plane sees the sky, infinitely far.
  auto distance = [&](const glm::dvec3& r) {
    const double cos_n = glm::dot(n, glm::normalize(r));
    return cos_n > 0 ? offset / cos_n : 1e30;
  };
  int brackets = 0;
  for (const glm::dvec3& x : {glm::dvec3(0.4, -0.3, 0.2), glm::dvec3(-0.7, 0.5, 0.6)})
    for (const glm::dvec3& direction :
         {glm::dvec3(0.1, 1.0, 0.3), glm::dvec3(-0.5, 0.8, -0.4), glm::dvec3(0.9, 0.6, 0.1)}) {
      const glm::dvec3 R = glm::normalize(direction);
      const double truth = (offset - glm::dot(n, x)) / glm::dot(n, R);
      for (int linear_steps : {4, 15, 80}) {
        const auto errors = secantErrors(x, R, linear_steps, 1, truth, distance);
        if (!errors) continue;  // not bracketed within the steps' reach
        ++brackets;
        EXPECT_LE(errors->back(), 1e-5 * truth) << linear_steps;
      }
    }
  EXPECT_GE(brackets, 12);
}

// On a curved surface (the inside of a sphere not centred at o) the secant steps close in on the
// hit monotonically: each step's error is at most the previous step's (regula falsi on a convex
// ratio keeps one end of the bracket and moves the other towards the root), and ten steps reach
// the stopping rule's 10⁻⁴. The first secant point may lie farther than the linear search's
// overshooting sample, which is only one end of the bracket, so the chain starts at the first
// step. Float rounding of the shared functions: 10⁻⁶ of the distance.
TEST(DistanceMapSecant, StepsConvergeMonotonicallyOnACurvedSurface) {
  const glm::dvec3 c(0.4, -0.3, 0.2);
  const double rho = 3.0;
  auto distance = [&](const glm::dvec3& r) {
    return sphereExit(glm::dvec3(0.0), glm::normalize(r), c, rho);
  };
  int chains = 0;
  const std::vector<glm::vec3> directions = spreadDirections(200);
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const glm::dvec3 x = 0.9 * glm::dvec3(directions[(k * 7 + 3) % directions.size()]);
    const glm::dvec3 R(directions[k]);
    const double truth = sphereExit(x, R, c, rho);
    for (int linear_steps : {1, 2, 4, 15}) {
      const auto errors = secantErrors(x, R, linear_steps, 10, truth, distance);
      if (!errors || errors->size() < 3) continue;
      ++chains;
      for (std::size_t i = 2; i < errors->size(); ++i)
        EXPECT_LE((*errors)[i], (*errors)[i - 1] + 1e-6 * truth)
            << "ray " << k << ", " << linear_steps << " linear steps, secant step " << i;
      EXPECT_LE(errors->back(), 2.0 * kSecantStop * rho) << "ray " << k;
    }
  }
  EXPECT_GT(chains, 200);
}

// ---------------------------------------------------------------------------------------------
// Fresnel: eq. 1.6's approximation (the book's shaders, fresnel=schlick) against eq. 1.5
// (fresnel=exact, the reference's). The expected values are computed independently, with complex
// arithmetic (r_s = (cos θ − ñ cos θ_t)/(cos θ + ñ cos θ_t), ñ cos θ_t = √(ñ² − sin²θ)), to six
// digits: held to 10⁻⁵.
TEST(DistanceMapSpecularFresnel, TheApproximationDeviatesAsKnownAwayFromNormalIncidence) {
  constexpr double kDigits = 1e-5;
  const auto at = [](double degrees) { return float(std::cos(degrees * 3.14159265358979 / 180)); };
  // Glass n = 1.5: F⊥ = 0.04 at normal incidence, both; at 60° the approximation is 21% low
  // (0.0700 against 0.0892), at 80° 6% high (0.4099 against 0.3877).
  const float eta = 1.5f;
  const float f0 = scene::fresnelDielectric(1.0f, eta);
  EXPECT_NEAR(f0, 0.04, kDigits);
  EXPECT_NEAR(scene::fresnelApproximation(glm::vec3(f0), 1.0f).x, f0, 1e-7);
  EXPECT_NEAR(scene::fresnelDielectric(at(60), eta), 0.089187, kDigits);
  EXPECT_NEAR(scene::fresnelApproximation(glm::vec3(f0), at(60)).x, 0.070000, kDigits);
  EXPECT_NEAR(scene::fresnelDielectric(at(80), eta), 0.387704, kDigits);
  EXPECT_NEAR(scene::fresnelApproximation(glm::vec3(f0), at(80)).x, 0.409910, kDigits);
  // Aluminium (red channel, n = 1.6235, κ = 7.7998): F⊥ = 0.9041; the exact reflectance dips
  // towards grazing (0.8865 at 60°, 0.8270 at 80°), which the approximation, rising from F⊥ to
  // 1, cannot: 0.9071 and 0.9411, 14% high at 80°.
  const scene::Metal& aluminium = *scene::findMetal("aluminium");
  const glm::vec3 n = aluminium.n, k = aluminium.k;
  ASSERT_NEAR(n.x, 1.6235, 1e-6);
  ASSERT_NEAR(k.x, 7.7998, 1e-6);
  const glm::vec3 metal_f0 = scene::fresnelAtNormalIncidence(n, k);
  EXPECT_NEAR(metal_f0.x, 0.904105, kDigits);
  EXPECT_NEAR(scene::fresnelConductor(1.0f, n, k).x, metal_f0.x, kDigits);
  EXPECT_NEAR(scene::fresnelConductor(at(60), n, k).x, 0.886478, kDigits);
  EXPECT_NEAR(scene::fresnelApproximation(metal_f0, at(60)).x, 0.907101, kDigits);
  EXPECT_NEAR(scene::fresnelConductor(at(80), n, k).x, 0.827006, kDigits);
  EXPECT_NEAR(scene::fresnelApproximation(metal_f0, at(80)).x, 0.941055, kDigits);
}

// ---------------------------------------------------------------------------------------------
// The technique on the Cornell box.

constexpr int kSize = 48;
// The maps at 64² a face keep a frame to about a second on llvmpipe; the mirror sphere's
// reflection spans fewer texels than that of the box at this image size.
const std::vector<std::string> kSmallMaps = {"map_resolution=64", "light_samples=8"};

std::vector<std::string> settings(std::vector<std::string> extra) {
  std::vector<std::string> all = kSmallMaps;
  all.insert(all.end(), extra.begin(), extra.end());
  return all;
}

// The pixels whose camera ray (through the pixel centre) meets a mesh of material `type`, as do
// its four neighbours' (clear of the silhouette, where a pixel mixes the sphere and the box).
std::vector<int> pixelsOf(const scene::Scene& scene, int size, scene::MaterialType type) {
  const std::unique_ptr<scene::RayCaster> caster = ref::embreeRayCasterFactory()(scene);
  const scene::CameraFrame frame = scene::makeCameraFrame(scene.camera, size, size);
  std::vector<char> of_type(std::size_t(size) * size, 0);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::vec3 d =
          scene::cameraRayDirection(frame, size, size, float(x) + 0.5f, float(y) + 0.5f);
      const scene::RayHit hit = caster->intersect(scene.camera.position, d, 0.0f);
      of_type[std::size_t(y) * size + x] =
          hit.valid() && scene.materials[scene.meshes[hit.mesh].material].type == type;
    }
  std::vector<int> pixels;
  for (int y = 1; y + 1 < size; ++y)
    for (int x = 1; x + 1 < size; ++x) {
      const std::size_t i = std::size_t(y) * size + x;
      if (of_type[i] && of_type[i - 1] && of_type[i + 1] && of_type[i - size] && of_type[i + size])
        pixels.push_back(y * size + x);
    }
  return pixels;
}

double channelMean(const image::Image& image, int pixel, int size) {
  const float* rgb = image.pixel(pixel % size, pixel / size);
  return (double(rgb[0]) + rgb[1] + rgb[2]) / 3.0;
}

// A correct technique misses this file's one comparison with the reference's mean with
// probability 1%.
constexpr test::TestFamily kFamily(0.01, 1);
// Radiance above the Cornell box's walls' (under 0.5) and below its light's: the light's
// reflection.
constexpr double kLightReflection = 1.0;

// The mirror sphere's pixels against the reference of the class L D? S{0,2} E (for a lone convex
// mirror the paths of L D? S{0,1} E) through the pixel
// centres, fresnel=exact (the reference's). With the secant search the mirror's mean is the
// reference's by a t test on its standard error, allowing 5% for the shared direct light (8 light
// samples and shadow maps; `direct`'s Cornell MAPE is 1.4% at 16) and for the 64² maps; and the
// mirror's relMSE falls from environment mapping (the reflection taken from o, the sphere's
// centre, 100 mm from its surface) to parallax to the secant search. The light's reflection is
// left out (a pixel above 1 in either image; the walls' light is under 0.5): its radiance is
// hundreds of times the walls', and whether a pixel centre's ray meets the light's edge, or a 64²
// map's bilinear lookup blends a texel of it in, is a matter of a fraction of a texel.
TEST(DistanceMapSpecularTechnique, TheMirrorMatchesTheReferenceOfItsClassBetterWithABetterSearch) {
  const scene::Scene scene = scene::loadScene("cornell", {"spheres=mirror"});
  const scene::PathClass path_class = scene::PathClass::ofExpression(
      scene::PathExpression::parse(distanceMapSpecularPathExpression(1)).text());
  const ref::RenderResult reference =
      test::renderCentreClassReference(scene, kSize, 64, path_class);
  const std::vector<int> pixels = pixelsOf(scene, kSize, scene::MaterialType::kMirror);
  ASSERT_GT(pixels.size(), 60u);

  std::vector<double> rel_mse;
  for (const char* method : {"environment", "parallax", "secant"}) {
    const TechniqueRunResult r =
        test::renderOneFrame(scene, "distance_map_specular",
                             settings({std::string("search=") + method, "fresnel=exact",
                                       "linear_steps=15", "secant_steps=4"}),
                             kSize);
    EXPECT_EQ(r.path_class, path_class);
    double ours = 0, truth = 0, variance = 0, variance_squared = 0, squared = 0;
    int light = 0;
    for (int p : pixels) {
      const double t = channelMean(r.image, p, kSize), m = channelMean(reference.mean, p, kSize);
      const double v = channelMean(reference.variance, p, kSize);
      if (std::max(t, m) > kLightReflection) {
        ++light;
        continue;
      }
      ours += t;
      truth += m;
      variance += v;
      variance_squared += v * v;
      squared += ((t - m) * (t - m) - v) / (m * m + metrics::kRelativeEpsilon);
    }
    EXPECT_LE(light, 3) << method;
    const double n = double(pixels.size() - std::size_t(light));
    rel_mse.push_back(squared / n);
    std::printf(
        "%s: %.0f mirror pixels (%d of the light left out), mean %.5f against %.5f "
        "(%+.2f%%), relMSE %.5f\n",
        method, n, light, ours / n, truth / n, 100.0 * (ours / truth - 1.0), squared / n);
    if (std::string(method) == "secant") {
      const double standard_error = std::sqrt(variance) / n;
      const double dof = variance * variance / (variance_squared / reference.variance_dof);
      EXPECT_TRUE(kFamily.tTest(ours / n, truth / n, standard_error, dof, 0.05 * truth / n));
    }
    EXPECT_EQ(image::countNonFinite(r.image), 0u);
  }
  // Measured 2026-11-28 (llvmpipe): 0.065, 0.0025 and 0.00042.
  EXPECT_LT(rel_mse[2], 0.005) << "the secant search";
  EXPECT_GT(rel_mse[0], 2.0 * rel_mse[2]) << "environment mapping against the secant search";
  EXPECT_GT(rel_mse[1], rel_mse[2]) << "parallax against the secant search";
}

// search_error (Embree's first hit on each traced ray against the search's) falls from
// environment mapping to parallax to the secant search, on the same maps (measured 2026-11-28 at
// 32², 64² maps: 86, 39, 49 (linear) and 1.0 mm).
TEST(DistanceMapSpecularTechnique, TheSearchErrorFallsWithABetterSearch) {
  const scene::Scene scene = scene::loadScene("cornell", {"spheres=mirror"});
  std::vector<double> means;
  for (const char* method : {"environment", "parallax", "linear", "secant"}) {
    const TechniqueRunResult r = test::renderOneFrame(
        scene, "distance_map_specular", settings({std::string("search=") + method}), 32);
    means.push_back(test::statisticNamed(r.statistics, "search_error_mean"));
    std::printf("%s: search_error_mean %.3f mm, max %.3f mm\n", method, means.back(),
                test::statisticNamed(r.statistics, "search_error_max"));
    const auto aux = std::find_if(r.auxiliary.begin(), r.auxiliary.end(),
                                  [](const AuxiliaryImage& a) { return a.name == "search_error"; });
    ASSERT_NE(aux, r.auxiliary.end());
  }
  EXPECT_GT(means[0], 2.0 * means[1]) << "environment against parallax";
  EXPECT_GT(means[1], 2.0 * means[3]) << "parallax against secant";
  EXPECT_GE(means[2], means[3]) << "linear against secant";
}

// rounds=2: the mirror's map shows the glass sphere as the glass's map does (its reflection and
// refraction), where the first round left it black; the class grows to L D? S{0,4} E, the
// mirror's pixels where it sees the glass grow brighter (8 of 140 at 64², 2026-11-28), none
// darker (a bounce only adds light), and the pixels off the spheres stay as they were. (The
// glass's pixels do not see the mirror from this camera: their refracted rays go down to the
// floor.)
TEST(DistanceMapSpecularTechnique, ASecondRoundShowsTheGlassInTheMirror) {
  const int size = 64;
  const scene::Scene scene = scene::loadScene("cornell", {"spheres=mirror_glass"});
  const TechniqueRunResult one =
      test::renderOneFrame(scene, "distance_map_specular", settings({"rounds=1"}), size);
  const TechniqueRunResult two =
      test::renderOneFrame(scene, "distance_map_specular", settings({"rounds=2"}), size);
  EXPECT_EQ(one.path_class.expression, "LD?S{0,2}E");
  EXPECT_EQ(two.path_class.expression, "LD?S{0,4}E");
  const std::vector<int> mirror = pixelsOf(scene, size, scene::MaterialType::kMirror);
  int brighter = 0, darker = 0;
  for (int p : mirror) {
    const double change = channelMean(two.image, p, size) - channelMean(one.image, p, size);
    brighter += change > 1e-3;
    darker += change < -1e-6;
  }
  std::printf("%zu mirror pixels: %d brighter in the second round, %d darker\n", mirror.size(),
              brighter, darker);
  EXPECT_GE(brighter, 4);
  EXPECT_EQ(darker, 0);
  // Every pixel the spheres do not cover is the shared direct light, the same in both.
  const std::unique_ptr<scene::RayCaster> caster = ref::embreeRayCasterFactory()(scene);
  const scene::CameraFrame frame = scene::makeCameraFrame(scene.camera, size, size);
  int diffuse = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const scene::RayHit hit = caster->intersect(
          scene.camera.position,
          scene::cameraRayDirection(frame, size, size, float(x) + 0.5f, float(y) + 0.5f), 0.0f);
      if (!hit.valid() ||
          scene::isIdealSpecular(scene.materials[scene.meshes[hit.mesh].material].type))
        continue;
      const int p = y * size + x;
      if (channelMean(one.image, p, size) != channelMean(two.image, p, size)) ++diffuse;
    }
  EXPECT_EQ(diffuse, 0) << "diffuse pixels changed by a second round";
  // The region the harness measures apart (relmse_region) is the spheres' pixels: every interior
  // pixel of the mirror and of the glass, and no pixel where Embree sees a diffuse surface.
  ASSERT_TRUE(two.region.has_value());
  const std::vector<int> glass = pixelsOf(scene, size, scene::MaterialType::kGlass);
  for (const std::vector<int>* sphere : {&mirror, &glass})
    for (int p : *sphere) EXPECT_EQ(two.region->data()[std::size_t(p)], 1.0f) << "pixel " << p;
  int outside = 0;
  for (int y = 1; y + 1 < size; ++y)
    for (int x = 1; x + 1 < size; ++x) {
      const scene::RayHit hit = caster->intersect(
          scene.camera.position,
          scene::cameraRayDirection(frame, size, size, float(x) + 0.5f, float(y) + 0.5f), 0.0f);
      // Interior diffuse pixels: away from a sphere's silhouette, where rasteriser and Embree may
      // differ by a pixel.
      bool interior = hit.valid();
      for (int dy = -1; dy <= 1 && interior; ++dy)
        for (int dx = -1; dx <= 1 && interior; ++dx) {
          const scene::RayHit n =
              caster->intersect(scene.camera.position,
                                scene::cameraRayDirection(frame, size, size, float(x + dx) + 0.5f,
                                                          float(y + dy) + 0.5f),
                                0.0f);
          interior = n.valid() &&
                     !scene::isIdealSpecular(scene.materials[scene.meshes[n.mesh].material].type);
        }
      if (interior && two.region->pixel(x, y)[0] != 0.0f) ++outside;
    }
  EXPECT_EQ(outside, 0) << "diffuse pixels in the technique's region";
}

// Bad parameters are refused with their name; a scene without mirrors or glass is a missing
// need (one line from the runner, exit code 2 from gibench: tests/cli/bad_input_cases.toml).
TEST(DistanceMapSpecularTechnique, RefusesBadParametersNamingThem) {
  test::expectParametersRefused("distance_map_specular",
                                {"linear_steps=0", "secant_steps=0", "map_resolution=100",
                                 "search=bisection", "rounds=0", "reference_point=camera"});
}

TEST(DistanceMapSpecularTechnique, NeedsASceneWithMirrorsOrGlass) {
  const std::optional<std::string> why =
      missingSceneNeed(findTechnique("distance_map_specular"), scene::loadScene("cornell"));
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("mirrors or glass"), std::string::npos) << *why;
  EXPECT_FALSE(missingSceneNeed(findTechnique("distance_map_specular"),
                                scene::loadScene("cornell", {"spheres=mirror"}))
                   .has_value());
}

}  // namespace
}  // namespace gib::rt
