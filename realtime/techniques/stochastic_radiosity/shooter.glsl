// The selected shooter as a point with a frame: its atlas sample point y_j, lifted along its
// normal by u_shooter_lift (so that surfaces meeting it at a corner are not cut by the near
// plane of its view), and an orthonormal basis (t, b, n) with n the shooter's normal.
#include "realtime/atlas/atlas_maps.glsl"
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_shared.h"

layout(std140, binding = kShooterBlockBinding) uniform ShooterBlock {
  Shooter u_shooter;  // the selection's first record
};

uniform float u_shooter_lift;  // world units

struct ShooterFrame {
  bool valid;
  vec3 origin;
  vec3 t, b, n;
};

// Duff et al. 2017, "Building an Orthonormal Basis, Revisited".
void orthonormalBasis(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

ShooterFrame shooterFrame() {
  ShooterFrame f;
  ivec2 texel = u_shooter.texel;
  f.valid = texel.x >= 0;
  if (!f.valid) texel = ivec2(0);
  f.n = texelFetch(u_atlas_normal, texel, 0).xyz;
  f.origin = texelFetch(u_atlas_position, texel, 0).xyz + f.n * u_shooter_lift;
  orthonormalBasis(f.n, f.t, f.b);
  return f;
}

// A world point in the shooter's frame: z along its normal.
vec3 shooterLocal(ShooterFrame f, vec3 p) {
  vec3 d = p - f.origin;
  return vec3(dot(d, f.t), dot(d, f.b), dot(d, f.n));
}
