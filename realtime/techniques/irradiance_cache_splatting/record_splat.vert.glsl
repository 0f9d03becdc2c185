// A record's zone of influence splatted (notes 001, "Splatting"): instance k draws the screen
// rectangle that holds the projection of record k's sphere of radius a·R_k (a triangle strip of
// four corners).
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_shared.h"
#include "realtime/techniques/irradiance_cache_splatting/record_face.glsl"

uniform float u_accuracy;
flat out int v_record;

void main() {
  IrradianceRecord record = records[gl_InstanceID];
  vec4 rect = sphereScreenRect(camera.view, camera.projection, record.position_radius.xyz,
                             u_accuracy * record.position_radius.w);
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
  gl_Position = vec4(mix(rect.xy, rect.zw, corner), 0.0, 1.0);
  v_record = gl_InstanceID;
}
