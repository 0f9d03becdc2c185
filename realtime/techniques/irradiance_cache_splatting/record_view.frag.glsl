// What a record's view sees at a pixel: the once-reflected radiance of the directly lit scene
// (rgb) and the distance to it (a), which the harmonic mean distance and the translation gradient
// need.
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_shared.h"

layout(binding = kSplatRadianceAtlasUnit) uniform sampler2D u_radiance_atlas;
in vec2 v_atlas_uv;
in vec3 v_world;
flat in vec3 v_origin;
layout(location = 0) out vec4 o_radiance_distance;

void main() {
  o_radiance_distance =
      vec4(texture(u_radiance_atlas, v_atlas_uv).rgb, length(v_world - v_origin));
}
