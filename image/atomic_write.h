// Private to gib_image: writes a file so that readers see either the old file or the complete
// new one, never a partial file (docs/architecture.md, "Errors": no partial output is left behind).
#pragma once

#include <filesystem>
#include <functional>

namespace gib::image::detail {

// Checks that target's directory exists, calls `write` with a fresh temporary path in that
// directory, then renames the temporary file onto `target`. If `write` throws or the rename
// fails, the temporary file is removed and the error propagates; a missing directory or a failed
// rename is a gib::InputError naming `target`.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

}  // namespace gib::image::detail
