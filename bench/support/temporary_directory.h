// A fresh directory under the system's temporary directory for a benchmark's files, removed
// with everything in it when the object goes (the tests' TempDir, without GoogleTest).
#pragma once

#include <filesystem>
#include <string>

namespace gib::bench {

class TemporaryDirectory {
 public:
  explicit TemporaryDirectory(const std::string& stem);
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace gib::bench
