// Private to gib_image: writes a file so that readers see either the old file or the complete
// new one, never a partial file (docs/architecture.md, "Errors": no partial output is left behind).
#pragma once

#include <filesystem>
#include <functional>
#include <span>

namespace gib::image::detail {

// Checks that target's directory exists, calls `write` with a fresh temporary path in that
// directory, then renames the temporary file onto `target`. If `write` throws or the rename
// fails, the temporary file is removed and the error propagates; a missing directory or a failed
// rename is a gib::InputError naming `target`.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

// Writes `bytes` to `target` through writeAtomically, with every I/O error checked on the stream
// after it is closed: a full disk (ENOSPC), a file size limit (EFBIG) or a failing device is a
// gib::InputError naming `target` and the system's reason, and `target` is left as it was.
// Encoders whose library may swallow a late write error (OpenEXR writes its line offset table
// from a destructor that ignores I/O errors) encode into memory and write through this.
void writeBytesAtomically(const std::filesystem::path& target, std::span<const char> bytes);

}  // namespace gib::image::detail
