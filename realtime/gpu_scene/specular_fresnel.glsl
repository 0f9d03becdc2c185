// Fresnel's reflectance of the scene's ideal specular materials at cos θ on their outside, by a
// technique's setting: eq. 1.6's approximation from the reflectance at normal incidence, as the
// book's shaders (§4.2.1, §6.2), or the exact functions the reference uses
// (scene/fresnel_shared.h). Shared by the techniques that shade mirrors and glass (distance maps,
// environment mapping), so that `fresnel=schlick|exact` means the same in each. Needs scene.glsl
// before it.
#include "scene/fresnel_shared.h"

// A mirror's, per channel. A perfect mirror reflects everything.
vec3 mirrorFresnel(uint material, float cos_i, bool schlick) {
  if (materialIsPerfectMirror(material)) return vec3(1.0);
  vec3 n = materialConductorN(material), k = materialConductorK(material);
  if (schlick) return fresnelApproximation(fresnelAtNormalIncidence(n, k), cos_i);
  return fresnelConductor(cos_i, n, k);
}

// A glass's, seen from outside (index 1 against the material's).
float glassFresnel(uint material, float cos_i, bool schlick) {
  float eta = materialIor(material);
  if (schlick) {
    float f0 = (eta - 1.0) * (eta - 1.0) / ((eta + 1.0) * (eta + 1.0));
    return fresnelApproximation(vec3(f0), cos_i).x;
  }
  return fresnelDielectric(cos_i, eta);
}
