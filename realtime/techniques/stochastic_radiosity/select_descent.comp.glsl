// One step of the hierarchical descent (book §7.1.1, SelectTexel; Barsi & Jakab §3.1): from the
// texel chosen on the level above, pick one of its four children on level u_level with
// probability proportional to its power, by comparing the running sum of the children with the
// remaining selection value r, then continue with r − (the children before the chosen one).
// The first pass starts at the 1×1 top with r = u·Φ. A child is chosen when
// cmin ≤ r < cmin + power, so a child without power is never chosen; if rounding leaves r at or
// above the children's sum, the last child with power is taken (the book's code would fall
// through to the fourth child even when it has none).
#include "realtime/techniques/stochastic_radiosity/selection.glsl"

layout(local_size_x = kDescentGroupSize) in;
layout(binding = kImageSourceUnit, r32f) uniform readonly image2D u_level;  // the level descended into
layout(binding = kImageDestinationUnit, r32f) uniform readonly image2D u_top;  // 1×1, first pass
uniform bool u_first;
uniform int u_count;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= u_count) return;
  Shooter s = shooters[i];
  if (u_first) {
    s.total_power = imageLoad(u_top, ivec2(0)).r;
    s.remaining = s.u * s.total_power;
    s.texel = s.total_power > 0.0 ? ivec2(0) : ivec2(-1);
  }
  if (s.texel.x < 0) {
    shooters[i] = s;
    return;
  }
  const ivec2 offsets[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 1));
  float cmin = 0.0;
  int chosen = -1, last_with_power = 0;
  float chosen_min = 0.0, chosen_power = 0.0, last_min = 0.0, last_power = 0.0;
  for (int k = 0; k < 4; ++k) {
    float power = imageLoad(u_level, 2 * s.texel + offsets[k]).r;
    if (power > 0.0) {
      last_with_power = k;
      last_min = cmin;
      last_power = power;
      if (chosen < 0 && s.remaining < cmin + power) {
        chosen = k;
        chosen_min = cmin;
        chosen_power = power;
      }
    }
    cmin += power;
  }
  if (chosen < 0) {  // rounding: r ≥ the children's sum
    chosen = last_with_power;
    chosen_min = last_min;
    chosen_power = last_power;
  }
  s.texel = 2 * s.texel + offsets[chosen];
  s.remaining = clamp(s.remaining - chosen_min, 0.0, chosen_power);
  s.power = chosen_power;
  shooters[i] = s;
}
