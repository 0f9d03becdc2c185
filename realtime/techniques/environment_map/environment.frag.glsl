// The environment's light at each camera pixel (book §4.2.1-4.2.2, no visibility), added to the
// frame: a mirror shows F·L(R), a glass F·L(R) + (1 − F)·L(T) with T refracted through its front
// surface only; a diffuse or glossy surface reflects ρd/π·E(n) + ρs·G_m(R) from the convolved
// maps (convolve.comp.glsl). GLOSSY_EXPONENTS lists the Phong exponents of the
// glossy layers 1, 2, … in order, GLOSSY_MAPS their count.
#include "realtime/gpu_scene/scene.glsl"
#include "realtime/gbuffer/shaded_surface.glsl"
#include "realtime/gpu_scene/specular_fresnel.glsl"
#include "realtime/lighting/environment.glsl"
#include "realtime/techniques/environment_map/environment_map_shared.h"

layout(binding = kConvolvedMapsUnit) uniform sampler2DArray u_convolved;
uniform bool u_fresnel_schlick;  // fresnel=schlick: eq. 1.6's approximation, as the book

layout(location = 0) out vec4 o_radiance;

// A convolved layer in a world direction, times the map's intensity (the sums leave it out). Its
// rows run from pole to pole inclusive (convolve.comp.glsl): v = θ/π falls between rows
// ⌊v(H − 1)⌋ and the next, whose centres are at texture coordinates (row + ½)/H.
vec3 convolvedRadiance(int layer, vec3 world) {
  vec2 uv = environmentCoordinatesOf(world);
  float rows = float(textureSize(u_convolved, 0).y);
  uv.y = (uv.y * (rows - 1.0) + 0.5) / rows;
  return u_environment.z * texture(u_convolved, vec3(uv, layer)).rgb;
}

// The glossy layer of a Phong exponent, or −1 for one the technique did not convolve.
int glossyLayer(float exponent) {
#if GLOSSY_MAPS > 0
  const float exponents[GLOSSY_MAPS] = GLOSSY_EXPONENTS;
  for (int k = 0; k < GLOSSY_MAPS; ++k)
    if (exponents[k] == exponent) return 1 + k;
#endif
  return -1;
}

void main() {
  ShadedSurface s;
  if (!shadedSurface(ivec2(gl_FragCoord.xy), s)) discard;
  uint material = s.material;
  int type = materialType(material);
  vec3 V = -s.wo;  // from the eye; s.n is on the eye's side
  vec3 R = reflect(V, s.n);
  float cos_i = clamp(dot(s.n, s.wo), 0.0, 1.0);
  vec3 radiance;
  if (type == kMaterialMirror) {
    radiance = mirrorFresnel(material, cos_i, u_fresnel_schlick) * environmentRadiance(R);
  } else if (type == kMaterialGlass) {
    vec3 reflected = environmentRadiance(R);
    vec3 T = refract(V, s.n, 1.0 / materialIor(material));
    if (dot(T, T) == 0.0) {
      radiance = reflected;  // total internal reflection (refract's zero vector)
    } else {
      float F = glassFresnel(material, cos_i, u_fresnel_schlick);
      radiance = F * reflected + (1.0 - F) * environmentRadiance(T);
    }
  } else {
    radiance = materialDiffuse(material) * kInvPi * convolvedRadiance(0, s.n);
    int layer = materialIsPhong(material) ? glossyLayer(materialExponent(material)) : -1;
    if (layer > 0) radiance += materialSpecular(material) * convolvedRadiance(layer, R);
  }
  o_radiance = vec4(radiance, 0.0);
}
