// EXR input to `gibench compare` and the reference store (image/exr_io.h): the input is the file,
// read as `compare` reads it (readRgb, through readExr). The reader's size cap is lowered to 2^14
// values (64×64 RGBA; the largest seed holds 24×16×6): a header declaring a larger image is
// refused before anything is allocated, as the default cap does beyond 1 GiB. With a cap of 2^22
// most of the fuzzer's time went to allocating and zeroing the buffers of images that mutated
// headers declare (13–22 executions a second); with 2^14 it goes to the decoders.
#include "fuzz/fuzz_support.h"
#include "image/exr_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gib;
  const auto path = fuzz::writeInput(data, size, "image.exr");
  fuzz::refusedOnlyAsInputError([&] { image::readRgb(path, std::size_t(1) << 14); });
  return 0;
}
