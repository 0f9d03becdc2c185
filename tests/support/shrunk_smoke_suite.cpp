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
  return std::regex_replace(shrunk("suites/smoke.toml"), std::regex(R"(checkpoints = \[[^\]]*\])"),
                            "checkpoints = [4, 16, 64]");
}

std::string shrunkFigureSuite(const std::string& name) {
  return shrunk(std::filesystem::path("suites/figures") / (name + ".toml"));
}

}  // namespace gib::test
