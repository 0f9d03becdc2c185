// Eq. 2 on the GPU: each probe's coefficients as the sum over its six cube faces of radiance
// times the precomputed Y·dω of the texel, one work group per probe reducing in shared memory.
#include "sh/spherical_harmonics.glsl"

#define kGroupSize 64
layout(local_size_x = kGroupSize) in;

layout(binding = 0) uniform sampler2D u_radiance;  // the lit cube-map atlas
layout(std430, binding = 2) writeonly buffer Coefficients {
  vec4 coefficients[];  // [probe · 16 + i]
};
layout(std430, binding = 5) readonly buffer Weights {
  float weights[];  // [((face · size + j) · size + i) · count + c]: Y_c · dω
};
uniform int u_face;
uniform int u_tiles_x;
uniform int u_coefficient_count;

shared vec3 partial[kGroupSize][SH_MAX_COEFFICIENTS];

void main() {
  int probe = int(gl_WorkGroupID.x);
  int thread = int(gl_LocalInvocationID.x);
  vec3 sums[SH_MAX_COEFFICIENTS];
  for (int c = 0; c < SH_MAX_COEFFICIENTS; ++c) sums[c] = vec3(0.0);
  int per_face = u_face * u_face;
  for (int t = thread; t < 6 * per_face; t += kGroupSize) {
    int face = t / per_face, j = (t % per_face) / u_face, i = t % u_face;
    int tile = probe * 6 + face;
    ivec2 texel = ivec2(tile % u_tiles_x, tile / u_tiles_x) * u_face + ivec2(i, j);
    vec3 radiance = texelFetch(u_radiance, texel, 0).rgb;
    int base = t * u_coefficient_count;
    for (int c = 0; c < u_coefficient_count; ++c) sums[c] += radiance * weights[base + c];
  }
  for (int c = 0; c < SH_MAX_COEFFICIENTS; ++c) partial[thread][c] = sums[c];
  barrier();
  for (int stride = kGroupSize / 2; stride > 0; stride /= 2) {
    if (thread < stride)
      for (int c = 0; c < u_coefficient_count; ++c)
        partial[thread][c] += partial[thread + stride][c];
    barrier();
  }
  if (thread < SH_MAX_COEFFICIENTS)
    coefficients[probe * SH_MAX_COEFFICIENTS + thread] =
        vec4(thread < u_coefficient_count ? partial[0][thread] : vec3(0.0), 0.0);
}
