#include "realtime/gpu_scene/glossy_exponents.h"

#include <fmt/format.h>

#include <set>

namespace gib::rt {

std::vector<float> glossyExponents(const scene::Scene& scene) {
  std::set<float> exponents;
  for (const scene::Mesh& mesh : scene.meshes) {
    const scene::Material& m = scene.materials[mesh.material];
    if (!mesh.triangles.empty() && m.type == scene::MaterialType::kPhong &&
        m.specular != scene::Rgb(0.0f))
      exponents.insert(m.exponent);
  }
  return {exponents.begin(), exponents.end()};
}

std::string glslExponentArray(const std::vector<float>& exponents) {
  return fmt::format("float[]({:.9e})", fmt::join(exponents, ", "));
}

}  // namespace gib::rt
