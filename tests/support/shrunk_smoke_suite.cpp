#include "support/shrunk_smoke_suite.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

namespace gib::test {

std::string shrunkSmokeSuite() {
  std::ifstream in(std::filesystem::path(GIB_SOURCE_DIR) / "suites" / "smoke.toml");
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  text = std::regex_replace(text, std::regex(R"((width|height) = \d+)"), "$1 = 32");
  text = std::regex_replace(text, std::regex(R"(spp = \d+)"), "spp = 64");
  text = std::regex_replace(text, std::regex(R"(checkpoints = \[[^\]]*\])"),
                            "checkpoints = [4, 16, 64]");
  return text;
}

}  // namespace gib::test
