// A record's view of the directly lit scene: the atlas mesh seen from record u_first_record +
// instance / faces through face instance % faces, into layer `instance`. Perspective depth; the
// horizon clips what lies below the record's tangent plane.
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_shared.h"
#include "realtime/techniques/irradiance_cache_splatting/record_face.glsl"
#include "realtime/atlas/atlas_vertex.glsl"

uniform int u_first_record;
uniform int u_faces;
uniform float u_half_width;  // h of the faces
uniform float u_near;
uniform float u_far;
uniform float u_lift;  // the eye sits this far off the surface, along the normal

out vec2 g_atlas_uv;
out vec3 g_world;
flat out vec3 g_origin;
flat out int g_layer;
out gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[1];
};

void main() {
  IrradianceRecord record = records[u_first_record + gl_InstanceID / u_faces];
  vec3 n = record.normal.xyz;
  RecordFace f = recordFace(n, gl_InstanceID % u_faces);
  vec3 origin = record.position_radius.xyz + u_lift * n;
  vec3 d = vertex_position - origin;
  vec3 q = vec3(dot(d, f.right), dot(d, f.up), dot(d, f.forward));
  g_atlas_uv = vertex_atlas_uv;
  g_world = vertex_position;
  g_origin = origin;
  g_layer = gl_InstanceID;
  gl_ClipDistance[0] = dot(d, n);
  gl_Position = vec4(q.xy / u_half_width,
                     (u_far + u_near) / (u_far - u_near) * q.z -
                         2.0 * u_far * u_near / (u_far - u_near),
                     q.z);
}
