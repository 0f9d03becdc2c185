// Scene files (scene/scene_file.h): the input is the TOML file. Its meshes may name "box.obj", a
// valid mesh beside it, so that inputs reach the placement, material and light checks.
#include "fuzz/fuzz_support.h"
#include "scene/scene_file.h"

#include <string_view>

namespace {

constexpr std::string_view kBoxObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\n";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gib;
  static const bool written = [] {
    fuzz::writeInput(reinterpret_cast<const std::uint8_t*>(kBoxObj.data()), kBoxObj.size(),
                     "box.obj");
    return true;
  }();
  (void)written;
  const auto path = fuzz::writeInput(data, size, "scene.toml");
  fuzz::refusedOnlyAsInputError([&] { scene::loadSceneFile(path); });
  return 0;
}
