// Hard and PCF shadow maps need depth only; a variance shadow map (book §4.1.3) also stores the
// light distance and its square, to be blurred and read through Chebyshev's inequality.
#include "realtime/lighting/light_space.glsl"
in vec3 v_world;
flat in int v_slot;  // the batch's sample whose map this is
#ifdef VARIANCE_SHADOW_MAP
layout(location = 0) out vec2 o_moments;
#endif

void main() {
#ifdef VARIANCE_SHADOW_MAP
  float d = lightDistance(v_slot, v_world);
  o_moments = vec2(d, d * d);
#endif
}
