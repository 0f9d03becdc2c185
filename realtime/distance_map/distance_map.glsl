// Reading distance maps (book §6.1): the objects' block, a map's texel in a direction, the four
// searches of a ray's hit, and which object a scene triangle belongs to. The maps are one
// cube-map array at kDistanceMapUnit, layer 6·object + face; a texel holds the radiance of the
// surface it sees (rgb) and that surface's distance from the object's reference point o (a).
// Positions passed to the searches are relative to o.
#include "realtime/distance_map/distance_map_shared.h"

layout(binding = kDistanceMapUnit) uniform samplerCubeArray u_distance_maps;
layout(std140, binding = kDistanceMapObjectsBinding) uniform DistanceMapObjectBlock {
  DistanceMapBlock u_distance_map;
};

// Level 0 always: the book's texCUBElod, and no derivatives are taken inside a loop.
vec4 distanceMapTexel(int object, vec3 direction) {
  return textureLod(u_distance_maps, vec4(direction, float(object)), 0.0);
}

// The object the scene triangle t belongs to, or −1.
int distanceMapObjectOf(int triangle) {
  for (int k = 0; k < u_distance_map.counts.x; ++k) {
    ivec4 range = u_distance_map.objects[k].triangles;
    if (triangle >= range.x && triangle < range.y) return k;
  }
  return -1;
}

vec3 distanceMapReferencePoint(int object) {
  return u_distance_map.objects[object].reference_point.xyz;
}

// §6.1.2's march from x (relative to o) along unit R: samples t = Δt/2, 3Δt/2, … of the line
// between the ray's start and end projected onto the unit sphere, Δt = 1/steps, their ray
// parameters d(t) = |x|·t/(1 − t), each compared with the map's distance in its direction. The
// stopping rule is the book's: the march ends once it has seen an undershooting sample
// (|r| < |r′|) and an overshooting one (|r| ≥ |r′|), keeping the last of each (d_l, d_p and their
// ratios). Returns whether both were seen: a ray that only undershoots leaves through a texel
// that sees the sky, or is not bracketed within the steps.
bool distanceMapLinearSearch(int object, vec3 x, vec3 R, int steps, out float d_l, out float d_p,
                             out float l_ratio, out float p_ratio) {
  float origin_distance = length(x);
  bool undershoot = false, overshoot = false;
  d_l = 0.0;
  d_p = 0.0;
  l_ratio = 0.0;
  p_ratio = 0.0;
  float dt = 1.0 / float(steps);
  for (int i = 0; i < steps && !(undershoot && overshoot); ++i) {
    float t = (float(i) + 0.5) * dt;
    float d = linearSearchParameter(origin_distance, t);
    vec3 r = x + R * d;
    float ratio = length(r) / distanceMapTexel(object, r).a;
    if (ratio < 1.0) {
      d_l = d;
      l_ratio = ratio;
      undershoot = true;
    } else {
      d_p = d;
      p_ratio = ratio;
      overshoot = true;
    }
  }
  return undershoot && overshoot;
}

// The point (relative to o) where the ray x + R·d (R unit) meets the surfaces the map holds, by
// `method` (kSearch…). A ray from o itself needs no search: every method returns the map's
// point in direction R, which is exact.
vec3 distanceMapHit(int object, vec3 x, vec3 R, int method, int linear_steps, int secant_steps) {
  float environment_distance = distanceMapTexel(object, R).a;
  // Environment mapping: the map's point in the ray's direction, as if x were o.
  if (method == kSearchEnvironment || dot(x, x) == 0.0) return R * environment_distance;
  if (method == kSearchParallax) {
    // Eq. 6.1: the surface through that point taken perpendicular to R.
    return x + R * (environment_distance - dot(x, R));
  }
  float d_l, d_p, l_ratio, p_ratio;
  // Unbracketed: the ray leaves through the sky's texels (or past the steps), which environment
  // mapping reads in its direction.
  if (!distanceMapLinearSearch(object, x, R, linear_steps, d_l, d_p, l_ratio, p_ratio))
    return R * environment_distance;
  vec3 hit = x + R * d_p;
  if (method == kSearchLinear) return hit;
  // §6.1.3: secant steps, keeping one undershooting and one overshooting parameter; a step
  // within 10⁻⁴ of the surface ends the refinement (the book's code).
  for (int i = 0; i < secant_steps; ++i) {
    float d = secantParameter(d_l, d_p, l_ratio, p_ratio);
    hit = x + R * d;
    float ratio = length(hit) / distanceMapTexel(object, hit).a;
    if (ratio < 0.9999) {
      d_l = d;
      l_ratio = ratio;
    } else if (ratio > 1.0001) {
      d_p = d;
      p_ratio = ratio;
    } else {
      break;
    }
  }
  return hit;
}
