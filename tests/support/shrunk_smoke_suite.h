// Shipped suites shrunk for tests: 32x32 images and 64-spp references, every case otherwise as
// shipped.
#pragma once

#include <string>

namespace gib::test {

// suites/smoke.toml as the quick start runs it, shrunk, with checkpoints [4, 16, 64], 3 measured
// frames after 1 warm-up frame and 4 light samples.
std::string shrunkSmokeSuite();

// suites/figures/<name>.toml, shrunk; its checkpoints and iteration counts as shipped (they are
// what its figures show).
std::string shrunkFigureSuite(const std::string& name);

}  // namespace gib::test
