// The once-reflected light a gather view sees: the radiance atlas of the directly lit scene (ρ/π
// times the direct irradiance, no emission: light seen straight from an emitter is direct light,
// which the frame's own direct pass adds).
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"

layout(binding = kRadianceAtlasUnit) uniform sampler2D u_radiance_atlas;
in vec2 v_atlas_uv;
in vec3 v_world;
flat in vec3 v_normal;
layout(location = 0) out vec4 o_radiance;

void main() {
  o_radiance = vec4(texture(u_radiance_atlas, v_atlas_uv).rgb, 1.0);
}
