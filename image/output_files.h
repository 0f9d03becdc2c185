// Checks and writes of output files for the command line and the harness: a bad --out is found
// before any rendering time is spent, and no partial file is ever left behind.
#pragma once

#include <filesystem>
#include <string_view>

namespace gib::image {

// Throws gib::InputError naming the file when its directory does not exist or is not writable,
// or when `extension` (".exr", ".json") is given and the name does not end in it.
void checkOutputFile(const std::filesystem::path& path, std::string_view extension = {});

// Writes `text` so that readers see the old file or the complete new one.
void writeTextFile(const std::filesystem::path& path, std::string_view text);

// Copies `from` to `to` so that readers see the old file or the complete copy. Throws
// gib::InputError naming the files when the copy fails.
void copyFileAtomically(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace gib::image
