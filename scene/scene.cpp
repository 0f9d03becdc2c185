#include "scene/scene.h"

#include "common/content_hash.h"
#include "common/input_error.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace gib::scene {

bool isIdealSpecular(MaterialType type) {
  switch (type) {
    case MaterialType::kLambert:
    case MaterialType::kPhong:
      return false;
    case MaterialType::kMirror:
    case MaterialType::kGlass:
      return true;
  }
  return false;
}

bool Scene::hasIdealSpecular() const {
  for (const Mesh& mesh : meshes)
    if (!mesh.triangles.empty() && isIdealSpecular(materials.at(mesh.material).type)) return true;
  return false;
}

bool Scene::hasEnvironmentLight() const {
  return sky_radiance != Rgb(0.0f) || !environment.empty();
}

std::size_t Scene::triangleCount() const {
  std::size_t count = 0;
  for (const Mesh& mesh : meshes) count += mesh.triangles.size();
  return count;
}

bool Scene::hasEmissiveTriangles() const {
  for (const Mesh& mesh : meshes)
    if (!mesh.triangles.empty() && materials.at(mesh.material).isEmissive()) return true;
  return false;
}

float spotEdgeCosine(const SpotLight& spot) {
  const float edge = std::cos(glm::radians(spot.cone_angle_deg));
  return spot.falloff_exponent > 0 ? std::max(edge, 0.0f) : edge;
}

float spotSolidAngleIntegral(const SpotLight& spot) {
  const float k = spot.falloff_exponent;
  const float edge = spotEdgeCosine(spot);
  return 2.0f * std::numbers::pi_v<float> * (1.0f - std::pow(edge, k + 1.0f)) / (k + 1.0f);
}

namespace {

bool isFinite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool isNonNegative(const glm::vec3& v) {
  return v.x >= 0 && v.y >= 0 && v.z >= 0;
}

void require(bool ok, const std::string& message) {
  if (!ok) throw InputError(message);
}

void validateRgb(const Rgb& value, const std::string& what) {
  require(isFinite(value) && isNonNegative(value),
          fmt::format("{} must be finite and non-negative, got ({}, {}, {})", what, value.r,
                      value.g, value.b));
}

void validateMaterial(const Material& m) {
  const std::string where = fmt::format("material '{}'", m.name);
  validateRgb(m.diffuse, where + " diffuse");
  validateRgb(m.specular, where + " specular");
  validateRgb(m.emission, where + " emission");
  require(std::isfinite(m.exponent) && m.exponent >= 0,
          fmt::format("{} exponent must be finite and >= 0, got {}", where, m.exponent));
  if (m.type == MaterialType::kMirror && !m.perfect_mirror) {
    for (int c = 0; c < 3; ++c) {
      require(std::isfinite(m.conductor_n[c]) && m.conductor_n[c] > 0,
              fmt::format("{} n must be finite and > 0 in every channel, got {} in channel {}; "
                          "give the metal's refractive index (e.g. gold's, 0.18 at 650 nm)",
                          where, m.conductor_n[c], c));
      require(std::isfinite(m.conductor_k[c]) && m.conductor_k[c] >= 0,
              fmt::format("{} k (the extinction coefficient kappa) must be finite and >= 0 in "
                          "every channel, got {} in channel {}",
                          where, m.conductor_k[c], c));
    }
  }
  if (m.type == MaterialType::kGlass) {
    require(std::isfinite(m.ior) && m.ior >= kMinGlassIor && m.ior <= kMaxGlassIor,
            fmt::format("{} ior must be in [{}, {}] (air to germanium), got {}; glass is about 1.5",
                        where, kMinGlassIor, kMaxGlassIor, m.ior));
    validateRgb(m.absorption, where + " absorption");
  }
  // Reflecting more than arrives would make the path tracer diverge; every loader must stop it.
  for (int c = 0; c < 3; ++c)
    require(m.diffuse[c] + m.specular[c] <= 1.0f + 1e-6f,
            fmt::format("{} reflects more energy than it receives (diffuse + specular = {} > 1 in "
                        "channel {}); lower diffuse or specular",
                        where, m.diffuse[c] + m.specular[c], c));
}

void validateMesh(const Scene& scene, const Mesh& mesh) {
  const std::string where = fmt::format("mesh '{}'", mesh.name);
  require(mesh.material < scene.materials.size(),
          fmt::format("{} refers to material index {}, but the scene has {} materials", where,
                      mesh.material, scene.materials.size()));
  for (const glm::vec3& p : mesh.positions)
    require(isFinite(p), fmt::format("{} has a non-finite vertex position", where));
  require(mesh.normals.empty() || mesh.normals.size() == mesh.positions.size(),
          fmt::format("{} has {} vertex normals for {} positions; give one normal per vertex or "
                      "none (flat shading)",
                      where, mesh.normals.size(), mesh.positions.size()));
  for (const glm::vec3& n : mesh.normals)
    require(isFinite(n) && std::abs(glm::length(n) - 1.0f) < 1e-3f,
            fmt::format("{} has a vertex normal that is not a finite unit vector", where));
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      require(t[k] < mesh.positions.size(),
              fmt::format("{} has a triangle with vertex index {} but only {} vertices", where,
                          t[k], mesh.positions.size()));
}

void validateCamera(const Camera& c) {
  require(isFinite(c.position) && isFinite(c.look_at) && isFinite(c.up),
          "camera position, look_at and up must be finite");
  glm::vec3 forward = c.look_at - c.position;
  require(glm::length(forward) > 0, "camera look_at equals its position; move one of them");
  require(glm::length(glm::cross(forward, c.up)) > 1e-6f * glm::length(forward) * glm::length(c.up),
          "camera up is parallel to the viewing direction; choose another up vector");
  require(c.vertical_fov_deg > 0 && c.vertical_fov_deg < 180,
          fmt::format("camera vertical_fov_deg must be in (0, 180), got {}", c.vertical_fov_deg));
  checkLensRadius(c.lens_radius, "camera lens_radius");
  // 0 stands for look_at's distance (Camera::focus_distance); anything else must be a distance.
  if (c.focus_distance != 0) checkFocusDistance(c.focus_distance, "camera focus_distance");
}

}  // namespace

