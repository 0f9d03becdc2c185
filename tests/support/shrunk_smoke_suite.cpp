#include "support/shrunk_smoke_suite.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

namespace gib::test {

namespace {

std::string shrunk(const std::filesystem::path& relative) {
  std::ifstream in(std::filesystem::path(GIB_SOURCE_DIR) / relative);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  text = std::regex_replace(text, std::regex(R"((width|height) = \d+)"), "$1 = 32");
  return std::regex_replace(text, std::regex(R"(spp = \d+)"), "spp = 64");
}

}  // namespace

std::string shrunkSmokeSuite() {
  std::string text =
      std::regex_replace(shrunk("suites/smoke.toml"), std::regex(R"(checkpoints = \[[^\]]*\])"),
                         "checkpoints = [4, 16, 64]");
  // Fewer frames and light samples: under the sanitizers a VSM frame of 16 light samples takes
  // 1.5 s on llvmpipe whatever the image size (its shadow maps keep their size), and the tests
  // that run this suite check the harness, not the technique.
  text = std::regex_replace(text, std::regex(R"(frames = \d+)"), "frames = 3");
  text = std::regex_replace(text, std::regex(R"(warmup = \d+)"), "warmup = 1");
  return std::regex_replace(text, std::regex(R"(light_samples = \d+)"), "light_samples = 4");
}

std::string shrunkFigureSuite(const std::string& name) {
  return shrunk(std::filesystem::path("suites/figures") / (name + ".toml"));
}

}  // namespace gib::test
