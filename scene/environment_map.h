// A light at infinity given by a latitude–longitude image (book §4.2, "environment mapping"):
// a ray that leaves the scene in direction ω receives the radiance L(ω) of the image's texel in
// that direction, times `intensity`. The reference samples it by importance
// (scene/environment_distribution.h); the real-time techniques read the same texels.
//
// The map's own frame ("map directions") has +y up, as the world does. A map direction
// d = (sinθ cosφ, cosθ, sinθ sinφ) with polar angle θ ∈ [0, π] from +y and azimuth
// φ = atan2(d.z, d.x) ∈ [0, 2π) lies in texel column ⌊φ/(2π)·width⌋ and row ⌊θ/π·height⌋: row 0
// looks straight up, the middle row along the horizon, column 0 starts at +x and φ grows
// towards +z. The world turns the map by `rotation_deg` about +y, from +x towards −z (counter-
// clockwise seen from above, the right-hand rule about +y): what the map holds at azimuth φ the
// world sees at azimuth φ − rotation. A sky's sun at azimuth φ_s (scene/preetham_sky.h) uses the
// same azimuth.
//
// Texels are piecewise constant over their cells (no filtering), so the light the reference
// integrates is exactly the one the importance sampler draws from.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace gib::scene {

using Rgb = glm::vec3;

struct EnvironmentMap {
  int width = 0;   // 2 × height
  int height = 0;  // rows from the zenith (row 0) to the nadir
  // width × height RGB triples, row-major, scene-linear Rec.709 radiance before `intensity`.
  // Shared, so that copying a scene does not copy its map.
  std::shared_ptr<const std::vector<float>> texels;
  float rotation_deg = 0.0f;  // turns the map about +y (see above)
  float intensity = 1.0f;     // multiplies every texel, ≥ 0
  // Where the texels come from (a file's path, the sky's parameters): recorded, not hashed.
  std::string source;

  bool empty() const { return width == 0 || height == 0 || !texels; }
  // The texel at column x, row y, before `intensity`.
  Rgb texel(int x, int y) const;
  // intensity × the texel the world direction falls in (not normalised: any length > 0).
  Rgb radiance(const glm::vec3& world_direction) const;
  // The world direction as a map direction, and back (rotations about +y).
  glm::vec3 toMap(const glm::vec3& world_direction) const;
  glm::vec3 toWorld(const glm::vec3& map_direction) const;
};

// A map direction's coordinates (u, v) ∈ [0, 1)²: u = φ/(2π), v = θ/π. Not normalised: any
// length > 0; a zero or non-finite vector gives (0, 0).
glm::vec2 latLongCoordinates(const glm::vec3& map_direction);
// The unit map direction at coordinates (u, v) ∈ [0, 1]².
glm::vec3 latLongDirection(glm::vec2 uv);

// A map from its texels (width × height RGB values), checked by validateEnvironmentMap.
EnvironmentMap makeEnvironmentMap(int width, int height, std::vector<float> texels,
                                  std::string source);
// Throws gib::InputError naming the first problem: a size that is not 2:1 (width = 2 × height,
// height ≥ 1), a texel count that does not match, a negative, infinite or NaN texel, a rotation
// that is not finite, a negative or non-finite intensity.
void validateEnvironmentMap(const EnvironmentMap& map);

// Reads a latitude–longitude map from an EXR file's main RGB layer (a Y file gives grey), then
// validates it; gib::InputError names the file and the problem.
EnvironmentMap loadEnvironmentMap(const std::filesystem::path& exr_path);

// ∫ L(ω) dω over the sphere of each channel (intensity included): for a constant map of L, 4πL.
// Exact for the piecewise-constant texels (each row's solid angle 2π/width·(cosθ₀ − cosθ₁)).
Rgb environmentIntegral(const EnvironmentMap& map);

}  // namespace gib::scene
