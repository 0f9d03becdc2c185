// EXR input to `gibench compare` and the reference store (image/exr_io.h): the input is the file,
// read as `compare` reads it (readRgb, through readExr). The reader's size cap is lowered to 2^22
// values (16 MiB of floats), so that a header declaring a large image is refused rather than
// allocated, fast, as the default cap does for files of more than 1 GiB.
#include "fuzz/fuzz_support.h"
#include "image/exr_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gib;
  const auto path = fuzz::writeInput(data, size, "image.exr");
  fuzz::refusedOnlyAsInputError([&] { image::readRgb(path, std::size_t(1) << 22); });
  return 0;
}
