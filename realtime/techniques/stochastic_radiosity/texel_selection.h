// Random texel selection with probability proportional to the luminance of the texel's power,
// p_j = lum(L_j)·A_j / Φ, Φ = Σ lum(L_i)·A_i (Barsi & Jakab §3.1; book §7.1.1), in the two
// variants the paper measured:
//   kGpu: a summed pyramid of the power map (each texel the sum of four below: the paper's and
//         book's "mipmap"; compute passes of four levels each, two at 128²), then a descent
//         from the top in one pass, each level choosing one of four children by comparing the
//         running sum with the remaining selection value (the book's SelectTexel). Nothing is
//         read back.
//   kCpu: the power map is read back and searched linearly with a running sum (the paper's first
//         implementation, whose read-back it found to dominate the iteration).
// Both write the selected texels into one storage buffer (Shooters, whose record is declared in
// stochastic_radiosity_shared.h), which the later passes read on the GPU. Several selections can
// run at once (one per value of u), which the tests use; the technique selects one texel per
// iteration.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/techniques/stochastic_radiosity/stochastic_radiosity_shared.h"

#include <vector>

namespace gib::rt {

enum class SelectionMethod { kGpu, kCpu };

// A selection with nothing selected yet.
inline constexpr gpu::Shooter kNoShooter = {{-1, -1}, 0, 0, 0, 0, {0, 0}};

class TexelSelection {
 public:
  // A power map of resolution × resolution (a power of two), R32F with its pyramid levels;
  // room for `capacity` simultaneous selections.
  TexelSelection(SelectionMethod method, int resolution, int capacity = 1);

  SelectionMethod method() const { return method_; }
  // The power map, lum(L)·A per texel: level 0 is written by the caller (a framebuffer
  // attachment); the levels above are the pyramid.
  const gl::Texture& powerMap() const { return power_; }
  // Sums level 0 up into the pyramid (kGpu only; kCpu has none to build).
  void buildPyramid() const;
  // Selects one texel per value of `u` (each in [0, 1)) into the Shooters buffer.
  void select(const std::vector<float>& u);
  // Binds the first selection as the uniform block the shooting passes read (shooter.glsl).
  void bindShooter() const {
    shooters_.bindRange(GL_UNIFORM_BUFFER, gpu::kShooterBlockBinding, 0, sizeof(gpu::Shooter));
  }
  // Reads the first `count` selections back (tests, and nothing else: it stalls the pipeline).
  std::vector<gpu::Shooter> readSelections(int count) const;

 private:
  void selectOnGpu(const std::vector<float>& u);
  void selectOnCpu(const std::vector<float>& u);

  SelectionMethod method_;
  int resolution_, levels_, capacity_;
  gl::Texture power_;
  std::vector<float> read_back_;  // kCpu: the power map's texels, reused every selection
  gl::Buffer shooters_;
  gl::Program sum_, descend_;
};

}  // namespace gib::rt
