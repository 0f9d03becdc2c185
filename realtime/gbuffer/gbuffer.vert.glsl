#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gpu_scene/vertex.glsl"

#ifdef EXPLICIT_VIEW
// Views other than the camera's (GBuffer::renderViews): instance i draws through view i into
// viewport i, chosen here where the GL allows, else in gbuffer_views.geom.glsl (which then takes
// these outputs under g_ names).
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gbuffer/gbuffer_views_shared.h"
layout(std140, binding = kGBufferViewsBinding) uniform GBufferViewBlock {
  GBufferViewRecord u_views[kMaxGBufferViewsPerDraw];
};
#ifndef VIEWPORT_FROM_VERTEX_SHADER
#define world_position g_world_position
#define world_normal g_world_normal
#define material g_material
#define view_eye g_view_eye
flat out int g_viewport;
#endif
flat out vec3 view_eye;
#endif

out vec3 world_position;
flat out vec3 world_normal;
flat out uint material;

void main() {
  world_position = vertex_position;
  world_normal = vertex_normal;
  material = vertex_material;
#ifdef EXPLICIT_VIEW
  view_eye = u_views[gl_InstanceID].eye.xyz;
  gl_Position = u_views[gl_InstanceID].view_projection * vec4(vertex_position, 1.0);
#ifdef VIEWPORT_FROM_VERTEX_SHADER
  gl_ViewportIndex = gl_InstanceID;
#else
  g_viewport = gl_InstanceID;
#endif
#else
  gl_Position = camera.view_projection * vec4(vertex_position, 1.0);
#endif
}
