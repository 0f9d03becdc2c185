// The transfer vectors of diffuse PRT (book §8.3, eq. 8.4): at every vertex x of a PrtMesh and
// for every colour channel, T_i = (ρ/π) ∫ Y_i(ω) V(x, ω) cos⁺θ dω, the radiance the vertex
// reflects towards any viewer under the environment lighting L(ω) = Σ_i L_i Y_i(ω) being
// Σ_i L_i T_i. Estimated by Monte Carlo from `rays` cosine-distributed, stratified rays per
// vertex (pdf cosθ/π: each ray that escapes adds ρ·Y(ω)/rays); interreflections by iterating
// (Sloan, Kautz & Snyder 2002, §5): bounce b's transfer at a vertex is ρ/rays times the sum, over
// its rays that hit a front face, of the hit point's bounce-(b − 1) transfer interpolated from
// its sub-triangle's vertices; the vertex's transfer is the sum over bounces 1..`bounces`.
#pragma once

#include "realtime/techniques/prt/prt_mesh.h"
#include "scene/ray_caster.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace gib::rt::prt {

struct TransferSettings {
  int bands = 6;
  int rays = 256;
  int bounces = 1;
  std::uint64_t seed = 0;
  int threads = 0;  // parallelFor's: 0 one per hardware thread; the result does not depend on it
};

struct Transfer {
  int coefficients = 0;  // bands²
  // Vertex v's vector, 3·bands² floats at v·3·bands²: red's bands² coefficients, then green's,
  // then blue's.
  std::vector<float> vectors;
  std::size_t rays_cast = 0, rays_hit = 0;  // rays_hit: those that met any surface
  // The estimated relative standard error of the vertices' radiance under `lighting`:
  // sqrt(Σ_v σ_v² / Σ_v R_v²) over the vertices, R_v the luminance of the vertex's radiance and
  // σ_v² the sample variance of its per-ray estimates over `rays` (README.md, "Errors").
  double monte_carlo_error = 0;

  int dimension() const { return 3 * coefficients; }
};

// `lighting`: bands² RGB coefficients (sh_projection.h) used only for monte_carlo_error.
Transfer computeTransfer(const PrtMesh& mesh, const scene::Scene& scene,
                         const scene::RayCaster& caster, const TransferSettings& settings,
                         std::span<const glm::vec3> lighting);

// The RGB radiance Σ_i L_i T_i of each vertex of `vectors` (laid out as Transfer::vectors).
std::vector<glm::vec3> vertexRadiance(std::span<const float> vectors, int coefficients,
                                      std::span<const glm::vec3> lighting);

// The rows × columns of a stratified grid of exactly `rays` cells: the largest divisor of rays
// not above √rays rows (32 × 32 for the book's 1024; 1 × rays for a prime).
std::pair<int, int> strataOf(int rays);

}  // namespace gib::rt::prt
