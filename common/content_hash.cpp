#include "content_hash.h"

#include <xxhash.h>

#include <fmt/format.h>
#include <bit>
#include <cstring>
#include <fstream>
#include <vector>

#include "common/input_error.h"

namespace gib {

static XXH3_state_t* state(void* p) {
  return static_cast<XXH3_state_t*>(p);
}

ContentHasher::ContentHasher() : state_(XXH3_createState()) {
  XXH3_128bits_reset(state(state_));
}

ContentHasher::~ContentHasher() {
  XXH3_freeState(state(state_));
}

void ContentHasher::addBytes(std::span<const std::uint8_t> bytes) {
  XXH3_128bits_update(state(state_), bytes.data(), bytes.size());
}

void ContentHasher::addU64(std::uint64_t value) {
  std::uint8_t bytes[8];
  for (int i = 0; i < 8; ++i) bytes[i] = static_cast<std::uint8_t>(value >> (8 * i));
  addBytes(bytes);
}

void ContentHasher::addFloat(float value) {
  if (value == 0.0f) value = 0.0f;  // fold -0 into +0
  addU64(std::bit_cast<std::uint32_t>(value));
}

void ContentHasher::addFloats(std::span<const float> values) {
  addU64(values.size());
  for (float v : values) addFloat(v);
}

void ContentHasher::addString(std::string_view text) {
  addU64(text.size());
  addBytes({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

std::string ContentHasher::hexDigest() const {
  XXH128_hash_t h = XXH3_128bits_digest(state(state_));
  return fmt::format("{:016x}{:016x}", h.high64, h.low64);
}

std::string hashFileContents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(
        fmt::format("cannot read '{}'; check that it exists and is readable", path.string()));
  ContentHasher hasher;
  std::vector<char> chunk(std::size_t(1) << 20);
  while (in) {
    in.read(chunk.data(), std::streamsize(chunk.size()));
    hasher.addBytes(
        {reinterpret_cast<const std::uint8_t*>(chunk.data()), std::size_t(in.gcount())});
  }
  if (in.bad())
    throw InputError(fmt::format("cannot read '{}' to the end; check the disk", path.string()));
  return hasher.hexDigest();
}

}  // namespace gib
