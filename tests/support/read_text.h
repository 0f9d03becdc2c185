// A whole file as a string, for tests that check what a command or writer left on disk ("" when
// the file cannot be read, so the expectation on its content fails and says what is missing).
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace gib::test {

inline std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace gib::test
