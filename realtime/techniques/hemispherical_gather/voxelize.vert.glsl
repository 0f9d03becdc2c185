// Voxelisation (§5.3): the scene seen by an orthographic view along axis u_axis from side
// u_side (0: from below, looking along +axis), into layer u_face · u_slices + instance, the slab
// that the fragment shader keeps.
#include "realtime/techniques/hemispherical_gather/layered_vertex_outputs.glsl"
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/atlas/atlas_vertex.glsl"

uniform int u_axis;
uniform int u_side;
uniform int u_face;
uniform int u_slices;
uniform vec3 u_bounds_min;
uniform vec3 u_bounds_max;

void main() {
  g_atlas_uv = vertex_atlas_uv;
  g_world = vertex_position;
  g_normal = vertex_normal;
  g_layer = u_face * u_slices + gl_InstanceID;
  vec3 t = (vertex_position - u_bounds_min) / (u_bounds_max - u_bounds_min);  // [0, 1]³
  vec2 uv = u_axis == 0 ? t.yz : (u_axis == 1 ? t.zx : t.xy);
  float along = u_axis == 0 ? t.x : (u_axis == 1 ? t.y : t.z);
  float depth = u_side == 0 ? along : 1.0 - along;  // nearest to the side it is seen from
  gl_Position = vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  for (int i = 0; i < kGatherClipDistances; ++i) gl_ClipDistance[i] = 1.0;
}
