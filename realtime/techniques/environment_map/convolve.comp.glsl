// One texel of one convolved map (book §4.2.2, the sums after eq. 4.2), over every cell i of the
// downsampled environment. The irradiance layer (u_exponent < 0) sums
//   E(n) = Σ_i L_i · max(0, n · W_i),   W_i = ∫_cell ω dω,
// which is Σ L_i ∫_cell (n·ω) dω exactly where the cell lies wholly above the horizon of n (the
// cosine is linear in ω), and clamps only the cells the horizon crosses. A glossy layer of Phong
// exponent m sums the normalised lobe about the query direction R
//   G(R) = (m + 2)/(2π) · Σ_i L_i · max(0, R · ω_i)^(m+1) · Δω_i,
// ω_i the cell's mean direction: the modified Phong lobe with the cosine to the normal taken as
// the cosine to R (exact when R is the normal; README.md, "Glossy maps").
#include "realtime/techniques/environment_map/environment_map_shared.h"
#include "realtime/gpu_scene/brdf_shared.h"

layout(local_size_x = kConvolutionGroupSize, local_size_y = kConvolutionGroupSize) in;

layout(binding = kConvolutionRadianceUnit) uniform sampler2D u_radiance;
layout(binding = kConvolutionCellsUnit) uniform sampler2D u_cells;
layout(binding = kImageDestinationUnit, rgba32f) uniform writeonly image2DArray u_maps;

uniform int u_layer;
uniform float u_exponent;  // the Phong exponent m of a glossy layer; < 0 for the irradiance

void main() {
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_maps).xy;
  if (texel.x >= size.x || texel.y >= size.y) return;
  // The texel's map direction (latLongDirection): φ = 2πu at the column's centre, θ = πv with
  // the rows from pole to pole inclusive (row 0 straight up, the last straight down), so that a
  // normal at a pole, a horizontal surface's, reads the irradiance of exactly that direction
  // rather than clamping to a row some degrees off whose value depends on the azimuth.
  vec2 uv = vec2((float(texel.x) + 0.5) / float(size.x), float(texel.y) / float(size.y - 1));
  float phi = 2.0 * uv.x / kInvPi, theta = uv.y / kInvPi;
  vec3 axis = vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));

  ivec2 cells = textureSize(u_radiance, 0);
  vec3 sum = vec3(0.0);
  for (int y = 0; y < cells.y; ++y)
    for (int x = 0; x < cells.x; ++x) {
      vec3 radiance = texelFetch(u_radiance, ivec2(x, y), 0).rgb;
      vec4 cell = texelFetch(u_cells, ivec2(x, y), 0);
      if (u_exponent < 0.0) {
        sum += radiance * max(0.0, dot(axis, cell.xyz));
      } else {
        float c = max(0.0, dot(axis, normalize(cell.xyz)));
        sum += radiance * (pow(c, u_exponent + 1.0) * cell.w);
      }
    }
  if (u_exponent >= 0.0) sum *= (u_exponent + 2.0) * 0.5 * kInvPi;
  imageStore(u_maps, ivec3(texel, u_layer), vec4(sum, 1.0));
}
