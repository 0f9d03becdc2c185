// The scene model shared by the reference path tracer and every real-time technique
// (docs/architecture.md, "Conventions"). Units: lengths in scene units (the Cornell box uses mm),
// radiance in linear Rec.709 RGB (W/(sr·m²) per channel, scene-linear), spot intensity in W/sr,
// directional irradiance in W/m² on a plane perpendicular to the light.
#pragma once

#include "common/luminance_shared.h"
#include "scene/environment_map.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib::scene {

using Rgb = glm::vec3;

// Luminance of linear Rec.709 RGB (common/luminance_shared.h); used for importance sampling.
inline float luminance(const Rgb& c) {
  return float(kLuminanceRed) * c.r + float(kLuminanceGreen) * c.g + float(kLuminanceBlue) * c.b;
}

enum class MaterialType { kLambert, kPhong, kMirror, kGlass };

// Whether a material type reflects or refracts as a delta distribution (an ideal mirror, glass):
// what the specular techniques need, and what path classes call S. Lambert and Phong are not:
// their light paths are D, glossy lobes included (docs/rendering.md, "Path classes").
bool isIdealSpecular(MaterialType type);

// The range of a glass's index of refraction scene files and builders accept: from air (1, the
// surrounding medium, so the glass is invisible) to germanium (about 4, the densest optical
// material in common use).
inline constexpr float kMinGlassIor = 1.0f;
inline constexpr float kMaxGlassIor = 4.0f;

// Lambert: f = diffuse/π. Phong (normalised modified Phong):
// f = diffuse/π + specular·(n+2)/(2π)·cosⁿα, α between the mirror direction of ωo and ωi.
// Energy conservation requires diffuse + specular ≤ 1 per channel (checked by validateScene).
// Mirror: an ideal specular conductor; it reflects the fraction F(θ) of eq. 1.5 (the exact
// Fresnel function of the complex index n + iκ, per channel, scene/fresnel_shared.h) into the
// mirror direction, or all of it when `perfect_mirror` (a test reflector, R = 1 at every angle).
// Glass: a smooth dielectric of index `ior` inside a surrounding medium of index 1; it reflects
// F(θ) (exact, unpolarised) and refracts the rest by Snell's law, with total internal reflection,
// and attenuates light travelling inside it by exp(−absorption·distance) (Beer–Lambert, per
// channel, per scene unit). A glass mesh must be closed, with its triangles facing outwards: the
// front side is the outside.
// A material with non-zero emission turns its triangles into one-sided Lambertian area lights that
// emit `emission` (radiance) from their front side.
struct Material {
  std::string name;
  MaterialType type = MaterialType::kLambert;
  Rgb diffuse{0.0f};
  Rgb specular{0.0f};
  float exponent = 1.0f;  // Phong n ≥ 0
  Rgb emission{0.0f};
  Rgb conductor_n{1.0f};  // mirror: real part n > 0 of the index of refraction
  Rgb conductor_k{0.0f};  // mirror: extinction coefficient κ ≥ 0
  bool perfect_mirror = false;
  float ior = 1.5f;      // glass, in [kMinGlassIor, kMaxGlassIor]
  Rgb absorption{0.0f};  // glass: Beer–Lambert coefficient inside, per scene unit

  bool isEmissive() const { return emission.r > 0 || emission.g > 0 || emission.b > 0; }
};

// An indexed triangle mesh. The front side of a triangle (a, b, c) is the side its normal
// (b − a) × (c − a) points to; only emission is one-sided, reflection is two-sided (glass has an
// inside: the back side).
// `normals`, when given, are unit shading normals per vertex (one per position, pointing to the
// front side's hemisphere), interpolated across each triangle to shade a smooth surface out of
// flat triangles; without them the surface is shaded flat. Rays always leave from the geometric
// surface (docs/rendering.md, "Shading normals").
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::uvec3> triangles;
  std::uint32_t material = 0;  // index into Scene::materials
};

// Intensity I(θ) = intensity · cos(θ)^falloff_exponent for θ ≤ cone_angle_deg, zero outside;
// θ is the angle to `direction`. cone_angle_deg is the half angle of the cone.
struct SpotLight {
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
  Rgb intensity{0.0f};  // W/sr on the axis
  float cone_angle_deg = 45.0f;
  float falloff_exponent = 0.0f;
};

