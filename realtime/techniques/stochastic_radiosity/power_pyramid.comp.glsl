// Up to kPyramidLevelsPerPass levels of the power pyramid in one pass: each texel the sum of the
// four below it (Barsi & Jakab sum four texels; the book allows sum or average: a sum keeps the
// top texel equal to Φ). An invocation owns one texel of the pass's highest level and sums the
// block below it level by level in a local array (a 16×16 block of the finer level for four
// levels), adding the four children in the order one pass per level added them. No shared memory:
// llvmpipe runs work-group barriers as coroutine switches.
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_shared.h"

layout(local_size_x = kPyramidGroupSize, local_size_y = kPyramidGroupSize) in;
layout(binding = kImageSourceUnit, r32f) uniform readonly image2D u_finer;
layout(binding = kImageDestinationUnit + 0, r32f) uniform writeonly image2D u_level1;
layout(binding = kImageDestinationUnit + 1, r32f) uniform writeonly image2D u_level2;
layout(binding = kImageDestinationUnit + 2, r32f) uniform writeonly image2D u_level3;
layout(binding = kImageDestinationUnit + 3, r32f) uniform writeonly image2D u_level4;
uniform int u_levels;  // levels this pass writes, 1..kPyramidLevelsPerPass
uniform ivec2 u_top_size;  // texels of the highest of them

void storeLevel(int level, ivec2 texel, float sum) {
  if (level == 1) imageStore(u_level1, texel, vec4(sum));
  else if (level == 2) imageStore(u_level2, texel, vec4(sum));
  else if (level == 3) imageStore(u_level3, texel, vec4(sum));
  else imageStore(u_level4, texel, vec4(sum));
}

float sumOfFour(float a, float b, float c, float d) {
  return a + b + c + d;  // children (0,0), (1,0), (0,1), (1,1)
}

void main() {
  ivec2 top = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(top, u_top_size))) return;
  // The block's texels of each level, rows of 8 (level 1: up to 8×8, level 2: 4×4, level 3: 2×2).
  float sums[2][64];
  int n = 1 << (u_levels - 1);  // texels of the first level per side of the block
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      ivec2 c = top * n + ivec2(x, y), f = 2 * c;
      float sum = sumOfFour(imageLoad(u_finer, f).r, imageLoad(u_finer, f + ivec2(1, 0)).r,
                            imageLoad(u_finer, f + ivec2(0, 1)).r,
                            imageLoad(u_finer, f + ivec2(1, 1)).r);
      sums[0][y * 8 + x] = sum;
      storeLevel(1, c, sum);
    }
  for (int level = 2; level <= u_levels; ++level) {
    int from = (level - 2) % 2, to = 1 - from;
    n /= 2;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        int i = 2 * y * 8 + 2 * x;
        float sum = sumOfFour(sums[from][i], sums[from][i + 1], sums[from][i + 8],
                              sums[from][i + 9]);
        sums[to][y * 8 + x] = sum;
        storeLevel(level, top * n + ivec2(x, y), sum);
      }
  }
}
