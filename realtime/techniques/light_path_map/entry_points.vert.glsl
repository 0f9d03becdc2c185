// The entry points as dots over the scene (book Fig. 8.12): point i of the entry textures, lifted
// off its surface towards its front side so the depth test against the scene keeps it.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/techniques/light_path_map/light_path_map_shared.h"

layout(binding = kEntryPositionUnit) uniform sampler2D u_entry_position;
layout(binding = kEntryNormalUnit) uniform sampler2D u_entry_normal;
uniform float u_lift;
uniform float u_point_size;  // pixels

void main() {
  int side = textureSize(u_entry_position, 0).x;
  ivec2 texel = ivec2(gl_VertexID % side, gl_VertexID / side);
  vec3 p = texelFetch(u_entry_position, texel, 0).xyz + u_lift * texelFetch(u_entry_normal, texel, 0).xyz;
  gl_Position = camera.view_projection * vec4(p, 1.0);
  gl_PointSize = u_point_size;
}
