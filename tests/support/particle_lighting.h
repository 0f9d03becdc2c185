// The error model of the particle techniques (spherical billboards, the illumination network)
// against the reference: what their known approximation, lighting each particle at its centre,
// may cost (derived from the particles, not measured from a run), and the comparison of their
// scattered light with the reference's under the reference's noise.
#pragma once

#include "reference/progressive_renderer.h"
#include "scene/scene.h"
#include "support/render_statistics.h"
#include "support/statistical_test.h"

#include <vector>

namespace gib::test {

// The density-weighted mean, over the points of a particle and over directions, of the
// particle's own optical depth from a point to its surface, in units of τr: ½∫D² dA / ∫D dA for
// the linear fall-off, D(b) the optical depth of the chord at impact parameter b (0.28; computed
// by quadrature of the closed form).
double ownDepthPerTauR();

// The relative error of a particle's scattered light that lighting it at its centre allows.
// A particle scatters, per unit opacity, the light that reaches its centre through the *other*
// particles (realtime/particles/volume_shadow.comp.glsl); the truth scatters at each point of
// the sphere the light that reaches that point through all of them.
// - First order, the particle's own density, left out: each point scatters in proportion to its
//   density, so on average the light is attenuated by its own depth ownDepthPerTauR()·τr, which
//   the technique does not do: a relative error a = ownDepthPerTauR()·τr at most (1 − e^−a).
// - The other particles' depth is taken at the centre instead of at each point: its first-order
//   part (the depth's gradient across the sphere) cancels over the sphere, which is symmetric
//   about its centre; the second-order part, half the depth's variance across the sphere, is of
//   the order of a² where the neighbours are of the particle's size and density.
// So a particle's light errs by at most a + a². The image's scattered light is a sum over the
// particles, each (where it is optically thin) in proportion to its mass ∫σ dV = πτr³/3: its
// relative error is at most the mass-weighted mean of a + a² (`mean`); a pixel may see one
// particle alone, so a pixel's is at most the largest particle's (`largest`).
struct CentreLightingAllowance {
  double mean = 0;
  double largest = 0;
};
CentreLightingAllowance centreLightingAllowance(
    const std::vector<scene::MediumParticle>& particles);

// A particle technique's image against the reference of its path class, split into what it
// renders exactly, the sky transmitted through the medium (its image with albedo 0: the tests
// of the transmittance bound it to 1e-3), and the scattered light, which carries the
// approximation.
struct ScatteredLightMatch {
  // Σ(image − transmitted) / Σ(reference − transmitted), with the reference's image-mean error
  // (delta method) and degrees of freedom.
  MeanEstimate ratio;
  // relMSE of the image against the truth, the reference's noise taken out (relMseLessNoise).
  MeanEstimate relmse;
  // The relMSE that the largest relative error the allowance gives each pixel's scattered light
  // would add.
  double relmse_allowance = 0;
};
ScatteredLightMatch matchScatteredLight(const ref::RenderResult& reference,
                                        const image::Image& image, const image::Image& transmitted,
                                        const CentreLightingAllowance& allowance);

// Expects the scattered light's ratio within 1 ± (allowance.mean + k·standard error) (the
// family's t test) and the relMSE less noise below relmse_allowance + k·standard error, k the
// family's two-sided critical value (conservative for the relMSE, which only an excess fails).
// Two tests of `family`.
void expectScatteredLightMatches(const ScatteredLightMatch& match,
                                 const CentreLightingAllowance& allowance,
                                 const TestFamily& family);

}  // namespace gib::test
