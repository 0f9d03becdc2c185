// One headless GL context for the whole test binary (creating one per test would cost more than
// most tests), with KHR_debug output on: a fixture that derives from GlTest fails any test during
// which GL reported an error.
#pragma once

#include "realtime/gl/context.h"

#include <gtest/gtest.h>

namespace gib::test {

rt::gl::Context& glTestContext();

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
};

}  // namespace gib::test
