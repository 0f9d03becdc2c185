// results.json and a job's result file (results/results_json.h), as `gibench report`, `diff` and
// `merge` read them: the input is the file.
#include "fuzz/fuzz_support.h"
#include "results/results_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gib;
  const auto path = fuzz::writeInput(data, size, "results.json");
  fuzz::refusedOnlyAsInputError([&] { results::readResultsFile(path); });
  fuzz::refusedOnlyAsInputError([&] { results::readJobFile(path); });
  return 0;
}
