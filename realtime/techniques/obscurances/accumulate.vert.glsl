// One point per pixel and layer of a peeled bundle (book §10.4): the surface at that layer is a
// patch crossed by the pixel's global ray, and its neighbour along the ray on the side its normal
// faces is its occluder. A front-facing patch (normal back along the bundle) looks towards the
// projection plane, at the layer before it; a back-facing one looks along the bundle, at the layer
// after it; no layer there means the ray leaves the scene (d = ∞). The point lands on the patch's
// atlas texel carrying the ray's sample of eq. 10.6 (scalar or spectral: obscurance_shared.h),
// added by blending.
#include "realtime/atlas/atlas_maps.glsl"
#include "realtime/depth_peeling/depth_peeling_shared.h"
#include "scene/obscurance_shared.h"

layout(binding = kPeelLayersUnit) uniform sampler2DArray u_layers;
uniform int u_peel_resolution;
uniform int u_layer_count;
uniform int u_truncated;  // peeling stopped at max_layers: surfaces beyond the last layer are unknown
uniform int u_atlas_resolution;
uniform int u_spectral;
uniform int u_falloff;
uniform float u_d_max;
uniform vec3 u_average_albedo;
out vec3 v_sample;

ivec2 atlasTexel(vec2 uv) {
  return clamp(ivec2(floor(uv * float(u_atlas_resolution))), ivec2(0), ivec2(u_atlas_resolution - 1));
}

void main() {
  int pixels = u_peel_resolution * u_peel_resolution;
  int layer = gl_VertexID / pixels;
  int pixel = gl_VertexID - layer * pixels;
  ivec2 p = ivec2(pixel % u_peel_resolution, pixel / u_peel_resolution);
  vec4 surface = texelFetch(u_layers, ivec3(p, layer), 0);
  gl_PointSize = 1.0;
  if (surface.z == kPeelEmpty) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the view: clipped
    v_sample = vec3(0.0);
    return;
  }
  int neighbour = surface.z == kPeelFrontFacing ? layer - 1 : layer + 1;
  if (neighbour >= u_layer_count && u_truncated != 0) {
    // The occluder may lie in a layer that was not peeled: no sample rather than a wrong "open".
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    v_sample = vec3(0.0);
    return;
  }
  float d = 3.0e38;  // nothing there: the ray leaves the scene
  vec3 albedo = vec3(0.0);
  if (neighbour >= 0 && neighbour < u_layer_count) {
    vec4 occluder = texelFetch(u_layers, ivec3(p, neighbour), 0);
    if (occluder.z != kPeelEmpty) {
      d = abs(occluder.w - surface.w);
      albedo = texelFetch(u_atlas_albedo, atlasTexel(occluder.xy), 0).rgb;
    }
  }
  v_sample = obscuranceSample(u_spectral != 0, u_falloff, d, u_d_max, albedo, u_average_albedo);
  vec2 texel_centre = (vec2(atlasTexel(surface.xy)) + 0.5) / float(u_atlas_resolution);
  gl_Position = vec4(2.0 * texel_centre - 1.0, 0.0, 1.0);
}
