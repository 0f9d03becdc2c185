// Declared passes: the tree a technique's profile may hold, the names suites look passes up by,
// and the mistakes in a declaration that the code refuses.
#include "realtime/pass_declarations.h"

#include "realtime/technique.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

namespace gib::rt {
namespace {

TEST(PassDeclarations, FindsAPassByPathOrByItsNameUnderTheFrame) {
  PassDeclarations passes;
  passes.add("frame/lights", "l").add("frame/lights/shadow map", "s").add("iteration", "i");
  passes.add("iteration/update", "u");
  EXPECT_EQ(passes.find("frame/lights/shadow map")->path, "frame/lights/shadow map");
  EXPECT_EQ(passes.find("shadow map")->path, "frame/lights/shadow map");
  EXPECT_EQ(passes.find("frame")->path, "frame");
  EXPECT_EQ(passes.find("iteration/update")->path, "iteration/update");
  // An iteration's pass is named with its root: "update" alone would read as a frame's pass.
  EXPECT_FALSE(passes.declares("update"));
  EXPECT_FALSE(passes.declares("frame/shadow map"));
  EXPECT_FALSE(passes.declares("lights/shadow map"));
}

TEST(PassDeclarations, RefusesAPassBeforeItsParentOrOutsideTheRoots) {
  PassDeclarations passes;
  EXPECT_THROW(passes.add("frame/lights/shadow map", "s"), std::logic_error);
  EXPECT_THROW(passes.add("iteration/update", "u"), std::logic_error);
  EXPECT_THROW(passes.add("shading", "no root"), std::logic_error);
}

// A name used twice under one root would make a suite's "shadow map" ambiguous.
TEST(PassDeclarations, RefusesANameTwiceUnderOneRoot) {
  PassDeclarations passes;
  passes.add("frame/lights", "l").add("frame/lights/relight", "r");
  EXPECT_THROW(passes.add("frame/relight", "again"), std::logic_error);
  passes.add("iteration", "i");
  EXPECT_NO_THROW(passes.add("iteration/relight", "another root"));
}

// Every technique of the catalogue: paths start at a root, names are unique per root (add()
// checks both), and every declared path's parent is declared, so the tree the report draws is
// whole.
TEST(PassDeclarations, EveryTechniqueDeclaresAWholeTree) {
  for (const TechniqueInfo& info : techniqueCatalogue()) {
    std::set<std::string> paths;
    for (const DeclaredPass& pass : info.passes.passes()) {
      EXPECT_FALSE(pass.description.empty()) << info.name << " " << pass.path;
      const std::size_t slash = pass.path.rfind('/');
      if (slash != std::string::npos) {
        EXPECT_TRUE(paths.contains(pass.path.substr(0, slash))) << info.name << " " << pass.path;
      }
      paths.insert(pass.path);
    }
    EXPECT_TRUE(paths.contains("frame")) << info.name;
  }
}

}  // namespace
}  // namespace gib::rt
