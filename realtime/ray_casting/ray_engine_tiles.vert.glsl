// §5.3: one point per (triangle, tile) pair, vertex = triangle, instance = tile. The point lands
// on the tile, its size the tile's, when the triangle's bounding sphere meets the cone of the
// tile's rays, and outside the clip volume (discarded) when it does not: the book's test,
// φ + arcsin(r/|v − a|) ≥ arccos(x·(v − a)/|v − a|).
#include "realtime/ray_casting/ray_engine_shared.h"

layout(binding = kRayEngineConesUnit) uniform samplerBuffer u_cones;
layout(binding = kRayEngineSpheresUnit) uniform samplerBuffer u_spheres;
uniform int u_tiles_x;
uniform int u_tile_size;
uniform ivec2 u_target_size;
flat out int v_slot;

void main() {
  int tile = gl_InstanceID;
  v_slot = gl_VertexID;
  vec4 apex_angle = texelFetch(u_cones, 2 * tile);
  vec4 axis_mode = texelFetch(u_cones, 2 * tile + 1);
  vec4 sphere = texelFetch(u_spheres, gl_VertexID);
  vec2 centre = (vec2(tile % u_tiles_x, tile / u_tiles_x) + 0.5) * float(u_tile_size);
  gl_Position = sphereMeetsCone(sphere, apex_angle, axis_mode)
                    ? vec4(centre / vec2(u_target_size) * 2.0 - 1.0, 0.0, 1.0)
                    : vec4(2.0, 2.0, 2.0, 1.0);
  gl_PointSize = float(u_tile_size);
}
