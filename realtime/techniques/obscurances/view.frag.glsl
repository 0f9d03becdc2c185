// The camera's view of the obscurances (book §10.2's ObscurancePS, without its direct term, which
// the shared surface lighting adds): Lᵃ·a(x)·W(x), optionally weighted by the distance to the
// light (Fig. 10.6; obscurances_technique.h, "Light weighting"), or W(x) itself for output =
// obscurance. The atlas holds the front side of each surface, so a back face shows nothing.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/atlas/atlas_maps.glsl"
#include "realtime/techniques/obscurances/obscurances_shared.h"

layout(binding = kObscuranceMapUnit) uniform sampler2D u_obscurance;
uniform int u_show_obscurance;
uniform vec3 u_ambient;  // Lᵃ
uniform int u_light_weighting;
uniform vec3 u_light_position;
uniform float u_weight_offset;  // h² of the weight 1/(|x − p|² + h²)
uniform float u_weight_scale;   // 1 / its area mean
in vec2 v_atlas_uv;
in vec3 v_world;
flat in vec3 v_normal;
layout(location = 0) out vec4 o_radiance;

void main() {
  bool front = dot(v_normal, camera.position.xyz - v_world) > 0.0;
  vec3 w = texture(u_obscurance, v_atlas_uv).rgb;
  vec3 radiance = w;
  if (u_show_obscurance == 0) {
    radiance = u_ambient * texture(u_atlas_albedo, v_atlas_uv).rgb * w;
    if (u_light_weighting != 0) {
      vec3 to_light = u_light_position - v_world;
      radiance *= u_weight_scale / (dot(to_light, to_light) + u_weight_offset);
    }
  }
  o_radiance = vec4(front ? radiance : vec3(0.0), 1.0);
}
