#include "image/atomic_write.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include "common/input_error.h"
#include "common/stall_point.h"

namespace gib::image::detail {
namespace {

namespace fs = std::filesystem;

void requireDirectory(const fs::path& target) {
  if (!target.has_filename())
    throw InputError("cannot write '" + target.string() +
                     "': the path names a directory, not a file; add a file name");
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  const fs::file_status status = fs::status(directory, error);
  if (!fs::exists(status))
    throw InputError("cannot write '" + target.string() + "': directory '" + directory.string() +
                     "' does not exist; create it first or choose another output path");
  if (!fs::is_directory(status))
    throw InputError("cannot write '" + target.string() + "': '" + directory.string() +
                     "' is not a directory; choose another output path");
}

// Unique per process and call: the process id keeps concurrent programs apart, the counter
// concurrent writers in this one. Hidden, so that a directory listing during the write does not
// show it as a result.
fs::path temporaryPathFor(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about "." + std::string.
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter.fetch_add(1));
  return target.parent_path() / name;
}

}  // namespace

void writeAtomically(const fs::path& target,
                     const std::function<void(const fs::path& temporary)>& write) {
  requireDirectory(target);
  const fs::path temporary = temporaryPathFor(target);
  try {
    write(temporary);
    stallPoint("write:" + target.filename().string());
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error)
      throw InputError("cannot write '" + target.string() + "': " + error.message() +
                       "; check that the path is not a directory and the directory is writable");
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
}

void writeBytesAtomically(const fs::path& target, std::span<const char> bytes) {
  writeAtomically(target, [&](const fs::path& temporary) {
    errno = 0;
    std::ofstream file(temporary, std::ios::binary);
    file.write(bytes.data(), std::streamsize(bytes.size()));
    file.close();
    if (file.fail())
      throw InputError("cannot write '" + target.string() +
                       "': " + (errno ? std::strerror(errno) : "the write failed") +
                       "; free space on the disk or choose another place");
  });
}

}  // namespace gib::image::detail
