// Suite files (suites/suite_file.h), with their [[chart]], [[paper]], [[figure]] and
// [tolerances] tables: the input is the TOML file; a case may name the scene file "room.toml"
// beside it (a suite only checks that a scene file exists).
#include "fuzz/fuzz_support.h"
#include "suites/suite_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gib;
  static const bool written = [] {
    fuzz::writeInput(nullptr, 0, "room.toml");
    return true;
  }();
  (void)written;
  const auto path = fuzz::writeInput(data, size, "suite.toml");
  fuzz::refusedOnlyAsInputError([&] { suites::loadSuiteFile(path); });
  return 0;
}
