// The irradiance at each gather point of the batch: one work group per view sums radiance times
// each pixel's weight, cos θ dω. Perspective: a pixel of the image plane at unit distance, area
// A, at distance r from the eye, subtends A/r³ and sees its direction at cos θ = 1/r: A/r⁴ (the
// 160° square misses the grazing directions). Hemispherical: every pixel whose centre lies in the
// unit disk stands for the same projected solid angle, π over their count (Nusselt's analogue).
// Pixels where nothing was drawn hold the background radiance the views were cleared to.
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"

layout(local_size_x = kGatherSumGroupSize) in;
layout(binding = kGatherViewsUnit) uniform sampler2DArray u_views;
layout(rgba32f, binding = kImageDestinationUnit) uniform writeonly image2D u_irradiance;
uniform int u_first_point;
uniform ivec2 u_grid;
uniform int u_size;
uniform int u_projection;

shared vec3 partial[kGatherSumGroupSize];
shared float partial_count[kGatherSumGroupSize];

void main() {
  const int layer = int(gl_WorkGroupID.x);
  const int point = u_first_point + layer;
  const uint lane = gl_LocalInvocationIndex;
  const float pixel = 2.0 / float(u_size);  // a pixel's side in the image's [−1, 1]²
  const float tangent = kPerspectiveHalfTangent;
  vec3 sum = vec3(0.0);
  float count = 0.0;
  for (int i = int(lane); i < u_size * u_size; i += kGatherSumGroupSize) {
    vec2 xy = (vec2(i % u_size, i / u_size) + 0.5) * pixel - 1.0;
    vec3 radiance = texelFetch(u_views, ivec3(i % u_size, i / u_size, layer), 0).rgb;
    if (u_projection != kProjectionPerspective) {
      if (dot(xy, xy) < 1.0) {
        sum += radiance;
        count += 1.0;
      }
    } else {
      vec2 plane = xy * tangent;  // on the image plane at unit distance
      float r2 = dot(plane, plane) + 1.0;
      sum += radiance * (pixel * pixel * tangent * tangent) / (r2 * r2);
    }
  }
  partial[lane] = sum;
  partial_count[lane] = count;
  barrier();
  for (uint stride = kGatherSumGroupSize / 2; stride > 0u; stride /= 2u) {
    if (lane < stride) {
      partial[lane] += partial[lane + stride];
      partial_count[lane] += partial_count[lane + stride];
    }
    barrier();
  }
  if (lane == 0u && point < u_grid.x * u_grid.y) {
    vec3 irradiance = u_projection != kProjectionPerspective
                          ? partial[0] * (3.14159265358979 / max(partial_count[0], 1.0))
                          : partial[0];
    imageStore(u_irradiance, ivec2(point % u_grid.x, point / u_grid.x), vec4(irradiance, 1.0));
  }
}
