// timings.json, the pass timings of a technique job (results/results_json.h): the input is the
// file.
#include "fuzz/fuzz_support.h"
#include "results/results_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gib;
  const auto path = fuzz::writeInput(data, size, "timings.json");
  fuzz::refusedOnlyAsInputError([&] { results::readPassTimingsFile(path); });
  return 0;
}