// The cosine of a spot's effective cone edge: its cone's, or 0 when the cone is wider than a
// hemisphere and k > 0 (cosᵏθ is taken as zero behind the light, as the path tracer's next-event
// estimation has it).
float spotEdgeCosine(const SpotLight& spot);
// ∫ cosᵏθ dω over the spot's cone, 2π(1 − μ^(k+1))/(k + 1) with μ = spotEdgeCosine: its power
// is Φ = I·∫cosᵏθ dω. Shared by the light tracer (emission by power) and the obscurances' ambient
// light (scene/obscurance.h), so both count a spot's power alike.
float spotSolidAngleIntegral(const SpotLight& spot);

// A light at infinity. `direction` is the direction the light travels (from the light into the
// scene); `irradiance` is what a surface perpendicular to it receives.
struct DirectionalLight {
  glm::vec3 direction{0.0f, -1.0f, 0.0f};
  Rgb irradiance{0.0f};
};

// A particle of a participating medium: σt(p) = density·(1 − |p − centre|/radius) inside it.
struct MediumParticle {
  glm::vec3 centre{0.0f};
  float radius = 1.0f;
  float density = 1.0f;  // τ: extinction coefficient at the centre, per scene unit
};

// A medium made of particles (the cloud), with one single-scattering albedo σs/σt and one
// Henyey–Greenstein phase function for all of it. Surfaces and medium may coexist; the medium has
// no boundary surface (its density fades to zero at the particles' edges).
struct Medium {
  std::vector<MediumParticle> particles;
  Rgb albedo{0.9f};
  float g = 0.0f;  // Henyey–Greenstein asymmetry in (−1, 1)

  bool empty() const { return particles.empty(); }
};

// Pinhole camera, right-handed world. The image's pixel (0,0) is at the top left and pixel
// centres are at +0.5 (see camera.h for the exact ray of a pixel).
struct Camera {
  glm::vec3 position{0.0f};
  glm::vec3 look_at{0.0f, 0.0f, -1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float vertical_fov_deg = 45.0f;
  // A thin lens (book §11.4), the reference's ground truth for depth of field: camera rays start
  // on a disc of this radius (scene units) about `position`, across the view, and meet where the
  // pinhole's ray through the same image point meets the plane in focus. 0: the pinhole.
  float lens_radius = 0.0f;
  // Distance (scene units) along the view direction from `position` to the plane in focus; 0: the
  // plane through look_at (focusDistance). Only a lens (lens_radius > 0) reads it.
  float focus_distance = 0.0f;
};

// The distance of the plane in focus: focus_distance, or look_at's distance along the view when
// it is 0.
float focusDistance(const Camera& camera);

// Throws gib::InputError unless `radius` is a finite lens radius >= 0 / `distance` a finite
// focus distance > 0, naming `option` (the command-line option, scene-file or suite key).
void checkLensRadius(double radius, std::string_view option);
void checkFocusDistance(double distance, std::string_view option);

// A lens chosen outside the scene (`gibench render --lens-radius --focus-distance`, a suite's
// `lens`), over the scene's own: each value given replaces the camera's, after the checks above
// (naming the two options).
struct LensSetting {
  std::optional<double> radius;
  std::optional<double> focus_distance;
  bool operator==(const LensSetting&) const = default;
};
void applyLens(Camera& camera, const LensSetting& lens, std::string_view radius_option,
               std::string_view focus_option);

struct Scene {
  std::string name;
  std::string provenance;  // where the data comes from; recorded in outputs, not hashed
  // The built-in scene's parameter values ("key", "value"), recorded in outputs; not hashed
  // (what they change, the geometry, lights and camera, is).
  std::vector<std::pair<std::string, std::string>> parameters;
  Camera camera;
  std::vector<Material> materials;
  std::vector<Mesh> meshes;
  std::vector<SpotLight> spot_lights;
  std::vector<DirectionalLight> directional_lights;
  Rgb sky_radiance{0.0f};  // constant radiance of rays that leave the scene
  // Or the radiance of a latitude–longitude map in their direction (book §4.2); a scene has at
  // most one of the two (validateScene).
  EnvironmentMap environment;
  Medium medium;
  int default_width = 512;
  int default_height = 512;

  std::size_t triangleCount() const;
  bool hasEmissiveTriangles() const;
  // Whether any mesh with triangles is a mirror or glass (isIdealSpecular).
  bool hasIdealSpecular() const;
  // Whether light arrives from beyond the scene: a constant sky or an environment map.
  bool hasEnvironmentLight() const;
};

// Throws gib::InputError naming the first problem (bad index, NaN, negative reflectance, energy
// gain, degenerate camera, ...). Every loader calls it.
void validateScene(const Scene& scene);

// Canonical hash of everything that affects the image: geometry, materials, lights, sky and
// camera (not the name, provenance or default resolution). 32 hex digits.
std::string hashScene(const Scene& scene);

}  // namespace gib::scene