float focusDistance(const Camera& camera) {
  if (camera.focus_distance > 0) return camera.focus_distance;
  return glm::length(camera.look_at - camera.position);
}

void checkLensRadius(double radius, std::string_view option) {
  if (!(std::isfinite(radius) && radius >= 0))
    throw InputError(fmt::format(
        "{} {} is not a lens radius; give a finite radius >= 0 in scene units (0: the pinhole)",
        option, radius));
}

void checkFocusDistance(double distance, std::string_view option) {
  if (!(std::isfinite(distance) && distance > 0))
    throw InputError(
        fmt::format("{} {} is not a distance; give the distance in scene units (> 0) from "
                    "the camera to the plane in focus",
                    option, distance));
}

void applyLens(Camera& camera, const LensSetting& lens, std::string_view radius_option,
               std::string_view focus_option) {
  if (lens.radius) {
    checkLensRadius(*lens.radius, radius_option);
    camera.lens_radius = static_cast<float>(*lens.radius);
  }
  if (lens.focus_distance) {
    checkFocusDistance(*lens.focus_distance, focus_option);
    camera.focus_distance = static_cast<float>(*lens.focus_distance);
  }
}

void validateScene(const Scene& scene) {
  for (const Material& m : scene.materials) validateMaterial(m);
  for (const Mesh& mesh : scene.meshes) validateMesh(scene, mesh);
  for (const SpotLight& l : scene.spot_lights) {
    require(isFinite(l.position) && isFinite(l.direction) && glm::length(l.direction) > 0,
            "spot light position and direction must be finite and the direction non-zero");
    validateRgb(l.intensity, "spot light intensity");
    require(l.cone_angle_deg > 0 && l.cone_angle_deg <= 180,
            fmt::format("spot light cone_angle_deg must be in (0, 180], got {}", l.cone_angle_deg));
    require(l.falloff_exponent >= 0 && std::isfinite(l.falloff_exponent),
            "spot light falloff_exponent must be finite and >= 0");
  }
  for (const DirectionalLight& l : scene.directional_lights) {
    require(isFinite(l.direction) && glm::length(l.direction) > 0,
            "directional light direction must be finite and non-zero");
    validateRgb(l.irradiance, "directional light irradiance");
  }
  validateRgb(scene.sky_radiance, "sky radiance");
  if (!scene.environment.empty()) {
    require(scene.sky_radiance == Rgb(0.0f),
            "a scene has one environment: give a constant sky radiance or an environment map, "
            "not both");
    validateEnvironmentMap(scene.environment);
  }
  validateRgb(scene.medium.albedo, "medium albedo");
  for (int c = 0; c < 3; ++c)
    require(scene.medium.albedo[c] <= 1.0f,
            "medium albedo must be <= 1 (a medium cannot gain energy)");
  require(std::isfinite(scene.medium.g) && scene.medium.g > -1 && scene.medium.g < 1,
          fmt::format("medium g must be in (-1, 1), got {}", scene.medium.g));
  for (const MediumParticle& p : scene.medium.particles)
    require(isFinite(p.centre) && std::isfinite(p.radius) && p.radius > 0 &&
                std::isfinite(p.density) && p.density >= 0,
            "medium particles need a finite centre, a positive radius and a density >= 0");
  validateCamera(scene.camera);
  require(scene.default_width > 0 && scene.default_height > 0,
          "scene default image size must be positive");
}

