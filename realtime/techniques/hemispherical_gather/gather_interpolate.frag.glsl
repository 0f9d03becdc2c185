// One bounce of indirect light at every pixel: the irradiance of the four gather points around
// it, weighted bilinearly and by how well their normals and planes agree with the pixel's (so
// light does not leak across a corner), times the diffuse albedo over π, added into the frame.
// Irradiance is smooth on a surface but not across its edges, so interpolation is the error
// this pass adds (the paper caches samples in meshes instead, §3.2).
#include "realtime/techniques/hemispherical_gather/hemispherical_gather_shared.h"
#include "realtime/techniques/hemispherical_gather/gather_point.glsl"

layout(binding = kGatherIrradianceUnit) uniform sampler2D u_irradiance;
layout(binding = kGBufferAlbedoUnit) uniform sampler2D u_gbuffer_albedo;
uniform float u_plane_tolerance;  // distance off a gather point's plane that still counts as on it
layout(location = 0) out vec4 o_radiance;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ShadedSurface s;
  if (!shadedSurface(pixel, s)) discard;
  // The cell coordinates of the pixel centre, gather points at integer positions.
  vec2 cell = (vec2(pixel) + 0.5 - 0.5 * float(u_spacing)) / float(u_spacing);
  ivec2 base = ivec2(floor(cell));
  vec2 f = cell - vec2(base);
  // Three tries, each less strict, so that a pixel whose four neighbours all lie on other surfaces
  // (a small object between gather points) still gets the nearest estimate there is.
  vec3 sum = vec3(0.0);
  float total = 0.0;
  for (int strictness = 2; strictness >= 0 && total <= 0.0; --strictness)
    for (int j = 0; j <= 1; ++j)
      for (int i = 0; i <= 1; ++i) {
        ivec2 c = clamp(base + ivec2(i, j), ivec2(0), u_grid - 1);
        GatherFrame g;
        if (!gatherFrame(c.y * u_grid.x + c.x, g)) continue;
        float w = max((i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y), 1e-6);
        if (strictness >= 1) w *= pow(max(dot(g.n, s.n), 0.0), 8.0);
        if (strictness >= 2) w *= abs(dot(s.p - g.origin, g.n)) < u_plane_tolerance ? 1.0 : 0.0;
        sum += w * texelFetch(u_irradiance, c, 0).rgb;
        total += w;
      }
  if (total <= 0.0) discard;
  vec3 albedo = texelFetch(u_gbuffer_albedo, pixel, 0).rgb;
  o_radiance = vec4(albedo * (1.0 / 3.14159265358979) * sum / total, 0.0);
}
