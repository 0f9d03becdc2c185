// The spherical-harmonic coefficients of an environment map (book §8.3's L, the lighting vector
// of eq. 8.4): L_i = ∫ L(ω) Y_i(ω) dω over the sphere in world directions, for the map's
// piecewise-constant texels, its rotation about +y and its intensity (scene/environment_map.h).
#pragma once

#include "scene/environment_map.h"

#include <glm/vec3.hpp>

#include <vector>

namespace gib::rt::sh {

// bands² RGB coefficients (sh_basis.h's order and convention) of the map's radiance. Exact for
// its texels up to rounding: in the map's own frame, where +y (the rows' axis) is the polar
// axis, every texel's integral separates into ∫cos(mφ) or ∫sin(mφ) over its column, taken in
// closed form, times ∫ P_l^m(cosθ) sinθ dθ over its row by Gauss–Legendre quadrature in θ
// (sh_projection.cpp says why in θ and why the order suffices); one ShRotation then turns the
// coefficients into the world's frame, whose polar axis is +z. Throws gib::InputError for an
// empty map or bands outside 1..8.
std::vector<glm::vec3> projectLatLong(const scene::EnvironmentMap& map, int bands);

}  // namespace gib::rt::sh
