// §5.3's enclosing cones, one invocation per tile of rays: the axis is the rays' mean direction,
// the half angle φ the largest angle between a ray and the axis (plus a margin for rounding), and
// the apex is set back along the axis from the origins' origin_mean until every origin lies inside
// the cone: then every ray does, since a cone contains every half-line that starts inside it and
// runs within φ of its axis. Rays from one point (primary rays) get their origin as apex. Rays
// that spread over more than a hemisphere get no cone (every triangle kept).
#include "realtime/ray_casting/ray_engine_shared.h"

layout(local_size_x = kRayEngineConeGroupSize) in;
layout(binding = kRayEngineOriginsUnit) uniform sampler2D u_origins;
layout(binding = kRayEngineDirectionsUnit) uniform sampler2D u_directions;
layout(std430, binding = kRayEngineConesBinding) writeonly buffer Cones { vec4 u_cone[]; };
uniform int u_tiles_x;
uniform int u_tile_count;
uniform int u_tile_size;
uniform int u_ray_count;
uniform int u_width;

// 10⁻⁴ rad of margin on the half angle, and the widest half angle worth a cone (about 86°).
const float kAngleMargin = 1.0e-4;
const float kWidestCone = 1.5;

void main() {
  int tile = int(gl_GlobalInvocationID.x);
  if (tile >= u_tile_count) return;
  ivec2 first = ivec2(tile % u_tiles_x, tile / u_tiles_x) * u_tile_size;
  vec3 direction_sum = vec3(0.0), origin_sum = vec3(0.0);
  int rays = 0;
  for (int y = first.y; y < first.y + u_tile_size; ++y)
    for (int x = first.x; x < min(first.x + u_tile_size, u_width); ++x) {
      if (y * u_width + x >= u_ray_count) continue;  // x < u_width by the loop
      vec4 d = texelFetch(u_directions, ivec2(x, y), 0);
      direction_sum += normalize(d.xyz);
      origin_sum += texelFetch(u_origins, ivec2(x, y), 0).xyz;
      ++rays;
    }
  if (rays == 0) {
    u_cone[2 * tile] = vec4(0.0);
    u_cone[2 * tile + 1] = vec4(0.0, 0.0, 1.0, kConeEmpty);
    return;
  }
  float sum_length = length(direction_sum);
  vec3 axis = sum_length > 1e-6 ? direction_sum / sum_length : vec3(0.0, 0.0, 1.0);
  vec3 origin_mean = origin_sum / float(rays);
  float cos_widest = 1.0;
  for (int y = first.y; y < first.y + u_tile_size; ++y)
    for (int x = first.x; x < min(first.x + u_tile_size, u_width); ++x) {
      if (y * u_width + x >= u_ray_count) continue;  // x < u_width by the loop
      cos_widest = min(cos_widest, dot(normalize(texelFetch(u_directions, ivec2(x, y), 0).xyz),
                                       axis));
    }
  float angle = acos(clamp(cos_widest, -1.0, 1.0)) + kAngleMargin;
  if (sum_length <= 1e-6 || angle >= kWidestCone) {
    u_cone[2 * tile] = vec4(origin_mean, angle);
    u_cone[2 * tile + 1] = vec4(axis, kConeKeepsAll);
    return;
  }
  // Set back h from the origin_mean: origin i (s along the axis, r across it) is inside when
  // r ≤ (s + h)·tan φ.
  float tan_angle = tan(angle), setback = 0.0;
  for (int y = first.y; y < first.y + u_tile_size; ++y)
    for (int x = first.x; x < min(first.x + u_tile_size, u_width); ++x) {
      if (y * u_width + x >= u_ray_count) continue;  // x < u_width by the loop
      vec3 w = texelFetch(u_origins, ivec2(x, y), 0).xyz - origin_mean;
      float s = dot(w, axis);
      float r = length(w - s * axis);
      setback = max(setback, r / tan_angle - s);
    }
  // Rounding of the origins' coordinates: a relative margin keeps them strictly inside.
  setback = setback * (1.0 + 1e-4) + 1e-6 * length(origin_mean);
  u_cone[2 * tile] = vec4(origin_mean - setback * axis, angle);
  u_cone[2 * tile + 1] = vec4(axis, kConeCulls);
}
