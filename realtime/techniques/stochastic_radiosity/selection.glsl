// The selected shooters (struct Shooter of stochastic_radiosity_shared.h), written by the
// selection passes and read by the visibility and update passes.
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_shared.h"

layout(std430, binding = kShootersBinding) buffer Shooters {
  Shooter shooters[];
};
