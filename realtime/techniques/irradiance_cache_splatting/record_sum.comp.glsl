// A record from its views (one work group per record of the round): irradiance E = Σ L cos θ dω,
// the harmonic mean distance R = Σ w / Σ (w / r) with w = cos θ dω, Ward & Heckbert's gradients in
// a form for any cells: rotation ∇r E = Σ L (n × ω) dω, translation ∇t E = Σ over the boundaries
// between neighbouring pixels a, b of (L_b − L_a) c_e m_e / min(r_a, r_b), where c_e is the
// boundary's cosine-weighted length and m_e the unit direction across it from a to b (the boundary
// moves with the nearer surface, which hides the farther; Ward & Heckbert's stratified formula is
// this sum over the boundaries of its cells). Boundaries between hemicube faces are left out.
//
// A pixel at (x, y) of a face at unit distance, of side δ, subtends dω = δ² / (x² + y² + 1)^(3/2).
// Plane sampling misses the directions beyond its border; as the notes propose, each border pixel
// stands for the part of the hemisphere beyond its outer edge as well: that edge spans δφ of
// azimuth at polar angle θ_b, and the missing part adds L cos² θ_b / 2 · δφ to E (the notes'
// solid angle cos θ_b · δφ, weighted by the cosine for irradiance).
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_shared.h"
#include "realtime/techniques/irradiance_cache_splatting/record_face.glsl"

layout(local_size_x = kRecordSumGroupSize) in;
layout(binding = kRecordViewsUnit) uniform sampler2DArray u_views;
uniform int u_first_record;
uniform int u_faces;
uniform int u_size;
uniform float u_half_width;
uniform bool u_extend_border;

shared float sums[kRecordSums * kRecordSumGroupSize];

float sums_[kRecordSums];

vec4 viewTexel(int i, int j, int layer) {
  return texelFetch(u_views, ivec3(i, j, layer), 0);
}

void addTranslation(vec3 la, vec3 lb, float ra, float rb, float cos_length, vec3 across) {
  float factor = cos_length / max(min(ra, rb), 1e-20);
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) sums_[14 + 3 * c + k] += (lb[c] - la[c]) * factor * across[k];
}

// The boundary at image point e (on the unit-distance plane) between pixel a and its neighbour
// b, the boundary running along `along` (a unit axis of the face) for δ, `towards` pointing
// from a to b.
void addBoundary(RecordFace f, vec3 n, vec2 e, vec3 along, vec3 towards, vec4 a, vec4 b,
                 float delta) {
  vec3 p = e.x * f.right + e.y * f.up + f.forward;
  float distance = length(p);
  vec3 w = p / distance;
  float cos_theta = dot(w, n);
  if (cos_theta <= 0.0) return;
  float angular_length = delta * sqrt(max(1.0 - dot(along, w) * dot(along, w), 0.0)) / distance;
  // The boundary's normal on the sphere: perpendicular to the line of sight and to the boundary
  // (whose image there is `along`), pointing to b's side.
  vec3 across = normalize(cross(w, along));
  if (dot(across, towards) < 0.0) across = -across;
  addTranslation(a.rgb, b.rgb, a.a, b.a, cos_theta * angular_length, across);
}

// The part of the hemisphere beyond a border pixel's outer edge, from e0 to e1 on the plane.
void addBorder(RecordFace f, vec3 n, vec2 e0, vec2 e1, vec4 texel) {
  float cos_border = dot(normalize(0.5 * (e0.x + e1.x) * f.right + 0.5 * (e0.y + e1.y) * f.up +
                                   f.forward),
                         n);
  float delta_phi = acos(clamp(dot(normalize(e0), normalize(e1)), -1.0, 1.0));
  float w = 0.5 * cos_border * cos_border * delta_phi;
  for (int c = 0; c < 3; ++c) sums_[c] += texel[c] * w;
  sums_[3] += w;
  sums_[4] += w / texel.a;
}

