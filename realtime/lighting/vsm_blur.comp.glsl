// One direction of the separable box filter over a batch's variance shadow maps (the book's 5×5
// texel filter, §4.1.3, Fig. 4.5), every drawn layer in one dispatch (work group z: the z-th
// face of the batch's shadow pass; the faces a sample cannot light stay cleared). Cube maps are
// filtered face by face; taps clamp at face edges.
//
// Each invocation filters a segment of kVsmBlurSegment texels along one line (a row, or a column)
// and keeps the window's 2r+1 taps in registers, so a texel is loaded once, not 2r+1 times; the
// window is summed afresh for every texel in the order of a direct sum (no running sum, which
// would carry the cleared maps' huge moments into their neighbours as rounding error).
// VSM_BLUR_RADIUS (r) is compiled in, so the window's loops unroll into registers.
#include "realtime/lighting/lighting_shared.h"
#include "realtime/lighting/light_sample_shared.h"

layout(local_size_x = kVsmBlurGroupSize, local_size_y = 1, local_size_z = 1) in;
// The batch's moments: a cube map for one point sample, a cube-map array for more, a 2D array
// for directional samples (shadow_maps.cpp); each addressed by (x, y, layer).
#if defined(POINT_LIGHT) && defined(SINGLE_CUBE_MAP)
#define MOMENTS_IMAGE imageCube
#elif defined(POINT_LIGHT)
#define MOMENTS_IMAGE imageCubeArray
#else
#define MOMENTS_IMAGE image2DArray
#endif
layout(rg32f, binding = kImageSourceUnit) uniform readonly MOMENTS_IMAGE u_source;
layout(rg32f, binding = kImageDestinationUnit) uniform writeonly MOMENTS_IMAGE u_destination;
layout(std140, binding = kShadowFacesBinding) uniform ShadowFaceBlock {
  ShadowFace u_shadow_faces[kMaxShadowFaces];
};
uniform ivec2 u_step;  // (1,0): along rows, then (0,1): along columns

const int kWidth = 2 * VSM_BLUR_RADIUS + 1;

void main() {
  ShadowFace face = u_shadow_faces[gl_WorkGroupID.z];
  int layer = face.layer_slot.x;
  // Only the texels that can hold anything drawn, and the filter's reach around them: outside
  // them both passes would write back the cleared value they hold (a box mean of equal values),
  // and taps clamp to the range, which ends in cleared texels too.
  ivec2 columns = unpackTexelRange(face.layer_slot.z), rows = unpackTexelRange(face.layer_slot.w);
  ivec2 along = u_step.x == 1 ? columns : rows, across_range = u_step.x == 1 ? rows : columns;
  int line = across_range.x + int(gl_GlobalInvocationID.x);
  if (line >= across_range.y) return;
  ivec2 across = ivec2(1) - u_step;
  int begin = along.x + int(gl_WorkGroupID.y) * kVsmBlurSegment;
  int end = min(begin + kVsmBlurSegment, along.y);
  if (begin >= end) return;
#define TAP(i) imageLoad(u_source, ivec3(u_step * clamp(i, along.x, along.y - 1) + across * line, layer)).rg
  vec2 window[kWidth];  // the taps t − r .. t + r of texel t
  for (int k = 1; k < kWidth; ++k) window[k] = TAP(begin - VSM_BLUR_RADIUS + k - 1);
  for (int t = begin; t < end; ++t) {
    for (int k = 0; k < kWidth - 1; ++k) window[k] = window[k + 1];
    window[kWidth - 1] = TAP(t + VSM_BLUR_RADIUS);
    vec2 sum = vec2(0.0);
    for (int k = 0; k < kWidth; ++k) sum += window[k];
    imageStore(u_destination, ivec3(u_step * t + across * line, layer),
               vec4(sum / float(kWidth), 0.0, 0.0));
  }
#undef TAP
}
