// The pipeline state a pass draws with (realtime/gl/pipeline_state.h): a scope applies its state
// and its end puts back the state it found, scopes nest, the default state is a new context's,
// and nothing in realtime/ outside gl/ sets that state with raw GL calls. And uniforms set by
// name (realtime/gl/program.h): a mistyped name, a dropped uniform or a value of the wrong type is
// an error naming the program and the uniform.
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "support/gl_test_context.h"
#include "support/glsl_sources.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>
#include <glm/vec3.hpp>

#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <regex>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace gib::rt::gl {

// What a failed comparison shows (found by GoogleTest in the type's namespace).
void PrintTo(const PipelineState& s, std::ostream* out) {
  auto hex = [](GLenum e) { return fmt::format("{:#x}", e); };
  *out << "{depth_test " << (s.depth_test ? hex(*s.depth_test) : "off") << ", depth_write "
       << s.depth_write << ", blend "
       << (s.blend ? fmt::format("{:#x} {:#x} {:#x} {:#x}", s.blend->src_rgb, s.blend->dst_rgb,
                                 s.blend->src_alpha, s.blend->dst_alpha)
                   : "off")
       << ", cull_face " << (s.cull_face ? hex(*s.cull_face) : "off") << ", color_write "
       << fmt::format("{}", fmt::join(s.color_write, " ")) << ", polygon_offset "
       << (s.polygon_offset
               ? fmt::format("{} {}", s.polygon_offset->factor, s.polygon_offset->units)
               : "off")
       << ", clip_distances " << s.clip_distances << ", program_point_size " << s.program_point_size
       << ", logic_op " << (s.logic_op ? hex(*s.logic_op) : "off");
  for (const auto& [name, r] : {std::pair{"scissor", s.scissor}, {"viewport", s.viewport}})
    *out << ", " << name << " "
         << (r ? fmt::format("{} {} {} {}", r->x, r->y, r->width, r->height) : "none");
  *out << "}";
}

namespace {

namespace fs = std::filesystem;

class PipelineStateTest : public test::GlTest {};
class ProgramUniformTest : public test::GlTest {};

bool enabled(GLenum capability) {
  return glIsEnabled(capability) == GL_TRUE;
}

GLenum integer(GLenum name) {
  GLint value = 0;
  glGetIntegerv(name, &value);
  return GLenum(value);
}

PixelRect rect(GLenum name) {
  GLint v[4] = {};
  glGetIntegerv(name, v);
  return {v[0], v[1], v[2], v[3]};
}

// The state the GL holds, read back field by field.
PipelineState queryState() {
  PipelineState s;
  if (enabled(GL_DEPTH_TEST)) s.depth_test = integer(GL_DEPTH_FUNC);
  GLboolean depth_write = GL_FALSE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_write);
  s.depth_write = depth_write == GL_TRUE;
  if (enabled(GL_BLEND))
    s.blend = BlendFactors{integer(GL_BLEND_SRC_RGB), integer(GL_BLEND_DST_RGB),
                           integer(GL_BLEND_SRC_ALPHA), integer(GL_BLEND_DST_ALPHA)};
  if (enabled(GL_CULL_FACE)) s.cull_face = integer(GL_CULL_FACE_MODE);
  GLboolean color[4] = {};
  glGetBooleanv(GL_COLOR_WRITEMASK, color);
  for (int c = 0; c < 4; ++c) s.color_write[std::size_t(c)] = color[c] == GL_TRUE;
  if (enabled(GL_POLYGON_OFFSET_FILL)) {
    PolygonOffset offset{};
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &offset.factor);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &offset.units);
    s.polygon_offset = offset;
  }
  const int most_clip_distances = int(integer(GL_MAX_CLIP_DISTANCES));
  while (s.clip_distances < most_clip_distances &&
         enabled(GLenum(GL_CLIP_DISTANCE0 + s.clip_distances)))
    ++s.clip_distances;
  s.program_point_size = enabled(GL_PROGRAM_POINT_SIZE);
  if (enabled(GL_COLOR_LOGIC_OP)) s.logic_op = integer(GL_LOGIC_OP_MODE);
  if (enabled(GL_SCISSOR_TEST)) s.scissor = rect(GL_SCISSOR_BOX);
  s.viewport = rect(GL_VIEWPORT);
  return s;
}

