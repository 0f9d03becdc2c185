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

// Typed parameters: a switch reads as a bool, an integer choice as an int, and each keeps the
// canonical text that job ids and hashes were made of before the types existed.
TEST(Parameters, BooleansAndIntegerChoicesAreTyped) {
  const ParameterTable table = joinParameterTables(
      {{booleanParameter("reuse", true, "keep the records")},
       {integerChoiceParameter("atlas", 128, {64, 128, 256}, "texels", "atlas side")}});
  const ParameterValues defaults = parseParameters(table, {}, "technique 'x'");
  EXPECT_TRUE(defaults.boolean("reuse"));
  EXPECT_EQ(defaults.integer("atlas"), 128);
  const ParameterValues set = parseParameters(table, {"reuse=false", "atlas=256"}, "x");
  EXPECT_FALSE(set.boolean("reuse"));
  EXPECT_EQ(set.integer("atlas"), 256);
  EXPECT_EQ(set.canonical(), (std::vector<std::pair<std::string, std::string>>{{"reuse", "false"},
                                                                               {"atlas", "256"}}));
  try {
    parseParameters(table, {"reuse=yes"}, "technique 'x'");
    ADD_FAILURE() << "reuse=yes was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("give a boolean in true|false"), std::string::npos)
        << e.what();
  }
  try {
    parseParameters(table, {"atlas=100"}, "technique 'x'");
    ADD_FAILURE() << "atlas=100 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("64|128|256"), std::string::npos) << e.what();
  }
  EXPECT_NE(describeParameters(table)[1].find("atlas (integer choice, default 128"),
            std::string::npos);
}

// Reading a parameter as another type than it is declared is a mistake in the code that reads
// it, not in anyone's input: a logic error, not a silent zero or a string compare.
TEST(Parameters, ReadingAsAnotherTypeIsALogicError) {
  const ParameterValues v = parseParameters(kTable, {}, "x");
  EXPECT_THROW(v.integer("shadow"), std::logic_error);
  EXPECT_THROW(v.boolean("detail"), std::logic_error);
  EXPECT_THROW(v.vector3("albedo"), std::logic_error);
  EXPECT_THROW(v.number("light_position"), std::logic_error);
  EXPECT_THROW(v.text("missing"), std::logic_error);
  EXPECT_DOUBLE_EQ(v.number("detail"), 1.0);  // an integer is a number
}

TEST(Parameters, JoinedTablesKeepTheirOrderAndRefuseANameTwice) {
  const ParameterTable joined = joinParameterTables({{kTable[0], kTable[1]}, {kTable[3]}});
  ASSERT_EQ(joined.size(), 3u);
  EXPECT_EQ(joined[0].name, "detail");
  EXPECT_EQ(joined[2].name, "shadow");
  EXPECT_THROW(joinParameterTables({{kTable[0]}, {kTable[0]}}), std::logic_error);
}

}  // namespace
}  // namespace gib
