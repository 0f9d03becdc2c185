// `gibench export-blender` as a user runs it: a script Python can compile, warnings for what
// Cycles cannot reproduce, and bad input refused with one line and no file.
#include "support/run_command.h"
#include "support/temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace gib::test {
namespace {

namespace fs = std::filesystem;

std::string fileText(const fs::path& path) {
  std::ifstream stream(path);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

TEST(ExportBlenderCommand, WritesAScriptPythonCompiles) {
  TempDir dir;
  const std::string out = (dir / "cornell.py").string();
  CommandResult r =
      runGibench({"export-blender", "--scene", "cornell", "--scene-set", "blocks=false", "--width",
                  "64", "--height", "48", "--spp", "16", "--seed", "3", "--out", out},
                 dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;  // the empty Cornell box maps exactly: no warning
  EXPECT_NE(r.out.find("64x48, 16 spp, seed 3"), std::string::npos) << r.out;
  const std::string script = fileText(out);
  EXPECT_NE(script.find("\"spp\": 16, \"seed\": 3"), std::string::npos);
  EXPECT_NE(script.find("bpy.ops.render.render(write_still=True)"), std::string::npos);
  // Blender is not needed to know the script is valid Python.
  CommandResult compiled = runProgram(
      {"python3", "-c", "import ast, sys; ast.parse(open(sys.argv[1]).read())", out}, dir.path());
  EXPECT_EQ(compiled.exit_code, 0) << compiled.err;
}

TEST(ExportBlenderCommand, WarnsOnStderrWhenTheSceneIsNotMappedExactly) {
  TempDir dir;
  CommandResult r = runGibench(
      {"export-blender", "--scene", "chamber", "--out", (dir / "chamber.py").string()}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(countLines(r.err), 2) << r.err;
  EXPECT_NE(r.err.find("gibench: warning: scene 'chamber' is not mapped exactly: Phong"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(fs::exists(dir / "chamber.py"));
}

TEST(ExportBlenderCommand, BadInputExitsWithCodeTwoOneLineAndNoFile) {
  TempDir dir;
  const std::string out = (dir / "scene.py").string();
  struct Case {
    std::vector<std::string> args;
    std::string message_part;
  };
  const std::vector<Case> cases = {
      {{"--scene", "cornel", "--out", out}, "unknown scene 'cornel'"},
      {{"--scene", "cornell", "--scene-set", "blocks=maybe", "--out", out}, "blocks"},
      {{"--scene", "cornell", "--spp", "0", "--out", out}, "--spp"},
      {{"--scene", "cornell", "--seed", "4294967296", "--out", out}, "--seed"},
      {{"--scene", "cornell", "--out", (dir / "scene.txt").string()}, ".py"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"export-blender"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    CommandResult r = runGibench(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << c.message_part << ": " << r.err;
    EXPECT_EQ(countLines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.message_part), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_empty(dir.path())) << c.message_part;
  }
}

}  // namespace
}  // namespace gib::test
