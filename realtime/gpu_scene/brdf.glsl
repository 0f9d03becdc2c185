// The materials' BRDF for the shading passes: evaluateBrdf and kInvPi, written once for GLSL and
// C++ in brdf_shared.h.
#include "realtime/gpu_scene/brdf_shared.h"
