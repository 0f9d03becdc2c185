// The distinct Phong exponents of a scene's glossy meshes: techniques that precompute one table
// or map per lobe shape (environment_map's convolved glossy maps, environment_shadows' cap
// reflectivity) make one per exponent, and their shaders find a material's by equality.
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

namespace gib::rt {

// The exponents of the Phong materials with non-zero specular reflectance on meshes with
// triangles, in increasing order, each once.
std::vector<float> glossyExponents(const scene::Scene& scene);

// A GLSL array literal of the exponents, `float[](…)`, in exponent notation with enough digits to
// round-trip a float, so that the shader's equality test finds the material's exponent.
std::string glslExponentArray(const std::vector<float>& exponents);

}  // namespace gib::rt
