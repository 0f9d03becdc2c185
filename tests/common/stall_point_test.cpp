// common/stall_point.h: the kill test (scripts/faults-kill.sh) relies on a stall happening at the
// points GIB_STALL_AT matches, and only there, and on its line on stderr.
#include "common/stall_point.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>

#include "common/input_error.h"

namespace gib {
namespace {

using ::testing::HasSubstr;

class StallPointTest : public ::testing::Test {
 protected:
  ~StallPointTest() override {
    unsetenv("GIB_STALL_AT");
    unsetenv("GIB_STALL_MS");
  }
};

TEST_F(StallPointTest, AMatchingPointPrintsItsNameAndHoldsForTheGivenTime) {
  setenv("GIB_STALL_AT", "write:*.json", 1);
  setenv("GIB_STALL_MS", "50", 1);
  ::testing::internal::CaptureStderr();
  const auto start = std::chrono::steady_clock::now();
  stallPoint("write:results.json");
  const auto held = std::chrono::steady_clock::now() - start;
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "gibench: stalled at write:results.json\n");
  EXPECT_GE(held, std::chrono::milliseconds(50));  // a sleep lasts at least its duration
}

TEST_F(StallPointTest, OtherPointsAndAnUnsetVariableDoNotStall) {
  setenv("GIB_STALL_MS", "0", 1);
  ::testing::internal::CaptureStderr();
  stallPoint("history-commit");  // GIB_STALL_AT unset
  setenv("GIB_STALL_AT", "", 1);
  stallPoint("history-commit");
  setenv("GIB_STALL_AT", "write:*.json", 1);
  stallPoint("write:index.html");
  stallPoint("history-commit");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST_F(StallPointTest, ADurationThatIsNotANumberIsAnInputError) {
  setenv("GIB_STALL_AT", "store-entry", 1);
  setenv("GIB_STALL_MS", "5s", 1);
  try {
    stallPoint("store-entry");
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("GIB_STALL_MS is '5s'"));
  }
}

}  // namespace
}  // namespace gib
