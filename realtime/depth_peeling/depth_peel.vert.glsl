// A bundle's orthographic view of the atlas mesh (realtime/depth_peeling/depth_peeler.h): clip
// position, the patch address (atlas coordinate) and the depth along the bundle, which is linear
// in an orthographic view and so interpolates exactly.
#include "realtime/atlas/atlas_vertex.glsl"
#include "realtime/depth_peeling/depth_peeling_shared.h"

uniform mat4 u_clip_from_world;
uniform vec3 u_plane_origin;
uniform vec3 u_direction;
out vec2 v_atlas_uv;
out float v_depth;
flat out float v_facing;

void main() {
  v_atlas_uv = vertex_atlas_uv;
  v_depth = dot(vertex_position - u_plane_origin, u_direction);
  // The geometric normal decides the side (book §10.4), not a shading normal.
  v_facing = dot(vertex_normal, u_direction) < 0.0 ? kPeelFrontFacing : kPeelBackFacing;
  gl_Position = u_clip_from_world * vec4(vertex_position, 1.0);
}
