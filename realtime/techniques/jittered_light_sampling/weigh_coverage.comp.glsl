// The technique's weighting (the paper reads the image back and weighs it on the CPU; here the
// GPU does it where the image lies): one work group per point of the batch sums, over the visible
// samples of its coverage layer, the light's radiance times the BRDF, the receiver's cosine and
// the solid angle of the sample's stratum (eq. 2 with eq. 3 evaluated at the sample), and adds
// it into the point's pixel of the frame.
#include "realtime/techniques/jittered_light_sampling/gbuffer_point.glsl"
#include "realtime/gpu_scene/brdf.glsl"

layout(local_size_x = kWeighGroupSize) in;
layout(binding = kCoverageUnit) uniform usampler2DArray u_coverage;
layout(rgba32f, binding = kImageDestinationUnit) uniform image2D u_target;
uniform int u_first_point;
uniform int u_size;
uniform int u_samples;         // 0: pixel centres (regular and occlusion query); else jittered
uniform bool u_equal_weights;  // the occlusion query's estimate: every visible pixel alike
uniform uint u_seed;
uniform vec3 u_emission;       // the light's radiance

shared vec3 partial[kWeighGroupSize];

void main() {
  const int layer = int(gl_WorkGroupID.x);
  const int point = u_first_point + layer;
  const uint lane = gl_LocalInvocationIndex;
  ShadedSurface s;
  vec3 x;
  CoverageView view;
  bool lit = gbufferSurface(point, s, x) && coverageView(x, view);
  vec3 sum = vec3(0.0);
  if (lit) {
    const vec2 cell = (view.window.zw - view.window.xy) / float(u_size);
    const float stratum = cell.x * cell.y / float(max(u_samples, 1));
    const float window_solid_angle = u_equal_weights ? windowSolidAngle(view.window, view.d) : 0.0;
    const vec3 diffuse = materialDiffuse(s.material), specular = materialSpecular(s.material);
    const float exponent = materialExponent(s.material);
    const bool phong = materialIsPhong(s.material);
    for (int i = int(lane); i < u_size * u_size; i += kWeighGroupSize) {
      uint bits = texelFetch(u_coverage, ivec3(i % u_size, i / u_size, layer), 0).r;
      while (bits != 0u) {
        const int k = findLSB(bits);
        bits &= bits - 1u;
        const vec2 offset = coverageSampleOffset(u_seed, uint(point), uint(i), k, u_samples);
        const vec2 uv = view.window.xy + (vec2(i % u_size, i / u_size) + offset) * cell;
        const vec3 q = uv.x * view.right + uv.y * view.up + view.d * view.forward;
        const float r2 = dot(q, q);
        const vec3 wi = q * inversesqrt(r2);
        const float solid_angle = u_equal_weights ? window_solid_angle / float(u_size * u_size)
                                                  : stratum * view.d / (r2 * sqrt(r2));
        sum += evaluateBrdf(diffuse, specular, exponent, phong, s.n, s.wo, wi) *
               max(dot(s.n, wi), 0.0) * solid_angle;
      }
    }
  }
  partial[lane] = sum;
  barrier();
  for (uint stride = kWeighGroupSize / 2; stride > 0u; stride /= 2u) {
    if (lane < stride) partial[lane] += partial[lane + stride];
    barrier();
  }
  if (lane == 0u && lit) {
    const ivec2 pixel = gbufferPixel(point);
    imageStore(u_target, pixel, imageLoad(u_target, pixel) + vec4(partial[0] * u_emission, 0.0));
  }
}
