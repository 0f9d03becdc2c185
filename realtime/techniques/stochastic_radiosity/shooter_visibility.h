// The first of the two passes of the radiance update (Barsi & Jakab §3.2, book §7.1.2): the
// scene drawn from the selected shooter into a visibility map of distances, as a hemicube (five
// faces, layers of one array drawn by one instanced draw) or a hemispherical projection. The
// shooter is read from the Shooters buffer on the GPU (shooter.glsl), so no selection result
// travels back to the CPU.
#pragma once

#include "realtime/atlas/atlas_mesh.h"
#include "realtime/gl/objects.h"

#include <string>

namespace gib::rt {

enum class ShooterProjection { kHemicube, kHemisphere };

class ShooterVisibility {
 public:
  // `map_size`: texels per side of a hemicube face (of the hemisphere's disk); `extent`: the
  // scene's diagonal, which sets the near and far planes and the shooter's lift.
  ShooterVisibility(ShooterProjection projection, int map_size, float extent);

  ShooterProjection projection() const { return projection_; }
  // "#define HEMICUBE\n" or nothing: for programs that include visibility_lookup.glsl.
  std::string defines() const;
  float shooterLift() const { return lift_; }

  // Draws `mesh` from the shooter in Shooters[0]; the atlas maps and the Shooters buffer must be
  // bound.
  void render(const atlas::AtlasMesh& mesh) const;
  // Sets the lookup's constant uniforms of `program` (once, after it is built).
  void setLookupConstants(const gl::Program& program) const;
  // Binds the map to gpu::kVisibilityUnit (stochastic_radiosity_shared.h).
  void bindForLookup() const;

 private:
  ShooterProjection projection_;
  int size_;
  float near_, far_, lift_;
  gl::Program program_;
  gl::Texture distance_, depth_;
  gl::Framebuffer framebuffer_;  // every layer
};

}  // namespace gib::rt
