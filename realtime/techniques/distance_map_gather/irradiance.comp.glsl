// The classic irradiance environment maps of §4.2.2, from the distance map averaged to
// kIrradianceSourceSize² texels per face, every texel's position ignored (all of it seen from o):
// cube 0 the diffuse irradiance I(N) = Σ L(ω)(N·ω)⁺Δω, cube 1 the glossy map
// G(R) = Σ L(ω)(n+2)/(2π)((R·ω)⁺)ⁿΔω, the normalised lobe of the object's Phong exponent n; Δω
// each source texel's exact solid angle (cubeTexelExactSolidAngle: the sum over the cube is 4π).
#include "realtime/gpu_scene/brdf_shared.h"
#include "realtime/techniques/distance_map_gather/distance_map_gather_shared.h"

layout(local_size_x = kIrradianceGroupSize, local_size_y = kIrradianceGroupSize) in;

layout(binding = kLowResMapUnit) uniform samplerCubeArray u_source;
layout(binding = kImageDestinationUnit, rgba32f) uniform writeonly imageCubeArray u_destination;

uniform float u_exponent;  // n of the object's lobe

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);  // z: 6·cube + face
  int cube = texel.z / 6, face = texel.z % 6;
  vec3 axis = normalize(cubeTexelVector(face, texel.x, texel.y, kIrradianceMapSize));
  vec3 sum = vec3(0.0);
  for (int source_face = 0; source_face < 6; ++source_face)
    for (int j = 0; j < kIrradianceSourceSize; ++j)
      for (int i = 0; i < kIrradianceSourceSize; ++i) {
        vec3 direction =
            normalize(cubeTexelVector(source_face, i, j, kIrradianceSourceSize));
        float c = max(dot(axis, direction), 0.0);
        if (c <= 0.0) continue;
        float weight = cube == 0 ? c : (u_exponent + 2.0) * 0.5 * kInvPi * pow(c, u_exponent);
        vec3 radiance = textureLod(u_source, vec4(direction, 0.0), 0.0).rgb;
        sum += radiance * weight * cubeTexelExactSolidAngle(i, j, kIrradianceSourceSize);
      }
  imageStore(u_destination, texel, vec4(sum, 1.0));
}
