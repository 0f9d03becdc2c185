// The scene's environment map on the GPU (book §4.2, "image-based lighting"): its latitude–
// longitude texels uploaded once as an RGB32F texture at gpu::kEnvironmentUnit, with the map's
// rotation and intensity as uniforms, so that realtime/lighting/environment.glsl reads exactly
// the radiance scene::EnvironmentMap::radiance gives the reference (the same texel, no filtering:
// the reference's texels are piecewise constant). The emission pass shows it where camera rays
// leave the scene; techniques that light by it (environment_map) read it too.
#pragma once

#include "realtime/gl/objects.h"
#include "scene/environment_map.h"

#include <string_view>

namespace gib::scene {
struct Scene;
}

namespace gib::rt {

// Added to a program's defines when it reads environment.glsl in place of a constant sky.
inline constexpr std::string_view kEnvironmentMapDefine = "#define ENVIRONMENT_MAP 1\n";

class EnvironmentTexture {
 public:
  explicit EnvironmentTexture(const scene::EnvironmentMap& map);

  // Sets environment.glsl's uniforms (the rotation into the map's frame, the intensity) in a
  // program that includes it; once, after the program is built.
  void setUniforms(const gl::Program& program) const;
  // Binds the texels at gpu::kEnvironmentUnit, before a draw that reads them.
  void bind() const;

  const scene::EnvironmentMap& map() const { return map_; }

 private:
  scene::EnvironmentMap map_;  // shares the scene's texels
  gl::Texture texture_;
};

// What a ray leaving `scene` sees, as a map: its environment map, or for a scene with a constant
// sky a map of that radiance, `constant_rows` rows of twice as many columns (a constant map is
// its texels' value in every direction; more texels serve a caller that divides the sphere by
// them); empty when the scene has neither.
scene::EnvironmentMap sceneEnvironment(const scene::Scene& scene, int constant_rows = 1);

}  // namespace gib::rt
