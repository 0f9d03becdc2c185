// The tables of environment_shadows' integrated reflectivity (book §4.2.3's a(Δω_i, ω), with the
// cell taken as a spherical cap of its solid angle, after Barsi, Szirmay-Kalos & Szécsi 2005):
// the mean of cos⁺^s γ over a cap of half-angle α whose axis lies at angle β from the lobe's
// axis (γ the angle from the lobe's axis), by quadrature on the CPU when the technique is
// prepared. Laid out as realtime/lighting/cell_reflectivity_shared.h reads them.
#pragma once

#include <vector>

namespace gib::rt {

// The mean over the cap of max(0, cos γ)^s, s ≥ 0; α, β in [0, π] radians. α = 0 gives
// cos⁺^s β, the centre's value. One-dimensional quadrature in γ: at each γ the fraction of the
// circle of directions at that angle from the lobe axis that lies inside the cap is known in
// closed form, acos((cos α − cos γ cos β)/(sin γ sin β))/π.
double capMeanCosinePower(double s, double alpha, double beta);

// The table of exponent s: kCellReflectivitySize² values, row j the angle β_j, column i the
// angle α_i, both π·(k/(N−1))².
std::vector<float> capReflectivityTable(double s);

}  // namespace gib::rt
