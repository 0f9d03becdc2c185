// The current batch of light samples (light_sample_shared.h) and where a world point lies in a
// sample's shadow map, shared by the shadow pass (which writes it) and the passes that compare
// against it. POINT_LIGHT: a cube map around the sample's position with 90° faces from u_near to
// u_far; otherwise an orthographic map along its axis through its view_projection, depth 0..1
// over the scene's bounding sphere. Sample k's map is layer k of the batch's array.
#include "realtime/gl/binding_plan_shared.h"
#include "realtime/lighting/light_sample_shared.h"

layout(std140, binding = kLightSamplesBinding) uniform LightSampleBlock {
  GpuLightSample u_light_samples[kMaxLightBatch];
};
uniform int u_light_sample_count;  // samples in the current batch
uniform float u_near;
uniform float u_far;

// The distance the variance shadow map stores, scaled to about 0..1 for float precision.
float lightDistance(int k, vec3 p) {
#ifdef POINT_LIGHT
  return length(p - u_light_samples[k].position.xyz) / u_far;
#else
  return (u_light_samples[k].view_projection * vec4(p, 1.0)).z * 0.5 + 0.5;
#endif
}
