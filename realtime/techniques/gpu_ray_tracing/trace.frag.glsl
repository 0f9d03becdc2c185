// The Whitted ray tree of every pixel whose visible surface is a mirror or glass (book §5.3, the
// reflection and refraction shaders of Figs. 5.7 and 5.15), traced through the ray-casting
// structure the program was built for (cast_ray.glsl), for one batch of light samples: the
// direct light their shadow maps give every diffuse or glossy end point of the tree, and, with
// u_first_batch, the emission and sky the tree reaches (added once). Paths carry the reference's
// weights (reference/bsdf.cpp): a mirror's exact conductor Fresnel reflectance, a glass's
// dielectric F on reflection and (1 − F)/η² on refraction, total internal reflection, and
// Beer–Lambert absorption on every segment that ends on a glass's back side. Depth-first, with
// one pending sibling per level; a specular vertex past MAX_DEPTH ends its path (the class
// L D? S{0,MAX_DEPTH} E).
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gpu_scene/brdf.glsl"
#include "realtime/gbuffer/gbuffer_maps.glsl"
#include "realtime/lighting/shadowed_irradiance.glsl"
#include "realtime/ray_casting/cast_ray.glsl"
#include "realtime/techniques/gpu_ray_tracing/gpu_ray_tracing_shared.h"
#include "scene/fresnel_shared.h"

layout(binding = kTraceTrianglesUnit) uniform samplerBuffer u_trace_triangles;

uniform vec3 u_set_origin;    // IvmTriangleSet::origin: rays are cast relative to it
uniform float u_ray_offset;   // kTraceRayOffsetFraction of the scene's diagonal
uniform vec3 u_sky_radiance;  // what a ray that leaves the scene sees
uniform bool u_first_batch;   // add emission and sky, and replace what the pixel held

layout(location = 0) out vec4 o_radiance;

// A ray still to trace: where from, where to, the weight of its light in the pixel, and the
// specular vertices before it.
struct PendingRay {
  vec3 origin;
  vec3 direction;
  vec3 weight;
  int depth;
};

// A hit's surface: the point, the geometric and shading normals on the side the ray came from,
// whether that is the front, and the material.
struct TraceSurface {
  vec3 p;
  vec3 ng;
  vec3 ns;
  bool front;
  uint material;
};

TraceSurface surfaceAt(vec3 origin, vec3 d, RayCastHit hit) {
  int base = kTraceTriangleTexels * int(hit.triangle);
  vec4 t0 = texelFetch(u_trace_triangles, base);
  TraceSurface s;
  s.p = origin + hit.t * d;
  s.material = uint(t0.w);
  s.front = dot(t0.xyz, -d) >= 0.0;
  // The shading normal as the reference interpolates it (reference/triangle_table.cpp): the
  // vertices' normals by the hit's barycentric weights, renormalised, and the geometric normal
  // where the mesh is flat or the interpolation leaves the front hemisphere.
  vec3 ns = t0.xyz;
  vec3 n0 = texelFetch(u_trace_triangles, base + 1).xyz;
  if (n0 != vec3(0.0)) {
    vec3 interpolated = (1.0 - hit.u - hit.v) * n0 +
                        hit.u * texelFetch(u_trace_triangles, base + 2).xyz +
                        hit.v * texelFetch(u_trace_triangles, base + 3).xyz;
    float length_n = length(interpolated);
    if (length_n > 0.0 && dot(interpolated, t0.xyz) > 0.0) ns = interpolated / length_n;
  }
  s.ng = s.front ? t0.xyz : -t0.xyz;
  s.ns = s.front ? ns : -ns;
  return s;
}

// The direct light of the batch reflected towards wo at a diffuse or glossy end point, as
// shade_light.frag.glsl computes it at a pixel's primary hit.
vec3 directLight(TraceSurface s, vec3 wo) {
  vec3 diffuse = materialDiffuse(s.material), specular = materialSpecular(s.material);
  float exponent = materialExponent(s.material);
  bool phong = materialIsPhong(s.material);
  vec3 radiance = vec3(0.0);
  for (int k = 0; k < u_light_sample_count; ++k) {
    vec3 wi, irradiance;
    if (shadowedIrradiance(k, s.p, s.ns, wi, irradiance))
      radiance += evaluateBrdf(diffuse, specular, exponent, phong, s.ns, wo, wi) * irradiance;
  }
  return radiance;
}