void main() {
  const int local = int(gl_WorkGroupID.x);
  const int index = u_first_record + local;
  const uint lane = gl_LocalInvocationIndex;
  for (int k = 0; k < kRecordSums; ++k) sums_[k] = 0.0;
  vec3 n = records[index].normal.xyz;
  const float delta = 2.0 * u_half_width / float(u_size);
  const int face_pixels = u_size * u_size;
  for (int i = int(lane); i < u_faces * face_pixels; i += kRecordSumGroupSize) {
    int face = i / face_pixels, px = i % u_size, py = (i % face_pixels) / u_size;
    int layer = local * u_faces + face;
    RecordFace f = recordFace(n, face);
    vec2 xy = (vec2(px, py) + 0.5) * delta - u_half_width;
    vec3 p = xy.x * f.right + xy.y * f.up + f.forward;
    float r2 = dot(p, p);
    vec3 w = p * inversesqrt(r2);
    float cos_theta = dot(w, n);
    if (cos_theta <= 0.0) continue;
    vec4 texel = viewTexel(px, py, layer);
    float solid_angle = delta * delta / (r2 * sqrt(r2));
    float weight = cos_theta * solid_angle;
    for (int c = 0; c < 3; ++c) sums_[c] += texel[c] * weight;
    sums_[3] += weight;
    sums_[4] += weight / texel.a;
    vec3 rotation = cross(n, w) * solid_angle;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) sums_[5 + 3 * c + k] += texel[c] * rotation[k];
    if (px + 1 < u_size)
      addBoundary(f, n, xy + vec2(0.5 * delta, 0.0), f.up, f.right, texel,
                  viewTexel(px + 1, py, layer), delta);
    if (py + 1 < u_size)
      addBoundary(f, n, xy + vec2(0.0, 0.5 * delta), f.right, f.up, texel,
                  viewTexel(px, py + 1, layer), delta);
    if (u_extend_border) {
      float h = u_half_width, lo = -0.5 * delta, hi = 0.5 * delta;
      if (px == 0) addBorder(f, n, vec2(-h, xy.y + lo), vec2(-h, xy.y + hi), texel);
      if (px == u_size - 1) addBorder(f, n, vec2(h, xy.y + lo), vec2(h, xy.y + hi), texel);
      if (py == 0) addBorder(f, n, vec2(xy.x + lo, -h), vec2(xy.x + hi, -h), texel);
      if (py == u_size - 1) addBorder(f, n, vec2(xy.x + lo, h), vec2(xy.x + hi, h), texel);
    }
  }
  for (int k = 0; k < kRecordSums; ++k) sums[k * kRecordSumGroupSize + int(lane)] = sums_[k];
  barrier();
  for (uint stride = kRecordSumGroupSize / 2; stride > 0u; stride /= 2u) {
    if (lane < stride)
      for (int k = 0; k < kRecordSums; ++k)
        sums[k * kRecordSumGroupSize + lane] += sums[k * kRecordSumGroupSize + lane + stride];
    barrier();
  }
  if (lane != 0u) return;
  float total[kRecordSums];
  for (int k = 0; k < kRecordSums; ++k) total[k] = sums[k * kRecordSumGroupSize];
  records[index].irradiance = vec4(total[0], total[1], total[2], 0.0);
  // No surface seen at all (a lone plane under an empty sky): no distance limits the zone.
  records[index].position_radius.w = total[4] > 0.0 ? total[3] / total[4] : 3.0e38;
  for (int c = 0; c < 3; ++c) {
    vec3 rotation = vec3(total[5 + 3 * c], total[6 + 3 * c], total[7 + 3 * c]);
    vec3 translation = vec3(total[14 + 3 * c], total[15 + 3 * c], total[16 + 3 * c]);
    records[index].rotation[c] = vec4(rotation, 0.0);
    // Ward's gradient is the change along the tangent plane.
    records[index].translation[c] = vec4(translation - dot(translation, n) * n, 0.0);
  }
}