// `state` with the viewport it would leave in place (none) replaced by the one the GL holds.
PipelineState withViewport(PipelineState state, PixelRect viewport) {
  if (!state.viewport) state.viewport = viewport;
  return state;
}

// Every field away from its default.
const PipelineState kEverything = {
    .depth_test = GL_LEQUAL,
    .depth_write = false,
    .blend = BlendFactors{GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE},
    .cull_face = GL_FRONT,
    .color_write = {true, false, true, false},
    .polygon_offset = PolygonOffset{1.5f, 2.0f},
    .clip_distances = 3,
    .program_point_size = true,
    .logic_op = GL_OR,
    .scissor = PixelRect{1, 2, 3, 4},
    .viewport = PixelRect{5, 6, 7, 8},
};

TEST_F(PipelineStateTest, TheDefaultIsWhatGlGivesANewContext) {
  const PixelRect test_viewport = rect(GL_VIEWPORT);
  ContextOptions options;
  options.debug = true;
  std::unique_ptr<Context> fresh = Context::create(options);
  const PipelineState found = queryState();
  EXPECT_EQ(found, withViewport(PipelineState{}, *found.viewport));
  fresh.reset();
  test::glTestContext().makeCurrent();
  // and the test context, between tests, holds it too: no test leaves state behind
  EXPECT_EQ(queryState(), withViewport(PipelineState{}, test_viewport));
}

TEST_F(PipelineStateTest, AScopeAppliesItsStateAndItsEndPutsBackTheStateBefore) {
  const PipelineState before = queryState();
  {
    const PipelineScope scope(kEverything);
    EXPECT_EQ(queryState(), kEverything);
  }
  EXPECT_EQ(queryState(), before);
}

TEST_F(PipelineStateTest, NestedScopesReplaceTheOuterStateWholeAndRestoreItInTurn) {
  const PipelineState before = queryState();
  const PipelineState outer = {.depth_test = GL_LESS,
                               .polygon_offset = PolygonOffset{1.0f, 1.0f},
                               .clip_distances = 2,
                               .viewport = PixelRect{0, 0, 16, 8}};
  const PipelineState inner = {.depth_write = false, .blend = kAdditiveBlend, .clip_distances = 1};
  {
    const PipelineScope outer_scope(outer);
    EXPECT_EQ(queryState(), outer);
    {
      const PipelineScope inner_scope(inner);
      // No depth test nor polygon offset inside: the inner state is whole; the viewport, which
      // it does not set, is the outer scope's.
      EXPECT_EQ(queryState(), withViewport(inner, *outer.viewport));
      {
        const PipelineScope innermost(kEverything);
        EXPECT_EQ(queryState(), kEverything);
      }
      EXPECT_EQ(queryState(), withViewport(inner, *outer.viewport));
    }
    EXPECT_EQ(queryState(), outer);
  }
  EXPECT_EQ(queryState(), before);
}

TEST_F(PipelineStateTest, AScopePutsBackTheViewportItFoundWhateverSetOneInside) {
  glViewport(0, 0, 12, 10);  // as RenderTarget::bind does, outside every scope
  {
    const PipelineScope scope({.viewport = PixelRect{1, 1, 4, 4}});
    glViewport(0, 0, 20, 20);  // a target bound inside
  }
  EXPECT_EQ(rect(GL_VIEWPORT), (PixelRect{0, 0, 12, 10}));
}

