// `chamber --scene-set sky=true` (book Fig. 4.15): roof lights in the vault open the hall to the
// Preetham sky, and only a small fraction of the sky is visible from the floor. Visibility is
// tested with a brute-force ray-triangle test in double precision over the scene's own triangles
// (two-sided, edges inclusive, so that a ray through a shared edge cannot slip between two
// triangles and pass for a leak).
#include "common/parameters.h"
#include "scene/builtin_scenes.h"
#include "scene/preetham_sky.h"
#include "scene/sky_parameters.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace gib::scene {
namespace {

// The roof lights (chamber.cpp): the vault's two crown segments across, |x| < 2.2·sin(11.25°)
// = 0.43 m, and the metre rows z ∈ [1, 2], [4, 5], [7, 8], [10, 11].
constexpr double kRoofLightHalfWidth = 0.43;
constexpr double kRoofLightRows[] = {1.0, 4.0, 7.0, 10.0};
constexpr double kVaultAxisY = 5.0, kVaultRadius = 2.2;

ParameterValues chamberValues(const std::vector<std::string>& assignments = {}) {
  return parseParameters(chamberParameters(), assignments, "scene 'chamber'");
}

// Whether the ray from `origin` along `direction` hits any triangle of the scene.
bool hitsAnything(const Scene& scene, glm::dvec3 origin, glm::dvec3 direction) {
  constexpr double kEdgeSlack = 1e-9;  // inclusive edges: no ray slips between two triangles
  for (const Mesh& mesh : scene.meshes)
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
      const glm::dvec3 e1 = b - a, e2 = c - a;
      const glm::dvec3 pv = glm::cross(direction, e2);
      const double det = glm::dot(e1, pv);
      if (std::abs(det) < 1e-14) continue;
      const glm::dvec3 tv = origin - a;
      const double u = glm::dot(tv, pv) / det;
      if (u < -kEdgeSlack || u > 1 + kEdgeSlack) continue;
      const glm::dvec3 qv = glm::cross(tv, e1);
      const double v = glm::dot(direction, qv) / det;
      if (v < -kEdgeSlack || u + v > 1 + kEdgeSlack) continue;
      if (glm::dot(e2, qv) / det > 1e-6) return true;
    }
  return false;
}

bool underRoofLight(double x, double z, double slack = 0) {
  if (std::abs(x) >= kRoofLightHalfWidth + slack) return false;
  for (double row : kRoofLightRows)
    if (z > row - slack && z < row + 1 + slack) return true;
  return false;
}

struct SkyView {
  double solid_angle_fraction = 0;  // of the upper hemisphere's 2π
  double cosine_fraction = 0;       // of the floor's irradiance from a uniform sky
  int escaping = 0, leaks = 0;      // escaping rays; those that do not leave by a roof light
};

// The upper hemisphere above a floor point in n × n strata (cos θ and φ uniform, one ray at each
// stratum's centre: deterministic, and equal-solid-angle strata).
SkyView skyView(const Scene& scene, glm::dvec3 floor_point, int n) {
  SkyView view;
  double cosine_sum = 0, cosine_total = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double cos_theta = (i + 0.5) / n, sin_theta = std::sqrt(1 - cos_theta * cos_theta);
      const double phi = 2 * std::numbers::pi * (j + 0.5) / n;
      const glm::dvec3 d(sin_theta * std::cos(phi), cos_theta, sin_theta * std::sin(phi));
      cosine_total += cos_theta;
      if (hitsAnything(scene, floor_point, d)) continue;
      ++view.escaping;
      cosine_sum += cos_theta;
      // Where the ray reaches the roof lights' sills (y = 5 + 2.2·sin 78.75°, their lowest
      // edges): inside a light's outline there, up to the chord's slant (a ray that passes the
      // sill's height elsewhere has gone through the vault), else it left by a gap.
      const double t =
          (kVaultAxisY + kVaultRadius * std::sin(78.75 * std::numbers::pi / 180) - floor_point.y) /
          d.y;
      const glm::dvec3 p = floor_point + t * d;
      if (!underRoofLight(p.x, p.z, 0.01)) ++view.leaks;
    }
  view.solid_angle_fraction = double(view.escaping) / (n * n);
  view.cosine_fraction = cosine_sum / cosine_total;
  return view;
}

