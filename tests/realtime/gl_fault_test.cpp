// GL failures as a user meets them (realtime/gl/fault_injection.h injects them where a real
// driver's failure is detected): a shader the driver rejects, a texture it cannot allocate, a
// context it cannot make. Each reaches runTechnique's caller as a gib::EnvironmentError of one
// line naming the technique and the cause.
#include "common/environment_error.h"
#include "common/input_error.h"
#include "realtime/gl/fault_injection.h"
#include "realtime/technique.h"
#include "realtime/technique_runner.h"
#include "scene/builtin_scenes.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace gib::rt {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

class GlFaultTest : public ::testing::Test {
 protected:
  ~GlFaultTest() override { unsetenv("GIB_GL_FAULT"); }

  // What running `direct` on the Cornell box throws with GIB_GL_FAULT=fault.
  static std::string failureOf(const char* fault) {
    setenv("GIB_GL_FAULT", fault, 1);
    const TechniqueInfo& info = findTechnique("direct");
    TechniqueRunSettings settings;
    settings.width = settings.height = 16;
    settings.warmup_frames = 0;
    settings.frames = 1;
    try {
      runTechnique(scene::loadScene("cornell"), info,
                   parseParameters(info.parameters, {}, "technique 'direct'"), settings);
    } catch (const EnvironmentError& e) {
      return e.what();
    }
    return "no EnvironmentError";
  }
};

TEST_F(GlFaultTest, EachFailureIsOneLineNamingTheTechniqueAndTheCause) {
  const std::pair<const char*, const char*> cases[] = {
      {"shader-compile", "shader realtime/gbuffer/gbuffer.vert.glsl does not compile: "},
      {"texture-out-of-memory", "out of GPU memory for a "},
      {"context", "cannot create a GL context"}};
  for (const auto& [fault, cause] : cases) {
    const std::string message = failureOf(fault);
    EXPECT_THAT(message, StartsWith("technique 'direct': ")) << fault;
    EXPECT_THAT(message, HasSubstr(cause)) << fault;
    EXPECT_THAT(message, Not(HasSubstr("\n"))) << fault;
  }
}

TEST_F(GlFaultTest, WithoutAFaultTheTechniqueRuns) {
  setenv("GIB_GL_FAULT", "", 1);
  EXPECT_FALSE(gl::glFaultInjected(gl::GlFault::kShaderCompile));
  EXPECT_EQ(failureOf(""), "no EnvironmentError");
}

TEST_F(GlFaultTest, ListsNameSeveralFaultsAndAnUnknownOneIsAnInputError) {
  setenv("GIB_GL_FAULT", "context,texture-out-of-memory", 1);
  EXPECT_TRUE(gl::glFaultInjected(gl::GlFault::kContext));
  EXPECT_TRUE(gl::glFaultInjected(gl::GlFault::kTextureOutOfMemory));
  EXPECT_FALSE(gl::glFaultInjected(gl::GlFault::kShaderCompile));
  setenv("GIB_GL_FAULT", "shader-compile,oops", 1);
  EXPECT_THROW(gl::glFaultInjected(gl::GlFault::kShaderCompile), InputError);
}

}  // namespace
}  // namespace gib::rt
