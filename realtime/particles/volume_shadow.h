// Volume shadowing of the particles (book §9.4, volume_shadow.comp.glsl): the transmittance from
// every particle's centre towards each of a set of directions (the lights', the sky's), through
// the rest of the medium.
#pragma once

#include "realtime/gl/objects.h"
#include "realtime/particles/particle_medium.h"

#include <glm/vec4.hpp>

#include <vector>

namespace gib::rt {

class VolumeShadow {
 public:
  VolumeShadow();

  // Fills `transmittance` (resized as needed) with N × M floats, [particle × M + direction], for
  // the M directions of `directions` (a buffer of vec4, xyz unit).
  void compute(const ParticleMedium& medium, const gl::Buffer& directions, int direction_count,
               gl::Buffer& transmittance) const;

 private:
  gl::Program program_;
};

}  // namespace gib::rt
