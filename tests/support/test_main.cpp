// The test binary's entry point: GoogleTest's, with the leak check done while every thread is
// parked (common/quiescent_leak_check.h says why the exit-time check can crash).
#include "common/quiescent_leak_check.h"

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const int exit_code = RUN_ALL_TESTS();
  gib::checkLeaksWhileQuiescent();
  return exit_code;
}
