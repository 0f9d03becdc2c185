// The materials of docs/architecture.md, evaluated exactly as the reference does (reference/bsdf.cpp):
// Lambert f = ρd/π; normalised modified Phong adds ρs·(n+2)/(2π)·cosⁿα, α between the mirror
// direction of ωo and ωi. `n` faces the side of ωo.
const float kInvPi = 0.31830988618379067;

vec3 evaluateBrdf(vec3 diffuse, vec3 specular, float exponent, bool phong, vec3 n, vec3 wo,
                  vec3 wi) {
  if (dot(n, wi) <= 0.0) return vec3(0.0);
  vec3 f = diffuse * kInvPi;
  if (phong) {
    float c = dot(2.0 * dot(n, wo) * n - wo, wi);
    if (c > 0.0) f += specular * ((exponent + 2.0) * 0.5 * kInvPi * pow(c, exponent));
  }
  return f;
}
