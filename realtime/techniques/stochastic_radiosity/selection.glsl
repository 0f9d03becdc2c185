// The selected shooters (gib::rt::SelectedTexel, texel_selection.h), written by the selection
// passes and read by the visibility and update passes.
#define kShootersBinding 1  // = gib::rt::kShootersBinding

struct Shooter {
  ivec2 texel;        // (−1, −1): nothing has power
  float power;        // lum(L_j)·A_j of the selected texel
  float total_power;  // Φ = Σ lum(L_i)·A_i
  float remaining;    // descent state
  float u;            // uniform random number of this selection
  ivec2 padding;
};

layout(std430, binding = kShootersBinding) buffer Shooters {
  Shooter shooters[];
};
