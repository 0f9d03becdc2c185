// Coverage images of jittered light sampling: the triangles' world positions, pulled from the
// storage buffer by vertex index, through the point's view and off-axis projection.
#include "realtime/techniques/jittered_light_sampling/jittered_light_sampling_shared.h"

layout(std430, binding = kCoverageTrianglesBinding) readonly buffer CoverageTriangles {
  vec4 corners[];
};
uniform mat4 u_view_projection;

void main() {
  gl_Position = u_view_projection * vec4(corners[gl_VertexID].xyz, 1.0);
}
