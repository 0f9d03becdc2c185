// The faces a record's hemisphere is rasterized on, shared by the views and their sums. Face 0
// looks along the normal; the hemicube's faces 1–4 look along ±t and ±b with the normal up, their
// lower halves below the horizon. A face's image spans [−h, h]² on the plane at unit distance
// (h = tan of half its field of view); pixel (i, j) looks along x·right + y·up + forward.
#include "realtime/irradiance_cache/irradiance_cache_shared.h"
#include "realtime/techniques/irradiance_cache_splatting/irradiance_cache_splatting_shared.h"

struct RecordFace {
  vec3 forward, right, up;
};

RecordFace recordFace(vec3 n, int face) {
  vec3 t = basisTangent(n), b = basisBitangent(n);
  RecordFace f;
  if (face == 0) {
    f.forward = n;
    f.right = t;
    f.up = b;
    return f;
  }
  vec3 axes[4] = vec3[4](t, -t, b, -b);
  f.forward = axes[face - 1];
  f.up = n;
  f.right = cross(f.forward, n);
  return f;
}

layout(std430, binding = kRecordsBinding) buffer Records {
  IrradianceRecord records[];
};
