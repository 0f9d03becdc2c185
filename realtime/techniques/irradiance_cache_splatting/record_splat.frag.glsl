// The record's contribution at the surface a pixel of its zone sees: Ward's full weight, and the
// record's irradiance extrapolated by its gradients, as (w·E, w); additive blending sums every
// record's. Pixels where the weight is at most 1/a take nothing.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gbuffer/shaded_surface.glsl"
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_shared.h"
#include "realtime/techniques/irradiance_cache_splatting/record_face.glsl"

uniform float u_accuracy;
flat in int v_record;
layout(location = 0) out vec4 o_weighted;

void main() {
  ShadedSurface s;
  if (!shadedSurface(ivec2(gl_FragCoord.xy), s)) discard;
  IrradianceRecord record = records[v_record];
  float w = recordWeight(record, s.p, s.n);
  if (w <= 1.0 / u_accuracy) discard;
  o_weighted = vec4(w * recordIrradiance(record, s.p, s.n), w);
}
