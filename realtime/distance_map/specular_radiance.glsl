// The radiance a mirror or glass point sends towards an eye, its reflected and refracted rays
// traced through its object's distance map (book §6.2): what the camera's specular pass shows,
// and what a map shows of another specular object (§6.3). Needs scene.glsl and
// distance_map.glsl before it.
#include "realtime/gpu_scene/specular_fresnel.glsl"

// Fresnel reflectance at cos θ of a mirror (per channel) and of a glass, by the block's setting
// (specular_fresnel.glsl).
vec3 distanceMapMirrorFresnel(uint material, float cos_i) {
  return mirrorFresnel(material, cos_i, u_distance_map.search.w == kFresnelSchlick);
}
float distanceMapGlassFresnel(uint material, float cos_i) {
  return glassFresnel(material, cos_i, u_distance_map.search.w == kFresnelSchlick);
}

// The radiance the map of `object` holds where the ray from world point p along unit `direction`
// meets its surfaces, by the block's search.
vec3 distanceMapRadiance(int object, vec3 p, vec3 direction, out vec3 hit_world) {
  vec3 o = distanceMapReferencePoint(object);
  ivec4 search = u_distance_map.search;
  vec3 hit = distanceMapHit(object, p - o, direction, search.x, search.y, search.z);
  hit_world = o + hit;
  return distanceMapTexel(object, hit).rgb;
}

// What a specular point p of `object` (shading normal n, any side) sends towards `eye`. A mirror
// reflects F·L(R). A glass, as the book's single refraction (§4.2.1, §6.2), F·L(R) +
// (1 − F)·L(T): the refracted ray is looked up in the map as if it went on straight from p, which
// leaves out the second refraction where it leaves the object (the reference's glass refracts
// twice); past the critical angle it reflects everything. `traced_ray` and `traced_hit` return
// the ray whose search the error image measures (the mirror ray, the glass's refracted one) and
// the hit the search found for it.
vec3 distanceMapSpecular(int object, uint material, vec3 p, vec3 n, vec3 eye,
                         out vec3 traced_ray, out vec3 traced_hit) {
  vec3 V = normalize(p - eye);
  if (dot(n, V) > 0.0) n = -n;  // the side the eye is on
  float cos_i = clamp(-dot(n, V), 0.0, 1.0);
  vec3 R = reflect(V, n);
  vec3 reflected_hit;
  vec3 reflected = distanceMapRadiance(object, p, R, reflected_hit);
  traced_ray = R;
  traced_hit = reflected_hit;
  if (materialType(material) == kMaterialMirror)
    return distanceMapMirrorFresnel(material, cos_i) * reflected;
  vec3 T = refract(V, n, 1.0 / materialIor(material));
  if (dot(T, T) == 0.0) return reflected;  // total internal reflection
  float F = distanceMapGlassFresnel(material, cos_i);
  vec3 refracted_hit;
  vec3 refracted = distanceMapRadiance(object, p, T, refracted_hit);
  traced_ray = T;
  traced_hit = refracted_hit;
  return F * reflected + (1.0 - F) * refracted;
}
