// What the fuzz targets share. The project's parsers read files by path, as users' files reach
// them, so a fuzz input is written to a file first; and the one acceptable way for a parser to
// refuse an input is gib::InputError (one line and exit code 2 in `gibench`). Anything else that
// escapes (another exception, which `gibench` would report as an internal error, or a crash or
// sanitizer report) is a finding: libFuzzer stops and saves the input.
#pragma once

#include "common/input_error.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace gib::fuzz {

// A directory of this process's own under the system's temporary directory, created on first use
// and removed at exit, so that parallel fuzzing jobs never share files.
const std::filesystem::path& workDirectory();

// Writes the bytes to workDirectory()/name (replacing the file) and returns its path.
std::filesystem::path writeInput(const std::uint8_t* data, std::size_t size, std::string_view name);

// The input as text.
std::string inputText(const std::uint8_t* data, std::size_t size);

// Runs `parse`; a gib::InputError is the expected refusal of a malformed input and is swallowed.
template <class Parse>
void refusedOnlyAsInputError(Parse&& parse) {
  try {
    parse();
  } catch (const InputError&) {
  }
}

}  // namespace gib::fuzz
