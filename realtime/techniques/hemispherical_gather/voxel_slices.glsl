// Looking the voxel slices up along a ray (§5.4): the paper draws a full-screen quad per slice
// face and finds, per fragment, where the pixel's direction S meets the slice's plane (eq. 7–9)
// and which texel that is (eq. 10), keeping the nearest by depth test; here one fragment walks
// the planes of each axis in order from the point and stops at the first face texel with
// something in it, the same answer without drawing the faces behind it. The planes within
// u_near_box of the point are left to the near geometry.
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"

layout(binding = kVoxelSlicesUnit) uniform sampler2DArray u_voxel_slices;
uniform int u_slices;
uniform vec3 u_bounds_min;
uniform vec3 u_bounds_max;

// Distance along `direction` (unit) from `origin` to the first slice texel with something in it
// beyond the near box, and its radiance; false when the ray meets none.
bool traceSlices(vec3 origin, vec3 direction, vec3 near_box, out float distance,
                 out vec3 radiance) {
  vec3 extent = u_bounds_max - u_bounds_min;
  distance = 1e30;
  for (int axis = 0; axis < 3; ++axis) {
    float d = direction[axis];
    if (abs(d) < 1e-6) continue;
    int side = d > 0.0 ? 0 : 1;  // entering slabs from their low side when going up the axis
    float spacing = extent[axis] / float(u_slices);
    float start = (origin[axis] - u_bounds_min[axis]) / spacing;  // in slab units
    float skip = near_box[axis] / spacing;
    // The first plane beyond the near box in the ray's direction, then one plane per slab.
    int plane = d > 0.0 ? int(ceil(start + skip)) : int(floor(start - skip));
    for (int step = 0; step <= u_slices; ++step, plane += d > 0.0 ? 1 : -1) {
      int slab = d > 0.0 ? plane : plane - 1;
      if (slab < 0 || slab >= u_slices) break;
      float t = (u_bounds_min[axis] + float(plane) * spacing - origin[axis]) / d;
      if (t >= distance) break;  // another axis already found something nearer
      vec3 p = (origin + t * direction - u_bounds_min) / extent;
      vec2 uv = axis == 0 ? p.yz : (axis == 1 ? p.zx : p.xy);
      if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) break;  // left the bounds
      vec4 texel = texture(u_voxel_slices, vec3(uv, float((2 * axis + side) * u_slices + slab)));
      if (texel.a > 0.5) {
        distance = t;
        radiance = texel.rgb;
        break;
      }
    }
  }
  return distance < 1e30;
}
