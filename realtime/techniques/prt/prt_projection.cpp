#include "realtime/techniques/prt/prt_projection.h"

#include "realtime/sh/sh_basis.h"
#include "realtime/sh/sh_rotation.h"

namespace gib::rt::prt {

void projectLighting(const CpcaResult& compressed, std::span<const glm::vec3> lighting, int bands,
                     float angle, std::vector<glm::vec3>& rotated, std::span<glm::vec4> out) {
  rotated.assign(lighting.begin(), lighting.end());
  if (angle != 0.0f) sh::rotateAboutY(std::span<glm::vec3>(rotated), bands, angle);
  const int n = sh::shBasisCount(bands);
  const std::size_t dimension = std::size_t(compressed.dimension);
  const std::size_t m = std::size_t(compressed.pca_vectors);
  for (std::size_t k = 0; k < std::size_t(compressed.clusters); ++k)
    for (std::size_t d = 0; d <= m; ++d) {
      const float* vector = d == 0 ? compressed.means.data() + k * dimension
                                   : compressed.bases.data() + (k * m + d - 1) * dimension;
      glm::vec4 dot(0.0f);
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i) dot[c] += rotated[std::size_t(i)][c] * vector[c * n + i];
      out[k * (m + 1) + d] = dot;
    }
}

}  // namespace gib::rt::prt
