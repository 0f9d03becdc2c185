// Book eq. 8.5 per vertex: the radiance Σ_d w_d (L·B_d^k) + L·M^k of the vertex's cluster k from
// the frame's projections, interpolated over the sub-triangle by the rasteriser.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/techniques/prt/prt_shared.h"

layout(std430, binding = kPrtPositionsBinding) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = kPrtCornersBinding) readonly buffer Corners { uint corners[]; };
layout(std430, binding = kPrtClustersBinding) readonly buffer Clusters { uint clusters[]; };
layout(std430, binding = kPrtWeightsBinding) readonly buffer Weights { float weights[]; };
layout(std430, binding = kPrtProjectionsBinding) readonly buffer Projections { vec4 projections[]; };

uniform int u_pca_vectors;  // M

out vec3 v_radiance;
// The depth pass and the colour pass compare equal depths.
invariant gl_Position;

void main() {
  uint v = corners[gl_VertexID];
  uint base = clusters[v] * uint(u_pca_vectors + 1);
  vec3 radiance = projections[base].rgb;
  for (int d = 0; d < u_pca_vectors; ++d)
    radiance += weights[v * uint(u_pca_vectors) + uint(d)] * projections[base + 1u + uint(d)].rgb;
  v_radiance = radiance;
  gl_Position = camera.view_projection * vec4(positions[v].xyz, 1.0);
}
