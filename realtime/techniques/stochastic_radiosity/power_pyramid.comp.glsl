// One level of the power pyramid: each texel the sum of the four below it (Barsi & Jakab sum
// four texels; the book allows sum or average: a sum keeps the top texel equal to Φ).
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_shared.h"

layout(local_size_x = kPyramidGroupSize, local_size_y = kPyramidGroupSize) in;
layout(binding = kImageSourceUnit, r32f) uniform readonly image2D u_finer;
layout(binding = kImageDestinationUnit, r32f) uniform writeonly image2D u_coarser;

void main() {
  ivec2 c = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(c, imageSize(u_coarser)))) return;
  ivec2 f = 2 * c;
  float sum = imageLoad(u_finer, f).r + imageLoad(u_finer, f + ivec2(1, 0)).r +
              imageLoad(u_finer, f + ivec2(0, 1)).r + imageLoad(u_finer, f + ivec2(1, 1)).r;
  imageStore(u_coarser, c, vec4(sum));
}
