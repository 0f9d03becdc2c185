// A gather view: the atlas mesh (tessellated, so that straight edges bend under the fish-eye
// projection) seen from gather point u_first_point + instance, into layer `instance`. Perspective:
// a 160° pinhole along the normal. Hemispherical (§5.2): a direction's tangent-plane coordinates
// are its image position (the unit disk), so every pixel stands for the same cosine-weighted solid
// angle; depth is the distance, written linearly with w = 1 so that nothing is clipped but what is
// below the horizon (gl_ClipDistance).
#include "realtime/techniques/hemispherical_gather/layered_vertex_outputs.glsl"
#include "realtime/techniques/hemispherical_gather/gather_point.glsl"
#include "realtime/atlas/atlas_vertex.glsl"

uniform int u_first_point;
uniform int u_projection;
uniform float u_near;
uniform float u_far;
uniform vec3 u_near_box;  // voxel slices: half-size of the box around the point drawn as geometry

void main() {
  g_atlas_uv = vertex_atlas_uv;
  g_world = vertex_position;
  g_normal = vertex_normal;
  g_layer = gl_InstanceID;
  GatherFrame f;
  if (!gatherFrame(u_first_point + gl_InstanceID, f)) {
    gl_Position = vec4(0.0);
    for (int i = 0; i < kGatherClipDistances; ++i) gl_ClipDistance[i] = -1.0;
    return;
  }
  vec3 d = vertex_position - f.origin;
  vec3 q = vec3(dot(d, f.t), dot(d, f.b), dot(d, f.n));
  gl_ClipDistance[0] = q.z;
  // Voxel slices: only what lies in the box around the point is drawn as geometry (§5.3: the
  // slices through the point's own voxel face away from it); farther away the slices stand in.
  for (int axis = 0; axis < 3; ++axis) {
    float offset = vertex_position[axis] - f.origin[axis];
    bool boxed = u_projection == kProjectionVoxelSlices;
    gl_ClipDistance[1 + 2 * axis] = boxed ? u_near_box[axis] + offset : 1.0;
    gl_ClipDistance[2 + 2 * axis] = boxed ? u_near_box[axis] - offset : 1.0;
  }
  if (u_projection != kProjectionPerspective) {
    float r = max(length(q), 1e-12);
    gl_Position = vec4(q.xy / r, 2.0 * (r - u_near) / (u_far - u_near) - 1.0, 1.0);
  } else {
    float scale = 1.0 / kPerspectiveHalfTangent;
    gl_Position = vec4(q.xy * scale,
                       (u_far + u_near) / (u_far - u_near) * q.z -
                           2.0 * u_far * u_near / (u_far - u_near),
                       q.z);
  }
}
