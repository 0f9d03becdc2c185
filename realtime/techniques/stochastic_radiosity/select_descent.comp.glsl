// The hierarchical descent (book §7.1.1, SelectTexel; Barsi & Jakab §3.1), one invocation per
// selection, in one pass over every level: starting at the 1×1 top with r = u·Φ, each level
// picks one of the current texel's four children with probability proportional to its power, by
// comparing the running sum of the children with the remaining selection value r, then goes on
// with r − (the children before the chosen one). A child is chosen when
// cmin ≤ r < cmin + power, so a child without power is never chosen; if rounding leaves r at or
// above the children's sum, the last child with power is taken (the book's code would fall
// through to the fourth child even when it has none).
#include "realtime/techniques/stochastic_radiosity/selection.glsl"

layout(local_size_x = kDescentGroupSize) in;
layout(binding = kRadiosityPowerUnit) uniform sampler2D u_power;  // the pyramid, level 0 the texels
uniform int u_count;
uniform int u_top;  // the pyramid's 1×1 level

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= u_count) return;
  Shooter s = shooters[i];
  s.total_power = texelFetch(u_power, ivec2(0), u_top).r;
  s.remaining = s.u * s.total_power;
  s.texel = s.total_power > 0.0 ? ivec2(0) : ivec2(-1);
  const ivec2 offsets[4] = ivec2[4](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 1));
  for (int level = u_top - 1; level >= 0 && s.texel.x >= 0; --level) {
    float cmin = 0.0;
    int chosen = -1, last_with_power = 0;
    float chosen_min = 0.0, chosen_power = 0.0, last_min = 0.0, last_power = 0.0;
    for (int k = 0; k < 4; ++k) {
      float power = texelFetch(u_power, 2 * s.texel + offsets[k], level).r;
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
  }
  shooters[i] = s;
}
