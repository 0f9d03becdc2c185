#include "support/glsl_sources.h"

#include <memory>

namespace gib::test {

rt::gl::GlslLookup glslSources(std::map<std::string, std::string, std::less<>> files) {
  // Shared, so that the views handed out stay valid in every copy of the lookup.
  auto shared =
      std::make_shared<const std::map<std::string, std::string, std::less<>>>(std::move(files));
  return [shared](std::string_view path) -> std::string_view {
    const auto found = shared->find(path);
    if (found == shared->end())
      throw rt::gl::ShaderError("no test GLSL file '" + std::string(path) + "'");
    return found->second;
  };
}

}  // namespace gib::test
