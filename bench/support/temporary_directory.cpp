#include "support/temporary_directory.h"

#include <cstdlib>
#include <stdexcept>

namespace gib::bench {

TemporaryDirectory::TemporaryDirectory(const std::string& stem) {
  std::string pattern = (std::filesystem::temp_directory_path() / (stem + ".XXXXXX")).string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create " + pattern);
  path_ = pattern;
}

TemporaryDirectory::~TemporaryDirectory() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace gib::bench
