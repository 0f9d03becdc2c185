// The `cloud` scene: a procedural cumulus of medium particles in the spirit of the book's
// Figs. 9.21/9.22 (Szirmay-Kalos et al., §9.6: "The cloud model consists of 1024 particles ...
// The albedo is 0.9 and material parameter g is 0"), lit by two directional lights and a sky.
// By default there are no surfaces: the medium is the whole scene. `surface` places one where the
// cloud meets it (a ground plane through its base, or a slab through its middle), for the book's
// Fig. 9.8, where billboards clip against objects inside a medium.
//
// Shape: 5–9 ellipsoidal lobes (a large core, a crown on top of it and a ring of smaller lobes on
// a base disk) cut off below by a flat base, filled with particles that are large and dense in
// the lobes' cores and small and thin at their fringes. Units are metres; the cloud is about
// 10 m across, centred on the y axis with its base near y = 0.
//
// Everything is derived from (seed, particle index, dimension) through a counter-based hash, so a
// particle does not depend on the order in which the others are made nor on the particle count.
// The arithmetic is done in double and rounded to float once: a last-bit difference in a
// library's cos, sin or cbrt (the only functions used that IEEE does not pin down) survives that
// rounding almost never, so the scene hash is the same with any standard library.
#include "common/splitmix.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib::scene {

