// Shadow map generation (book §4.1.1): the scene seen from the light, every layer of a batch in
// one instanced draw (instance i draws shadow face i into its layer). The layer is written here
// where the GL has vertex-shader layer selection (ARB_shader_viewport_layer_array or
// AMD_vertex_shader_layer), else by shadow.geom.glsl.
#include "realtime/gpu_scene/vertex.glsl"
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/lighting/light_sample_shared.h"

layout(std140, binding = kShadowFacesBinding) uniform ShadowFaceBlock {
  ShadowFace u_shadow_faces[kMaxShadowFaces];
};
#ifdef LAYER_FROM_VERTEX_SHADER
out vec3 v_world;
flat out int v_slot;
#else
out vec3 g_world;
flat out int g_slot;
flat out int g_layer;
#endif

void main() {
  ivec4 layer_slot = u_shadow_faces[gl_InstanceID].layer_slot;
  gl_Position = u_shadow_faces[gl_InstanceID].view_projection * vec4(vertex_position, 1.0);
#ifdef LAYER_FROM_VERTEX_SHADER
  v_world = vertex_position;
  v_slot = layer_slot.y;
  gl_Layer = layer_slot.x;
#else
  g_world = vertex_position;
  g_slot = layer_slot.y;
  g_layer = layer_slot.x;
#endif
}
