// The interpolated vertex radiance, clamped at zero: a truncated SH lighting rings below zero
// where the environment has a sharp edge (a sun), which no surface reflects.
in vec3 v_radiance;
layout(location = 0) out vec4 o_radiance;

void main() {
  o_radiance = vec4(max(v_radiance, vec3(0.0)), 0.0);
}