TEST(ChamberSky, WithoutTheSkyTheChamberIsTheDefaultOne) {
  // sky=false is the chamber every stored reference was rendered from: the same triangles, light
  // and camera, hence the same hash, at every detail and with the specular objects.
  for (const std::vector<std::string>& base :
       {std::vector<std::string>{}, {"detail=2"}, {"specular=objects", "light_intensity=300"}}) {
    std::vector<std::string> with_sky = base;
    with_sky.push_back("sky=false");
    const Scene plain = makeChamber(chamberValues(base));
    const Scene explicit_false = makeChamber(chamberValues(with_sky));
    EXPECT_EQ(hashScene(plain), hashScene(explicit_false));
    EXPECT_EQ(plain.triangleCount(), explicit_false.triangleCount());
    EXPECT_TRUE(explicit_false.environment.empty());
    EXPECT_EQ(explicit_false.spot_lights.size(), 1u);
  }
}

TEST(ChamberSky, HasTheSkyRoofLightsAndNoSpotByDefault) {
  const Scene plain = makeChamber(chamberValues());
  const Scene sky = makeChamber(chamberValues({"sky=true"}));
  ASSERT_FALSE(sky.environment.empty());
  EXPECT_NO_THROW(validateScene(sky));
  EXPECT_TRUE(sky.spot_lights.empty());
  EXPECT_EQ(makeChamber(chamberValues({"sky=true", "spot_light=on"})).spot_lights.size(), 1u);
  EXPECT_TRUE(makeChamber(chamberValues({"spot_light=off"})).spot_lights.empty());
  // Four roof lights of two vault cells, two triangles each, at detail 1 (d² times that at d).
  EXPECT_EQ(plain.triangleCount() - sky.triangleCount(), 4u * 2 * 2);
  const Scene sky2 = makeChamber(chamberValues({"sky=true", "detail=2"}));
  EXPECT_EQ(makeChamber(chamberValues({"detail=2"})).triangleCount() - sky2.triangleCount(),
            4u * 2 * 2 * 4);
  // The sky is outdoor's, built from the same parameters.
  const ParameterValues values = chamberValues({"sky=true"});
  EXPECT_EQ(sky.environment.intensity, kSkyScale);
  EXPECT_EQ(hashScene(sky), hashScene(makeChamber(values)));
  EXPECT_NE(hashScene(sky),
            hashScene(makeChamber(chamberValues({"sky=true", "sun_elevation=50"}))));
}

TEST(ChamberSky, RaysStraightUpEscapeOnlyThroughTheRoofLights) {
  const Scene sky = makeChamber(chamberValues({"sky=true"}));
  const Scene closed = makeChamber(chamberValues());
  int escaped = 0, checked = 0;
  // Floor points along the nave's middle every 0.25 m (avoiding the rows' edges), and across.
  for (double x : {-0.3, 0.0, 0.3, -1.0, 1.0})
    for (double z = 0.125; z < 12.0; z += 0.25) {
      const glm::dvec3 p(x, 0.01, z);
      const bool escapes = !hitsAnything(sky, p, {0, 1, 0});
      EXPECT_EQ(escapes, underRoofLight(x, z)) << "x " << x << " z " << z;
      EXPECT_TRUE(hitsAnything(closed, p, {0, 1, 0})) << "x " << x << " z " << z;
      escaped += escapes;
      ++checked;
    }
  EXPECT_EQ(escaped, 3 * 4 * 4);  // three columns under the lights, four points in each row
  EXPECT_EQ(checked, 5 * 48);
}

