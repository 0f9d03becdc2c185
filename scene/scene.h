// The scene model shared by the reference path tracer and every real-time technique
// (docs/architecture.md, "Conventions"). Units: lengths in scene units (the Cornell box uses mm),
// radiance in linear Rec.709 RGB (W/(sr·m²) per channel, scene-linear), spot intensity in W/sr,
// directional irradiance in W/m² on a plane perpendicular to the light.
#pragma once

#include "common/luminance_shared.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gib::scene {

using Rgb = glm::vec3;

// Luminance of linear Rec.709 RGB (common/luminance_shared.h); used for importance sampling.
inline float luminance(const Rgb& c) {
  return float(kLuminanceRed) * c.r + float(kLuminanceGreen) * c.g + float(kLuminanceBlue) * c.b;
}

enum class MaterialType { kLambert, kPhong };

// Whether a material type reflects or refracts as a delta distribution (an ideal mirror, glass):
// what the specular techniques need. Lambert and Phong are not.
bool isIdealSpecular(MaterialType type);

// Lambert: f = diffuse/π. Phong (normalised modified Phong):
// f = diffuse/π + specular·(n+2)/(2π)·cosⁿα, α between the mirror direction of ωo and ωi.
// Energy conservation requires diffuse + specular ≤ 1 per channel (checked by validateScene).
// A material with non-zero emission turns its triangles into one-sided Lambertian area lights that
// emit `emission` (radiance) from their front side.
struct Material {
  std::string name;
  MaterialType type = MaterialType::kLambert;
  Rgb diffuse{0.0f};
  Rgb specular{0.0f};
  float exponent = 1.0f;  // Phong n ≥ 0
  Rgb emission{0.0f};

  bool isEmissive() const { return emission.r > 0 || emission.g > 0 || emission.b > 0; }
};

// An indexed triangle mesh. The front side of a triangle (a, b, c) is the side its normal
// (b − a) × (c − a) points to; only emission is one-sided, reflection is two-sided.
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
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
};

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
  Medium medium;
  int default_width = 512;
  int default_height = 512;

  std::size_t triangleCount() const;
  bool hasEmissiveTriangles() const;
};

// Throws gib::InputError naming the first problem (bad index, NaN, negative reflectance, energy
// gain, degenerate camera, ...). Every loader calls it.
void validateScene(const Scene& scene);

// Canonical hash of everything that affects the image: geometry, materials, lights, sky and
// camera (not the name, provenance or default resolution). 32 hex digits.
std::string hashScene(const Scene& scene);

}  // namespace gib::scene
