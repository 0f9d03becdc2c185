#include "image/output_files.h"

#include "common/input_error.h"
#include "image/atomic_write.h"

#include <fmt/format.h>
#include <unistd.h>

#include <fstream>

namespace gib::image {

namespace fs = std::filesystem;

void checkOutputFile(const fs::path& path, std::string_view extension) {
  if (!extension.empty() && path.extension() != extension)
    throw InputError(fmt::format("output '{}' must end in {}", path.string(), extension));
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(
        fmt::format("cannot write '{}': directory '{}' does not exist; create it first",
                    path.string(), dir.string()));
  if (access(dir.c_str(), W_OK) != 0)
    throw InputError(
        fmt::format("cannot write '{}': directory '{}' is not writable; choose another place",
                    path.string(), dir.string()));
}

void writeTextFile(const fs::path& path, std::string_view text) {
  detail::writeBytesAtomically(path, text);
}

void copyFileAtomically(const fs::path& from, const fs::path& to) {
  detail::writeAtomically(to, [&](const fs::path& temporary) {
    std::error_code ec;
    fs::copy_file(from, temporary, fs::copy_options::overwrite_existing, ec);
    if (ec)
      throw InputError(
          fmt::format("cannot copy '{}' to '{}': {}", from.string(), to.string(), ec.message()));
  });
}

}  // namespace gib::image
