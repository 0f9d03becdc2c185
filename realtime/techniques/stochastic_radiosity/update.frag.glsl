// The second pass of the radiance update, in texture space (book §7.1.2; Barsi & Jakab §3.2):
// one fragment per atlas texel i, transferring the selected shooter j's radiance to it.
//
// Estimator. Eq. (7.2) sums over shooters j: L^r_i = Σ_j L_j f_i G(x_i, y_j) A_j, with
// L_j = L^e_j + L^r_j the shooter's current estimate. Choosing one j with probability p_j and
// dividing by it (eq. 7.3) gives an unbiased estimate of that sum. With p_j = lum(L_j)·A_j / Φ
// and Φ = Σ lum(L_i)·A_i (Barsi & Jakab §3.1),
//   L_j·A_j / p_j = L_j·Φ / lum(L_j),
// the paper's L_shoot: the shooter's colour scaled to the total power. We divide by exactly the
// power value the selection used (u_shooter.power), so that the estimate stays unbiased even
// though the power map is being rewritten by this pass.
//
// The geometric factor is the book's cos⁺θx·cos⁺θy / |x − y|², except that |x − y|² becomes
// |x − y|² + A/π with A the area of a whole texel: the form factor of a disk of a texel's area
// seen on its axis, which equals the point formula at distances large against a texel and stays
// finite for a receiver touching the shooter (across a corner), where the point formula's 1/r²
// gives unbounded fireflies. A whole texel's area rather than the shooter's own (A_j, smaller for
// a texel the chart's edge cuts): the shooter's sample point may sit anywhere in its texel, and
// every shot carries the whole power Φ whatever A_j is.
//
// Averaging (eq. 2 of Barsi & Jakab): L̃_m = (1/m)(L^e + T*L̃_{m−1}) + (1 − 1/m) L̃_{m−1}; with
// L̃ = L^e + L̃^r this is L̃^r_m = L̃^r_{m−1} + (T*L̃_{m−1} − L̃^r_{m−1}) / m for the reflected part,
// which is what the atlas stores. The second output is the power for the next selection, the
// book's "lum" (we use Rec.709 luminance; the book's weights (0.21, 0.39, 0.4) are not
// luminance).
//
// The shooter's radiance includes its emission, which is one-sided: it shoots into the half-space
// its normal points to. A receiver behind the shooter's plane, or seeing the shooter from its back
// side, gets nothing (reflection in the atlas is the front side's).
#include "realtime/techniques/stochastic_radiosity/shooter.glsl"
#include "realtime/techniques/stochastic_radiosity/visibility_lookup.glsl"
#include "realtime/gpu_scene/brdf.glsl"
#include "common/luminance_shared.h"

layout(binding = kRadiositySourceUnit) uniform sampler2D u_source;  // L^e plus injected direct light
layout(binding = kRadiosityReflectedUnit) uniform sampler2D u_reflected;  // L̃^r_{m−1}
uniform float u_iteration;   // m ≥ 1
uniform float u_texel_area;  // world area of a whole texel
layout(location = 0) out vec4 o_reflected;
layout(location = 1) out float o_power;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 position = texelFetch(u_atlas_position, texel, 0);
  if (position.w == 0.0) {  // outside every chart
    o_reflected = vec4(0.0);
    o_power = 0.0;
    return;
  }
  vec4 normal_area = texelFetch(u_atlas_normal, texel, 0);
  vec3 previous = texelFetch(u_reflected, texel, 0).rgb;

  // Step 1: the random transport operator T* applied to the current estimate, for this receiver.
  vec3 transferred = vec3(0.0);
  ShooterFrame shooter = shooterFrame();
  if (shooter.valid) {
    vec3 d = position.xyz - shooter.origin;
    float distance_squared = dot(d, d);
    vec3 w = d * inversesqrt(max(distance_squared, 1e-30));
    float cos_shooter = dot(shooter.n, w);
    float cos_receiver = -dot(normal_area.xyz, w);
    if (cos_shooter > 0.0 && cos_receiver > 0.0 &&
        visibleFromShooter(shooterLocal(shooter, position.xyz), cos_receiver)) {
      Shooter s = u_shooter;
      vec3 shooter_radiance = texelFetch(u_source, s.texel, 0).rgb + texelFetch(u_reflected, s.texel, 0).rgb;
      float shooter_area = texelFetch(u_atlas_normal, s.texel, 0).w;
      vec3 shot = shooter_radiance * (shooter_area * s.total_power / s.power);  // L_j·A_j / p_j
      vec3 brdf = texelFetch(u_atlas_albedo, texel, 0).rgb * kInvPi;
      float g = cos_shooter * cos_receiver / (distance_squared + u_texel_area * kInvPi);
      transferred = brdf * shot * g;
    }
  }

  // Step 2: the running average of eq. (2), and the texel's power for the next selection.
  vec3 reflected = previous + (transferred - previous) / u_iteration;
  o_reflected = vec4(reflected, 1.0);
  o_power = luminance(texelFetch(u_source, texel, 0).rgb + reflected) * normal_area.w;
}
