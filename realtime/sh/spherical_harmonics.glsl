// The real spherical harmonics basis of realtime/sh/spherical_harmonics.h, bands 0..3, in the
// same order and with the same constants (tests/realtime/irradiance_volume_test.cpp compares).
#include "realtime/sh/spherical_harmonics_shared.h"

void shBasis(vec3 d, out float y[kShMaxCoefficients]) {
  float x = d.x, yy = d.y, z = d.z;
  y[0] = 0.282094792;
  y[1] = 0.488602512 * yy;
  y[2] = 0.488602512 * z;
  y[3] = 0.488602512 * x;
  y[4] = 1.092548431 * x * yy;
  y[5] = 1.092548431 * yy * z;
  y[6] = 0.315391565 * (3.0 * z * z - 1.0);
  y[7] = 1.092548431 * x * z;
  y[8] = 0.546274215 * (x * x - yy * yy);
  y[9] = 0.590043589 * yy * (3.0 * x * x - yy * yy);
  y[10] = 2.890611442 * x * yy * z;
  y[11] = 0.457045799 * yy * (5.0 * z * z - 1.0);
  y[12] = 0.373176333 * z * (5.0 * z * z - 3.0);
  y[13] = 0.457045799 * x * (5.0 * z * z - 1.0);
  y[14] = 1.445305721 * z * (x * x - yy * yy);
  y[15] = 0.590043589 * x * (x * x - 3.0 * yy * yy);
}