TEST(ChamberSky, TheFloorSeesASmallFractionOfTheSky) {
  // Fig. 4.15's "only a small fraction of the environment is visible": from the floor under the
  // middle of a roof light (z = 4.5) and between two (z = 6, the middle of the nave), 128² strata
  // of the hemisphere. Estimate: a light of 0.86 × 1 m seen from 7.15 m straight below subtends
  // A/h² = 0.017 sr, one 1.5 m to the side 0.016 sr, 3 m 0.013, 4.5 m 0.010, 6 m 0.007: about
  // 0.05 sr from either point, 0.8 % of 2π, and with cos θ ≈ 0.9 about 1.4 % of the cosine-
  // weighted hemisphere (the floor's irradiance under a uniform sky). Measured (the strata blur
  // the lights' edges): 0.60 % / 1.08 % (cosine) under a light, 0.93 % / 1.73 % between two.
  const Scene sky = makeChamber(chamberValues({"sky=true"}));
  const Scene closed = makeChamber(chamberValues());
  for (double z : {4.5, 6.0}) {
    const SkyView view = skyView(sky, {0.0, 0.01, z}, 128);
    EXPECT_GT(view.escaping, 0) << "z " << z;
    EXPECT_EQ(view.leaks, 0) << "z " << z << ": rays leave the hall elsewhere than by a light";
    EXPECT_LT(view.solid_angle_fraction, 0.015) << "z " << z;
    EXPECT_LT(view.cosine_fraction, 0.025) << "z " << z;
    std::printf("floor at z = %.1f sees %.3f %% of the hemisphere, %.3f %% cosine-weighted\n", z,
                100 * view.solid_angle_fraction, 100 * view.cosine_fraction);
    // Without the sky the shell is closed: nothing escapes.
    EXPECT_EQ(skyView(closed, {0.0, 0.01, z}, 16).escaping, 0) << "z " << z;
  }
}

}  // namespace
}  // namespace gib::scene

namespace gib::scene {
namespace {

// `sun=none` (both scenes' sky parameters) leaves out exactly the sun's disc: the map loses the
// disc's power, ∫L dω drops by L_sun·Ω_sun, and nothing else changes; the default keeps the disc
// and the hash.
TEST(SkyParameters, SunNoneLeavesOutTheDiscAlone) {
  const ParameterValues with = parseParameters(outdoorParameters(), {}, "scene 'outdoor'");
  const ParameterValues without =
      parseParameters(outdoorParameters(), {"sun=none"}, "scene 'outdoor'");
  EXPECT_EQ(hashScene(makeOutdoor(with)),
            hashScene(makeOutdoor(parseParameters(outdoorParameters(), {"sun=disc"}, ""))));
  const EnvironmentMap disc = makeSkyEnvironment(with, "outdoor");
  const EnvironmentMap none = makeSkyEnvironment(without, "outdoor");
  SkyParameters sky;
  sky.sun_elevation_deg = float(with.number("sun_elevation"));
  sky.turbidity = float(with.number("turbidity"));
  const double sun_power =
      double(luminance(sunRadiance(
          sky.turbidity, std::numbers::pi / 2 - sky.sun_elevation_deg * std::numbers::pi / 180))) *
      2 * std::numbers::pi * (1 - std::cos(kSunAngularRadiusDeg * std::numbers::pi / 180)) *
      double(kSkyScale);
  const double drop =
      double(luminance(environmentIntegral(disc))) - double(luminance(environmentIntegral(none)));
  EXPECT_NEAR(drop, sun_power, 1e-4 * sun_power);
  int differing = 0;
  for (int y = 0; y < disc.height; ++y)
    for (int x = 0; x < disc.width; ++x) differing += disc.texel(x, y) != none.texel(x, y);
  EXPECT_EQ(differing, 1);
  EXPECT_NE(hashScene(makeOutdoor(with)), hashScene(makeOutdoor(without)));
}

}  // namespace
}  // namespace gib::scene
