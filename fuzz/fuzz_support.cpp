#include "fuzz/fuzz_support.h"

#include <unistd.h>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace gib::fuzz {

namespace {

std::filesystem::path g_directory;

void removeWorkDirectory() {
  std::error_code ignored;
  std::filesystem::remove_all(g_directory, ignored);
}

}  // namespace

const std::filesystem::path& workDirectory() {
  if (g_directory.empty()) {
    g_directory = std::filesystem::temp_directory_path() /
                  ("gib-fuzz-" + std::to_string(static_cast<long>(::getpid())));
    std::filesystem::create_directories(g_directory);
    std::atexit(removeWorkDirectory);
  }
  return g_directory;
}

std::filesystem::path writeInput(const std::uint8_t* data, std::size_t size,
                                 std::string_view name) {
  const std::filesystem::path path = workDirectory() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  // A write that fails here is the fuzzing machine's problem, not a finding in the parser.
  if (!out) throw std::runtime_error("cannot write the fuzz input " + path.string());
  return path;
}

std::string inputText(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

}  // namespace gib::fuzz