namespace {

// The particle count of the book's cloud. Other counts discretise the same cloud: particle radii
// scale with (kBookParticles / count)^(1/3) so that the total extinction (Σ τ·πr³/3) and hence
// the optical depths stay about the same.
constexpr int kBookParticles = 1024;

// Particle centres lie at or above this height: the flat base of a cumulus (its condensation
// level). Densities reach one particle radius below it.
constexpr double kBaseHeight = 0.4;

// Particle radius at a lobe's centre for kBookParticles particles, in metres; it shrinks to half
// at the lobe's fringe. Chosen so that neighbouring particles overlap (mean spacing is ~0.6 m).
constexpr double kCoreRadius = 0.9;
// Particle density τ (extinction at the particle's centre, per metre) at a lobe's centre; it
// falls to 30 % at the fringe. Chosen for an optical depth of about 8 along the view axis and the
// vertical through the core, 11 along the cloud's long axis (tests/scene/cloud_test.cpp gives
// the designed ranges).
constexpr double kCoreDensity = 0.75;

// Rejection sampling of a point in the cut lobe accepts about half of the tries; after this many
// the chance of failing is ~1e-9, and then the lobe's centre is used.
constexpr int kMaxPlacementTries = 32;

// Independent random streams of the hash.
enum class Stream : std::uint64_t { kLayout = 1, kParticle = 2 };

// A uniform number in [0, 1) for (seed, stream, index, dimension); 53 random bits.
double uniform01(std::uint64_t seed, Stream stream, std::uint64_t index, std::uint64_t dimension) {
  std::uint64_t h = splitMix64(seed);
  h = splitMix64(h ^ static_cast<std::uint64_t>(stream));
  h = splitMix64(h ^ index);
  h = splitMix64(h ^ dimension);
  return double(h >> 11) * 0x1.0p-53;
}

struct Lobe {
  glm::dvec3 centre;
  glm::dvec3 semi_axes;
};

// The lobes: a core on the axis, a crown on top of it, and ring lobes around it whose size falls
// with their distance from the axis. The ring is squeezed in depth (z), so that the cloud is
// widest seen from the camera, which looks along −z. Lobe centres and semi-axes in metres.
std::vector<Lobe> makeLobes(std::uint64_t seed) {
  auto u = [&](std::uint64_t index, std::uint64_t dimension) {
    return uniform01(seed, Stream::kLayout, index, dimension);
  };
  std::vector<Lobe> lobes;
  const double core = 2.9 * (0.95 + 0.1 * u(0, 0));
  lobes.push_back({{0.0, 2.4, 0.0}, {core, 2.6, 0.85 * core}});
  // The crown leans a little to one side, as rising towers do.
  lobes.push_back({{1.6 * (u(1, 0) - 0.5), 4.4, 1.0 * (u(1, 1) - 0.5)}, {2.0, 1.6, 1.7}});

  const int ring = 3 + static_cast<int>(5.0 * u(2, 0));  // 3..7, so 5..9 lobes in all
  const double phase = 2.0 * std::numbers::pi * u(2, 1);
  for (int j = 0; j < ring; ++j) {
    const std::uint64_t index = 3 + std::uint64_t(j);
    // Evenly spaced angles, jittered by up to ±15 % of the spacing.
    const double angle = phase + 2.0 * std::numbers::pi * (j + 0.3 * (u(index, 0) - 0.5)) / ring;
    const double distance = 2.0 + 1.2 * u(index, 1);
    const double radius = 2.2 - 0.45 * (distance - 2.0) + 0.3 * (u(index, 2) - 0.5);
    // Centres at 0.75 radius high, so the lobe's bottom reaches under the base and is cut flat
    // there; some are lifted by up to 0.8 m, so that the upper outline billows.
    lobes.push_back({{distance * std::cos(angle), 0.75 * radius + 0.8 * u(index, 3),
                      0.7 * distance * std::sin(angle)},
                     {radius, 0.85 * radius, 0.85 * radius}});
  }
  return lobes;
}

// Picks particle `index`'s lobe with probability proportional to the lobe's volume, so that the
// number of particles per volume is about the same everywhere and overlapping lobes (the middle
// of the cloud) are the densest.
const Lobe& pickLobe(const std::vector<Lobe>& lobes, std::uint64_t seed, std::uint64_t index) {
  double total = 0.0;
  for (const Lobe& lobe : lobes) total += lobe.semi_axes.x * lobe.semi_axes.y * lobe.semi_axes.z;
  double target = total * uniform01(seed, Stream::kParticle, index, 0);
  for (const Lobe& lobe : lobes) {
    target -= lobe.semi_axes.x * lobe.semi_axes.y * lobe.semi_axes.z;
    if (target < 0.0) return lobe;
  }
  return lobes.back();
}

// Particle `index`: a point uniformly distributed in its lobe above the base, with a radius and
// density that fall from the lobe's centre to its fringe.
MediumParticle makeParticle(const std::vector<Lobe>& lobes, std::uint64_t seed, std::uint64_t index,
                            double radius_scale) {
  auto u = [&](std::uint64_t dimension) {
    return uniform01(seed, Stream::kParticle, index, dimension);
  };
  const Lobe& lobe = pickLobe(lobes, seed, index);

  // Rejection-sample the unit ball (no trigonometry, so no library-dependent rounding).
  glm::dvec3 offset(0.0);  // in units of the lobe's semi-axes
  for (int attempt = 0; attempt < kMaxPlacementTries; ++attempt) {
    const std::uint64_t d = 1 + 3 * std::uint64_t(attempt);
    const glm::dvec3 q(2.0 * u(d) - 1.0, 2.0 * u(d + 1) - 1.0, 2.0 * u(d + 2) - 1.0);
    if (glm::dot(q, q) <= 1.0 && lobe.centre.y + q.y * lobe.semi_axes.y >= kBaseHeight) {
      offset = q;
      break;
    }
  }
  const double s = std::sqrt(glm::dot(offset, offset));  // 0 at the lobe's centre, 1 at its edge

  // Step: size and density, each with ±20–25 % jitter so the fringe looks ragged.
  constexpr std::uint64_t kSizeDimension = 1 + 3 * kMaxPlacementTries;
  const double radius =
      radius_scale * kCoreRadius * (1.0 - 0.5 * s) * (0.8 + 0.4 * u(kSizeDimension));
  const double density = kCoreDensity * (1.0 - 0.7 * s * s) * (0.75 + 0.5 * u(kSizeDimension + 1));

  MediumParticle particle;
  particle.centre = glm::vec3(lobe.centre + offset * lobe.semi_axes);
  particle.radius = float(radius);
  particle.density = float(density);
  return particle;
}

// Step: the optional surface through the cloud, grey Lambert (ρ = 0.5). The ground lies 0.2 m
// above the base, so that the lowest particles reach through it; the slab (a wall 6 m wide, 3.6 m
// high and 0.3 m thick) stands across the cloud's middle facing the camera, so that the front
// half's particles meet it all over the image. Reflection is two-sided; the front side matters
// only for emission.
void addSurface(Scene& scene, std::string_view surface) {
  if (surface == "none") return;
  Material grey;
  grey.name = "grey";
  grey.diffuse = Rgb(0.5f);
  scene.materials.push_back(grey);
  Mesh mesh;
  mesh.name = std::string(surface);
  mesh.material = std::uint32_t(scene.materials.size() - 1);
  if (surface == "ground") {
    constexpr float h = float(kBaseHeight) + 0.2f, e = 40.0f;
    appendQuad(mesh, {-e, h, e}, {e, h, e}, {e, h, -e}, {-e, h, -e});
  } else {
    const glm::vec3 lo(-3.0f, 0.4f, -0.15f), hi(3.0f, 4.0f, 0.15f);
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                            {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                            {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    // Outward faces: bottom, top, back, front, left, right.
    appendQuad(mesh, c[0], c[1], c[5], c[4]);
    appendQuad(mesh, c[3], c[7], c[6], c[2]);
    appendQuad(mesh, c[0], c[3], c[2], c[1]);
    appendQuad(mesh, c[4], c[5], c[6], c[7]);
    appendQuad(mesh, c[0], c[4], c[7], c[3]);
    appendQuad(mesh, c[1], c[2], c[6], c[5]);
  }
  scene.meshes.push_back(std::move(mesh));
}

}  // namespace

ParameterTable cloudParameters() {
  return {
      numericParameter(
          "particles", ParameterType::kInteger, "1024", 16, 16384, "",
          "number of medium particles; radii scale so that the cloud's optical depth stays "
          "about the same (the book's cloud has 1024)"),
      numericParameter("seed", ParameterType::kInteger, "1", 0, 2147483647, "",
                       "seed of the lobe layout and of the particle placement"),
      numericParameter("albedo", ParameterType::kNumber, "0.9", 0, 1, "",
                       "single-scattering albedo σs/σt of the medium, the same in R, G and B"),
      numericParameter("g", ParameterType::kNumber, "0", -0.95, 0.95, "",
                       "Henyey–Greenstein asymmetry of the phase function (0: isotropic)"),
      numericParameter("lights", ParameterType::kInteger, "2", 1, 4, "",
                       "directional lights: the key, the fill (the default two), light from "
                       "above, a front light"),
      booleanParameter("sky", true, "the blue sky around the cloud"),
      choiceParameter("surface", "none", {"none", "ground", "slab"},
                      "a grey surface the cloud meets: none, a ground plane through its base, or "
                      "a wall through its middle (the book's Fig. 9.8)"),
  };
}

Scene makeCloud(const ParameterValues& parameters) {
  Scene scene;
  scene.name = "cloud";
  scene.provenance =
      "procedural cumulus of particles after Szirmay-Kalos et al. Figs. 9.21/9.22 (1024 "
      "particles, albedo 0.9, g = 0)";

  // Step: the medium.
  const int count = parameters.integer("particles");
  const auto seed = static_cast<std::uint64_t>(parameters.integer("seed"));
  const std::vector<Lobe> lobes = makeLobes(seed);
  const double radius_scale = std::cbrt(double(kBookParticles) / double(count));
  scene.medium.particles.reserve(std::size_t(count));
  for (int i = 0; i < count; ++i)
    scene.medium.particles.push_back(makeParticle(lobes, seed, std::uint64_t(i), radius_scale));
  scene.medium.albedo = Rgb(float(parameters.number("albedo")));
  scene.medium.g = float(parameters.number("g"));

  // Step: lights. A warm sun high on the left and a little in front (key: the camera sees the
  // lit side and the shadowed side), a cooler, weaker, low light from the back right (fill,
  // standing in for light from other clouds), and a blue sky. Irradiance in W/m².
  DirectionalLight key;
  key.direction = glm::normalize(glm::vec3(0.75f, -0.6f, -0.25f));
  key.irradiance = {2.6f, 2.35f, 1.95f};
  DirectionalLight fill;
  fill.direction = glm::normalize(glm::vec3(-0.7f, -0.2f, 0.6f));
  fill.irradiance = {0.45f, 0.55f, 0.75f};
  // Two more for the book's claim that the network's frame time hardly depends on the number of
  // lights (`lights` = 3, 4): light from above (a brighter layer of haze) and a weak front light.
  DirectionalLight above;
  above.direction = glm::normalize(glm::vec3(-0.2f, -0.9f, -0.4f));
  above.irradiance = {0.5f, 0.5f, 0.55f};
  DirectionalLight front;
  front.direction = glm::normalize(glm::vec3(-0.3f, -0.4f, -0.85f));
  front.irradiance = {0.35f, 0.33f, 0.3f};
  const std::vector<DirectionalLight> lights = {key, fill, above, front};
  scene.directional_lights.assign(lights.begin(), lights.begin() + parameters.integer("lights"));
  if (parameters.boolean("sky")) scene.sky_radiance = {0.12f, 0.17f, 0.28f};
  addSurface(scene, parameters.text("surface"));

  // Step: camera. From the side, a little below the cloud's middle and looking slightly up, with
  // the whole cloud and some sky around it in view.
  scene.camera.position = {0.0f, 1.5f, 14.5f};
  scene.camera.look_at = {0.0f, 2.6f, 0.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vertical_fov_deg = 40.0f;
  scene.default_width = 512;
  scene.default_height = 384;
  return scene;
}

}  // namespace gib::scene
