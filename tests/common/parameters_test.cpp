#include "common/parameters.h"
#include "common/input_error.h"

#include <gtest/gtest.h>

namespace gib {
namespace {

const ParameterTable kTable = {
    {"detail", ParameterType::kInteger, "1", 1, 4, {}, "", "tessellation level"},
    {"albedo", ParameterType::kNumber, "0.9", 0, 1, {}, "", "single-scattering albedo"},
    {"light_position", ParameterType::kVector3, "0,2.5,0", -100, 100, {}, "m", "spot position"},
    {"shadow", ParameterType::kChoice, "hard", 0, 0, {"hard", "pcf", "vsm"}, "", "shadow filter"},
};

std::string errorOf(const std::vector<std::string>& assignments) {
  try {
    parseParameters(kTable, assignments, "scene 'x'");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Parameters, DefaultsAndAssignmentsAreCanonical) {
  ParameterValues v = parseParameters(kTable, {"albedo=0.50", "light_position=1, 2,3"}, "x");
  EXPECT_EQ(v.integer("detail"), 1);
  EXPECT_DOUBLE_EQ(v.number("albedo"), 0.5);
  EXPECT_EQ(v.text("albedo"), "0.5");
  EXPECT_EQ(v.vector3("light_position"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(v.text("shadow"), "hard");
  ASSERT_EQ(v.canonical().size(), 4u);
  EXPECT_EQ(v.canonical()[2].second, "1,2,3");
}

TEST(Parameters, ErrorsNameTheParameterAndTheFix) {
  EXPECT_NE(errorOf({"detial=2"}).find("its parameters are detail, albedo"), std::string::npos);
  EXPECT_NE(errorOf({"detail=7"}).find("[1, 4]"), std::string::npos);
  EXPECT_NE(errorOf({"detail=1.5"}).find("not an integer"), std::string::npos);
  EXPECT_NE(errorOf({"albedo=nan"}).find("not a number"), std::string::npos);
  EXPECT_NE(errorOf({"shadow=soft"}).find("hard|pcf|vsm"), std::string::npos);
  EXPECT_NE(errorOf({"light_position=1,2"}).find("three components"), std::string::npos);
  EXPECT_NE(errorOf({"albedo=0.1", "albedo=0.2"}).find("twice"), std::string::npos);
  EXPECT_NE(errorOf({"albedo"}).find("key=value"), std::string::npos);
  EXPECT_EQ(errorOf({"detail=2"}), "");
}

TEST(Parameters, DescribesEveryParameter) {
  std::vector<std::string> lines = describeParameters(kTable);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_NE(lines[0].find("detail (integer, default 1, [1, 4])"), std::string::npos);
  EXPECT_NE(lines[3].find("hard|pcf|vsm"), std::string::npos);
}

}  // namespace
}  // namespace gib
