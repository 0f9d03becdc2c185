// Whether a receiver is the surface the shooter sees in its direction (the book's depth
// comparison): its distance must not exceed the stored one by more than a tolerance relative to
// the distance: a constant part (float precision, kRelativeEpsilon) plus a slope part: one map
// texel spans an angle of about 2/u_map_size (the hemisphere's texels grow by 1/cos θ towards the
// rim), over which a receiver seen at angle θx from its normal changes distance by
// distance·angle·tan θx.
#include "realtime/techniques/stochastic_radiosity/visibility_projection.glsl"

#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_shared.h"

layout(binding = kVisibilityUnit) uniform sampler2DArray u_visibility;  // distance, 1e30: nothing drawn
const float kRelativeEpsilon = 0.005;
const float kMaxSlope = 20.0;  // tan of ~87°: grazing receivers get at most this slope

float visibilityTexelAngle(vec3 l, float distance) {
  float angle = 2.0 / float(u_map_size);
#ifndef HEMICUBE
  angle /= max(l.z / distance, 0.05);
#endif
  return angle;
}

bool visibleFromShooter(vec3 l, float cos_receiver) {
  float distance = length(l);
#ifdef HEMICUBE
  int face = hemicubeFace(l);
  vec3 c = hemicubeFaceCoordinates(l, face);
  vec2 ndc = c.xy / c.z;
  ivec2 texel = ivec2((ndc * 0.5 + 0.5) * vec2(u_map_size, hemicubeFaceRows(face)));
  texel = clamp(texel, ivec2(0), ivec2(u_map_size - 1, hemicubeFaceRows(face) - 1));
  float stored = texelFetch(u_visibility, ivec3(texel, face), 0).r;
#else
  ivec2 texel = ivec2((hemisphereCoordinates(l) * 0.5 + 0.5) * float(u_map_size));
  texel = clamp(texel, ivec2(0), ivec2(u_map_size - 1));
  float stored = texelFetch(u_visibility, ivec3(texel, 0), 0).r;
#endif
  float slope = min(sqrt(max(1.0 - cos_receiver * cos_receiver, 0.0)) / max(cos_receiver, 1e-3), kMaxSlope);
  float tolerance = distance * (kRelativeEpsilon + visibilityTexelAngle(l, distance) * slope);
  return distance <= stored + tolerance;
}