std::string hashScene(const Scene& scene) {
  // Field order and tags are part of the canonical form: change them only with a new tag
  // version, since stored references are keyed by this hash.
  ContentHasher h;
  h.addString("gibench-scene-v1");
  auto addVec = [&](const glm::vec3& v) { h.addFloats({&v.x, 3}); };
  h.addU64(scene.materials.size());
  for (const Material& m : scene.materials) {
    h.addU64(static_cast<std::uint64_t>(m.type));
    addVec(m.diffuse);
    addVec(m.specular);
    h.addFloat(m.exponent);
    addVec(m.emission);
    // Only the new material types hash their fields, so that Lambert and Phong materials (every
    // scene before them) keep their hashes.
    if (m.type == MaterialType::kMirror) {
      h.addU64(m.perfect_mirror ? 1 : 0);
      addVec(m.conductor_n);
      addVec(m.conductor_k);
    } else if (m.type == MaterialType::kGlass) {
      h.addFloat(m.ior);
      addVec(m.absorption);
    }
  }
  h.addU64(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) {
    h.addU64(mesh.material);
    h.addU64(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) addVec(p);
    h.addU64(mesh.triangles.size());
    for (const glm::uvec3& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) h.addU64(t[k]);
    // Shading normals likewise only when given (a tagged section: flat meshes hash as before).
    if (!mesh.normals.empty()) {
      h.addString("normals");
      for (const glm::vec3& n : mesh.normals) addVec(n);
    }
  }
  h.addU64(scene.spot_lights.size());
  for (const SpotLight& l : scene.spot_lights) {
    addVec(l.position);
    addVec(l.direction);
    addVec(l.intensity);
    h.addFloat(l.cone_angle_deg);
    h.addFloat(l.falloff_exponent);
  }
  h.addU64(scene.directional_lights.size());
  for (const DirectionalLight& l : scene.directional_lights) {
    addVec(l.direction);
    addVec(l.irradiance);
  }
  addVec(scene.sky_radiance);
  // An environment map only when there is one (a tagged section: scenes without one hash as
  // before).
  if (!scene.environment.empty()) {
    const EnvironmentMap& map = scene.environment;
    h.addString("environment map");
    h.addU64(std::uint64_t(map.width));
    h.addU64(std::uint64_t(map.height));
    h.addFloats(*map.texels);
    h.addFloat(map.rotation_deg);
    h.addFloat(map.intensity);
  }
  h.addU64(scene.medium.particles.size());
  for (const MediumParticle& p : scene.medium.particles) {
    addVec(p.centre);
    h.addFloat(p.radius);
    h.addFloat(p.density);
  }
  addVec(scene.medium.albedo);
  h.addFloat(scene.medium.g);
  addVec(scene.camera.position);
  addVec(scene.camera.look_at);
  addVec(scene.camera.up);
  h.addFloat(scene.camera.vertical_fov_deg);
  // The lens only when there is one (a tagged section: pinhole cameras hash as before), with the
  // focus distance in effect, so that an explicit look_at distance hashes as the default does.
  if (scene.camera.lens_radius > 0) {
    h.addString("thin lens");
    h.addFloat(scene.camera.lens_radius);
    h.addFloat(focusDistance(scene.camera));
  }
  return h.hexDigest();
}

}  // namespace gib::scene
