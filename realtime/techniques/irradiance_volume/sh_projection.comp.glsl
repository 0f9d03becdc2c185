// Eq. 2 on the GPU: each probe's coefficients as the sum over its six cube faces of radiance
// times the precomputed Y·dω of the texel, one work group per probe reducing in shared memory.
#include "realtime/sh/spherical_harmonics.glsl"
#include "realtime/techniques/irradiance_volume/irradiance_volume_shared.h"

layout(local_size_x = kShProjectionGroupSize) in;

layout(binding = kProbeRadianceUnit) uniform sampler2D u_radiance;  // the lit cube-map atlas
layout(std430, binding = kProbeCoefficientsBinding) writeonly buffer Coefficients {
  vec4 coefficients[];  // [probeCoefficientIndex(probe, i)]
};
layout(std430, binding = kProjectionWeightsBinding) readonly buffer Weights {
  float weights[];  // [((face · size + j) · size + i) · count + c]: Y_c · dω
};
uniform int u_face;
uniform int u_tiles_x;
uniform int u_coefficient_count;

shared vec3 partial[kShProjectionGroupSize][kShMaxCoefficients];

void main() {
  int probe = int(gl_WorkGroupID.x);
  int thread = int(gl_LocalInvocationID.x);
  vec3 sums[kShMaxCoefficients];
  for (int c = 0; c < kShMaxCoefficients; ++c) sums[c] = vec3(0.0);
  int per_face = u_face * u_face;
  for (int t = thread; t < kCubeFaces * per_face; t += kShProjectionGroupSize) {
    int face = t / per_face, j = (t % per_face) / u_face, i = t % u_face;
    ivec2 texel = tileOrigin(probeTile(probe, face), u_tiles_x, u_face) + ivec2(i, j);
    vec3 radiance = texelFetch(u_radiance, texel, 0).rgb;
    int base = t * u_coefficient_count;
    for (int c = 0; c < u_coefficient_count; ++c) sums[c] += radiance * weights[base + c];
  }
  for (int c = 0; c < kShMaxCoefficients; ++c) partial[thread][c] = sums[c];
  barrier();
  for (int stride = kShProjectionGroupSize / 2; stride > 0; stride /= 2) {
    if (thread < stride)
      for (int c = 0; c < u_coefficient_count; ++c)
        partial[thread][c] += partial[thread + stride][c];
    barrier();
  }
  if (thread < kShMaxCoefficients)
    coefficients[probeCoefficientIndex(probe, thread)] =
        vec4(thread < u_coefficient_count ? partial[0][thread] : vec3(0.0), 0.0);
}
