// A 128-bit content hash (XXH3) for canonical byte streams: the scene hash, later the keys of the
// reference store. Values are fed in a fixed little-endian layout so that the hash is the same
// on every machine.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace gib {

class ContentHasher {
 public:
  ContentHasher();
  ~ContentHasher();
  ContentHasher(const ContentHasher&) = delete;
  ContentHasher& operator=(const ContentHasher&) = delete;

  void addBytes(std::span<const std::uint8_t> bytes);
  void addU64(std::uint64_t value);
  // Floats are hashed by their bit pattern, with -0 folded into +0.
  void addFloat(float value);
  void addFloats(std::span<const float> values);
  // Strings are length-prefixed so that ("ab","c") and ("a","bc") differ.
  void addString(std::string_view text);

  // 32 lowercase hex digits.
  std::string hexDigest() const;

 private:
  void* state_;  // XXH3_state_t, kept out of this header.
};

// The hexDigest() of a file's bytes (fed through addBytes, so not length-prefixed). Throws
// gib::InputError naming the file when it cannot be read.
std::string hashFileContents(const std::filesystem::path& path);

}  // namespace gib
