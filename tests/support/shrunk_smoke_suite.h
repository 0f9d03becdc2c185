// suites/smoke.toml as shipped, shrunk for tests: 32x32 images, 64-spp references, checkpoints
// [4, 16, 64]; every case and parameter otherwise as the quick start runs it.
#pragma once

#include <string>

namespace gib::test {

std::string shrunkSmokeSuite();

}  // namespace gib::test