vec3 reflectAbout(vec3 wo, vec3 n) {
  return 2.0 * dot(n, wo) * n - wo;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_gbuffer_position, pixel, 0);
  if (position.w < 0.0) discard;
  if (materialType(uint(texelFetch(u_gbuffer_normal, pixel, 0).w)) < kMaterialMirror) discard;

  // The camera ray through the surface the G-buffer saw, cast again through the structure: the
  // hit's triangle gives the geometric normal and the glass's side, which the G-buffer lacks.
  PendingRay stack[MAX_DEPTH + 1];
  stack[0] = PendingRay(camera.position.xyz, normalize(position.xyz - camera.position.xyz),
                        vec3(1.0), 0);
  int pending = 1;
  vec3 radiance = vec3(0.0);
  while (pending > 0) {
    // Trace the last ray pushed (depth first).
    PendingRay ray = stack[--pending];
    RayCastHit hit = castRay(ray.origin - u_set_origin, ray.direction, 0.0, kRayInfinity);
    if (hit.triangle == kNoRayTriangle) {
      if (u_first_batch) radiance += ray.weight * u_sky_radiance;
      continue;
    }
    TraceSurface s = surfaceAt(ray.origin, ray.direction, hit);
    vec3 wo = -ray.direction;
    vec3 weight = ray.weight;
    int type = materialType(s.material);
    // Light travelling inside glass is absorbed along the segment that ends on its back side.
    if (type == kMaterialGlass && !s.front) weight *= exp(-materialAbsorption(s.material) * hit.t);
    // Emission is one-sided: the front only.
    if (u_first_batch && s.front) radiance += weight * materialEmission(s.material);
    if (type < kMaterialMirror) {
      radiance += weight * directLight(s, wo);
      continue;
    }
    // A specular vertex beyond the class's k ends the path.
    if (ray.depth >= MAX_DEPTH) continue;
    vec3 leave = s.p + u_ray_offset * s.ng;  // reflected rays leave on the incoming side
    vec3 enter = s.p - u_ray_offset * s.ng;  // refracted rays on the other
    if (type == kMaterialMirror) {
      // The shading normal's mirror direction unless it points below the geometric surface
      // (near a coarse mesh's silhouette): then the geometric normal's, as the reference does.
      vec3 n = s.ns;
      vec3 wi = reflectAbout(wo, n);
      if (dot(s.ng, wi) <= 0.0) {
        n = s.ng;
        wi = reflectAbout(wo, n);
      }
      vec3 f = materialIsPerfectMirror(s.material)
                   ? vec3(1.0)
                   : fresnelConductor(dot(n, wo), materialConductorN(s.material),
                                      materialConductorK(s.material));
      stack[pending++] = PendingRay(leave, wi, weight * f, ray.depth + 1);
      continue;
    }
    // Glass: reflection with F, refraction with (1 − F)/η² (radiance compressed entering a
    // denser medium, expanded leaving it), both from the shading normal unless either lands on
    // the wrong side of the geometric surface; then both from the geometric normal.
    float eta = s.front ? materialIor(s.material) : 1.0 / materialIor(s.material);
    vec3 n = s.ns;
    for (int attempt = 0; attempt < 2; ++attempt) {
      float cos_o = dot(n, wo);
      float sin2_t = (1.0 - cos_o * cos_o) / (eta * eta);
      vec3 wr = reflectAbout(wo, n);
      vec3 wt = sin2_t < 1.0
                    ? normalize(-wo / eta + (cos_o / eta - sqrt(max(0.0, 1.0 - sin2_t))) * n)
                    : vec3(0.0);
      bool valid = dot(s.ng, wr) > 0.0 && (sin2_t >= 1.0 || dot(s.ng, wt) < 0.0);
      if (!valid && attempt == 0) {
        n = s.ng;
        continue;
      }
      float f = fresnelDielectric(cos_o, eta);
      if (f < 1.0)
        stack[pending++] = PendingRay(enter, wt, weight * ((1.0 - f) / (eta * eta)), ray.depth + 1);
      if (f > 0.0) stack[pending++] = PendingRay(leave, wr, weight * f, ray.depth + 1);
      break;
    }
  }
  // Alpha as the frame's passes leave it: 1 written once, nothing added after.
  o_radiance = vec4(radiance, u_first_batch ? 1.0 : 0.0);
}
