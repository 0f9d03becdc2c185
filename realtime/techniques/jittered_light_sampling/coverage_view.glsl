// The camera of a point x that samples an area light (light_coverage_sampler.h): looking along
// the light plane's normal towards it, the image plane axes along the light's first edge and its
// bitangent, the window the light's bounding rectangle in its plane. The light's triangles are
// the first u_light_vertices corners of the coverage buffer, the occluders' follow.
#include "realtime/techniques/jittered_light_sampling/jittered_light_sampling_shared.h"

layout(std430, binding = kCoverageTrianglesBinding) readonly buffer CoverageTriangles {
  vec4 corners[];
};
uniform int u_light_vertices;

struct CoverageView {
  vec3 x;
  vec3 right, up, forward;  // forward: towards the light's plane
  float d;                  // distance from x to the light's plane
  vec4 window;              // u0, v0, u1, v1: the light's bounds in the plane, from x's foot
};

// False where x lies in the light's plane (it subtends nothing).
bool coverageView(vec3 x, out CoverageView v) {
  vec3 p0 = corners[0].xyz;
  vec3 normal = normalize(cross(corners[1].xyz - p0, corners[2].xyz - p0));
  float signed_distance = dot(p0 - x, normal);
  v.x = x;
  v.d = abs(signed_distance);
  v.forward = signed_distance > 0.0 ? normal : -normal;
  v.right = normalize(corners[1].xyz - p0);
  v.up = cross(-v.forward, v.right);  // right-handed: right × up = back
  v.window = vec4(1e30, 1e30, -1e30, -1e30);
  for (int i = 0; i < u_light_vertices; ++i) {
    vec2 uv = vec2(dot(corners[i].xyz - x, v.right), dot(corners[i].xyz - x, v.up));
    v.window.xy = min(v.window.xy, uv);
    v.window.zw = max(v.window.zw, uv);
  }
  return v.d > 1e-6 * length(corners[0].xyz - x);
}

// Clip coordinates of p: an off-axis perspective projection onto the window, with the near
// plane well before any occluder between x and the light and the far plane just past the light
// (at depth d).
vec4 coverageClip(CoverageView v, vec3 p) {
  vec3 q = p - v.x;
  float t = dot(q, v.forward);
  float near = 1e-3 * v.d, far = 1.01 * v.d;
  vec2 uv = vec2(dot(q, v.right), dot(q, v.up));
  vec2 size = v.window.zw - v.window.xy;
  return vec4(2.0 * (uv * v.d - v.window.xy * t) / size - t,
              (far + near) / (far - near) * t - 2.0 * far * near / (far - near), t);
}