// Only realtime/gl/ turns pipeline state on and off or sets its functions with raw GL calls, so
// that outside every scope the GL holds the default state each pass may assume.
TEST(PipelineState, OnlyTheGlFolderOfTheRealtimeLayerSetsItWithRawGlCalls) {
  const fs::path root = fs::path(GIB_SOURCE_DIR) / "realtime";
  const std::regex raw(
      R"(\bgl(Enablei?|Disablei?|BlendFunc\w*|BlendEquation\w*|DepthFunc|CullFace|PolygonOffset|LogicOp|Scissor\w*)\s*\()");
  std::vector<std::string> raw_calls;
  int files = 0;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root)) {
    const std::string extension = entry.path().extension().string();
    if (extension != ".cpp" && extension != ".h") continue;
    if (entry.path().parent_path() == root / "gl") continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int number = 1; std::getline(in, line); ++number)
      if (std::regex_search(line, raw))
        raw_calls.push_back(entry.path().string() + ":" + std::to_string(number) + ": " + line);
  }
  EXPECT_GT(files, 50) << "the realtime sources were not found under " << root;
  std::ostringstream list;
  for (const std::string& call : raw_calls) list << call << "\n";
  EXPECT_TRUE(raw_calls.empty()) << "state a pass's pipeline state with gl::PipelineScope:\n"
                                 << list.str();
}

// A compute program with an active int, an active vec3 array and a uniform the linker drops.
Program uniformsProgram() {
  return buildProgram({{GL_COMPUTE_SHADER, "uniforms.comp.glsl"}}, "",
                      test::glslSources({{"uniforms.comp.glsl",
                                          "layout(local_size_x = 1) in;\n"
                                          "layout(std430, binding = 0) buffer Out { float o[]; };\n"
                                          "uniform int u_count;\n"
                                          "uniform vec3 u_directions[2];\n"
                                          "uniform float u_unread;\n"
                                          "void main() {\n"
                                          "  o[0] = float(u_count) + u_directions[1].y;\n"
                                          "}\n"}}));
}

// The message of the std::logic_error that `set` throws, or "" when it throws none.
template <typename Set>
std::string logicError(Set set) {
  try {
    set();
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

TEST_F(ProgramUniformTest, IsSetByNameAndReadsBack) {
  const Program program = uniformsProgram();
  EXPECT_EQ(program.label(), "uniforms.comp.glsl");
  program.set("u_count", 7);
  const std::vector<glm::vec3> directions = {{1, 2, 3}, {4, 5, 6}};
  program.set("u_directions", std::span<const glm::vec3>(directions));
  GLint count = 0;
  glGetUniformiv(program.id(), program.uniform("u_count"), &count);
  EXPECT_EQ(count, 7);
  float second[3] = {};
  glGetUniformfv(program.id(), glGetUniformLocation(program.id(), "u_directions[1]"), second);
  EXPECT_EQ(second[1], 5.0f);
}

TEST_F(ProgramUniformTest, AMistypedOrDroppedNameIsAnErrorNamingTheProgramAndTheUniform) {
  const Program program = uniformsProgram();
  const std::string typo = logicError([&] { program.set("u_cuont", 7); });
  EXPECT_NE(typo.find("uniforms.comp.glsl"), std::string::npos) << typo;
  EXPECT_NE(typo.find("'u_cuont'"), std::string::npos) << typo;
  EXPECT_NE(logicError([&] { program.uniform("u_cuont"); }).find("'u_cuont'"), std::string::npos);
  // Declared but never read: the linker drops it, and only setIfPresent says that is expected.
  EXPECT_FALSE(program.hasUniform("u_unread"));
  EXPECT_NE(logicError([&] { program.set("u_unread", 1.0f); }).find("'u_unread'"),
            std::string::npos);
  EXPECT_EQ(logicError([&] { program.setIfPresent("u_unread", 1.0f); }), "");
}

TEST_F(ProgramUniformTest, AValueOfAnotherTypeIsAnErrorAndIsNotSet) {
  const Program program = uniformsProgram();
  const std::string wrong_type = logicError([&] { program.set("u_count", 7.0f); });
  EXPECT_NE(wrong_type.find("'u_count' is a GLSL int, set as float"), std::string::npos)
      << wrong_type;
  const std::vector<glm::vec3> three(3, glm::vec3(0.0f));
  EXPECT_NE(logicError([&] {
              program.set("u_directions", std::span<const glm::vec3>(three));
            }).find("holds 2 vec3, set with 3"),
            std::string::npos);
  GLint count = -1;
  glGetUniformiv(program.id(), program.uniform("u_count"), &count);
  EXPECT_EQ(count, 0) << "a refused value is not set";
}

}  // namespace
}  // namespace gib::rt::gl
