#include "support/gl_test_context.h"

namespace gib::test {

rt::gl::Context& glTestContext() {
  // Leaked on purpose: destroying a context after main() races the driver's own teardown.
  static rt::gl::Context* context = [] {
    rt::gl::ContextOptions options;
    options.debug = true;
    return rt::gl::Context::create(options).release();
  }();
  return *context;
}

void GlTest::SetUp() {
  glTestContext().makeCurrent();
  glTestContext().takeDebugErrors();  // a failed earlier test must not fail this one
}

void GlTest::TearDown() {
  for (const std::string& error : glTestContext().takeDebugErrors()) ADD_FAILURE() << error;
}

}  // namespace gib::test
