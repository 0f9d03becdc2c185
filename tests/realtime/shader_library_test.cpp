#include "realtime/gl/shader_library.h"

#include "support/gl_test_context.h"
#include "support/glsl_sources.h"

#include <gtest/gtest.h>

#include <utility>

namespace gib::rt::gl {
namespace {

using test::glslSources;
using test::glTestContext;

// Programs built through the driver; any GL error other than the expected ones fails a test.
class ShaderBuild : public test::GlTest {};

bool contains(const std::string& text, std::string_view part) {
  return text.find(part) != std::string::npos;
}

TEST(ShaderLibrary, ExpandsNestedIncludesAndMapsEachLineToItsFile) {
  const GlslLookup sources = glslSources({{"main.glsl", "#include \"a.glsl\"\nvoid main() {}\n"},
                                          {"a.glsl", "float a;\n#include \"b.glsl\"\nfloat a2;\n"},
                                          {"b.glsl", "float b;\n"}});
  const ExpandedSource out = expandIncludes("main.glsl", "#define N 4", sources);
  EXPECT_EQ(out.files, (std::vector<std::string>{"main.glsl", "a.glsl", "b.glsl"}));
  EXPECT_EQ(out.text,
            "#version 450 core\n"
            "#define N 4\n"
            "float a;\n"
            "float b;\n"
            "float a2;\n"
            "void main() {}\n");
  constexpr int kDefines = SourceLine::kDefinesFile;
  // After an include the count resumes where it was: "float a2;" is line 3 of a.glsl.
  EXPECT_EQ(out.lines, (std::vector<SourceLine>{
                           {kDefines, 0}, {kDefines, 1}, {1, 1}, {2, 1}, {1, 3}, {0, 2}}));
}

TEST(ShaderLibrary, IncludesAFileOnce) {
  const GlslLookup sources =
      glslSources({{"main.glsl", "#include \"a.glsl\"\n#include \"b.glsl\"\n"},
                   {"a.glsl", "#include \"common.glsl\"\n"},
                   {"b.glsl", "  #include \"common.glsl\"\n"},
                   {"common.glsl", "const float PI = 3.14159265;\n"}});
  const ExpandedSource out = expandIncludes("main.glsl", "", sources);
  EXPECT_EQ(out.files.size(), 4u);
  const std::size_t first = out.text.find("const float PI");
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(out.text.find("const float PI", first + 1), std::string::npos) << out.text;
}

// A header shared with C++ (`*_shared.h`): GLSL gets what is outside `#ifdef __cplusplus` and
// what follows its `#else`, with conditionals nested on either side, and no `#pragma once`.
TEST(ShaderLibrary, ReadsTheGlslSideOfASharedHeader) {
  const GlslLookup sources = glslSources(
      {{"main.glsl", "#include \"x_shared.h\"\nvoid main() {}\n"},
       {"x_shared.h",
        "#pragma once\n#ifdef __cplusplus\n#include <glm/vec3.hpp>\n#if 1\nnamespace a {\n#else\n"
        "#endif\n#else\n#define GLSL_ONLY 1\n#ifdef N\nfloat n;\n#endif\n#endif\n"
        "const int kShared = 2;\n#ifdef __cplusplus\n}\n#endif\n"}});
  const ExpandedSource out = expandIncludes("main.glsl", "", sources);
  EXPECT_EQ(out.text,
            "#version 450 core\n"
            "#define GLSL_ONLY 1\n"
            "#ifdef N\n"
            "float n;\n"
            "#endif\n"
            "const int kShared = 2;\n"
            "void main() {}\n");
  // Kept lines still map to their own lines of the header.
  EXPECT_EQ(out.lines[1], (SourceLine{1, 9}));
  EXPECT_EQ(out.lines[5], (SourceLine{1, 14}));
}

TEST(ShaderLibrary, AnUnclosedCppBlockIsAShaderError) {
  const GlslLookup sources = glslSources({{"y_shared.h", "#ifdef __cplusplus\nnamespace a {\n"}});
  EXPECT_THROW(expandIncludes("y_shared.h", "", sources), ShaderError);
}

TEST(ShaderLibrary, AnIncludeCycleIsAShaderError) {
  const GlslLookup sources =
      glslSources({{"a.glsl", "#include \"b.glsl\"\n"}, {"b.glsl", "#include \"a.glsl\"\n"}});
  EXPECT_THROW(expandIncludes("a.glsl", "", sources), ShaderError);
}

TEST(ShaderLibrary, VersionDirectivesAndMissingFilesAreShaderErrors) {
  const GlslLookup sources = glslSources({{"v.glsl", "float x;\n#version 330\n"},
                                          {"bad.glsl", "#include missing-quotes\n"},
                                          {"m.glsl", "#include \"nowhere.glsl\"\n"}});
  try {
    expandIncludes("v.glsl", "", sources);
    FAIL() << "expected a ShaderError";
  } catch (const ShaderError& e) {
    EXPECT_TRUE(contains(e.what(), "v.glsl:2")) << e.what();
  }
  EXPECT_THROW(expandIncludes("bad.glsl", "", sources), ShaderError);
  EXPECT_THROW(expandIncludes("m.glsl", "", sources), ShaderError);
  EXPECT_THROW(glslFile("no/such/file.glsl"), ShaderError);  // the embedded files
}

TEST(ShaderLibrary, TranslatesMesaAndNvidiaInfoLogLocations) {
  const GlslLookup sources =
      glslSources({{"main.frag.glsl", "#include \"lib/common.glsl\"\nvoid main() {}\n"},
                   {"lib/common.glsl", "float a;\nfloat b;\nfloat c;\n"}});
  // Expanded lines: 1 #version, 2–3 defines, 4–6 lib/common.glsl 1–3, 7 main.frag.glsl 2.
  const ExpandedSource source =
      expandIncludes("main.frag.glsl", "#define A 1\n#define B 2\n", sources);
  EXPECT_EQ(translateInfoLog("0:5(12): error: `x' undeclared\n", source),
            "lib/common.glsl:2: error: `x' undeclared");
  EXPECT_EQ(translateInfoLog("0(5) : error C1008: undefined variable \"x\"", source),
            "lib/common.glsl:2 : error C1008: undefined variable \"x\"");
  // Mesa sometimes names another source string; the line alone decides.
  EXPECT_EQ(translateInfoLog("1:7(1): error: a\n0:6(2): warning: b\n", source),
            "main.frag.glsl:2: error: a\nlib/common.glsl:3: warning: b");
  EXPECT_EQ(translateInfoLog("0:3(1): error: c", source), "defines:2: error: c");
  EXPECT_EQ(translateInfoLog("0:99(1): error: d", source), "?:99: error: d");
  EXPECT_EQ(translateInfoLog("no location here", source), "no location here");
}

const GlslLookup kProgramSources = glslSources(
    {{"test/fullscreen.vert.glsl",
      "void main() { gl_Position = vec4(vec2(gl_VertexID & 1, gl_VertexID >> 1), 0.0, 1.0); }\n"},
     {"test/lib.glsl", "float brighten(float x) {\n  return x * 2.0;\n}\n"},
     {"test/good.frag.glsl",
      "#include \"test/lib.glsl\"\nlayout(location = 0) out vec4 color;\n"
      "void main() { color = vec4(brighten(0.25 * SCALE)); }\n"},
     {"test/broken_lib.glsl", "float brighten(float x) {\n  return x * 2.0;\n  return y;\n}\n"},
     {"test/includes_broken.frag.glsl", "#include \"test/broken_lib.glsl\"\nvoid main() {}\n"},
     {"test/broken_after_include.frag.glsl",
      "#include \"test/lib.glsl\"\n\nvoid main() {\n  undeclared = 1.0;\n}\n"},
     {"test/no_main.frag.glsl", "float f() { return 1.0; }\n"}});

// Compile and link errors also reach KHR_debug as GL errors; here they are what is expected.
std::string buildError(std::initializer_list<ShaderStage> stages) {
  try {
    buildProgram(stages, "", kProgramSources);
  } catch (const ShaderError& e) {
    glTestContext().takeDebugErrors();
    return e.what();
  }
  ADD_FAILURE() << "the program built";
  return "";
}

TEST_F(ShaderBuild, BuildsAProgramFromInMemorySourcesWithDefines) {
  const Program program = buildProgram({{GL_VERTEX_SHADER, "test/fullscreen.vert.glsl"},
                                        {GL_FRAGMENT_SHADER, "test/good.frag.glsl"}},
                                       "#define SCALE 2.0\n", kProgramSources);
  GLint linked = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
  EXPECT_TRUE(linked);
}

TEST_F(ShaderBuild, ACompileErrorInAnIncludedFileNamesThatFileAndLine) {
  const std::string error = buildError({{GL_VERTEX_SHADER, "test/fullscreen.vert.glsl"},
                                        {GL_FRAGMENT_SHADER, "test/includes_broken.frag.glsl"}});
  EXPECT_TRUE(contains(error, "fragment shader test/includes_broken.frag.glsl")) << error;
  EXPECT_TRUE(contains(error, "test/broken_lib.glsl:3")) << error;
  EXPECT_FALSE(contains(error, "includes_broken.frag.glsl:3")) << error;  // Mesa's source 0
}

TEST_F(ShaderBuild, ACompileErrorAfterAnIncludeHasTheLineOfItsOwnFile) {
  const std::string error =
      buildError({{GL_VERTEX_SHADER, "test/fullscreen.vert.glsl"},
                  {GL_FRAGMENT_SHADER, "test/broken_after_include.frag.glsl"}});
  EXPECT_TRUE(contains(error, "test/broken_after_include.frag.glsl:4")) << error;
}

TEST_F(ShaderBuild, AnErrorInTheDefinesNamesTheirLine) {
  try {
    buildProgram({{GL_FRAGMENT_SHADER, "test/good.frag.glsl"}}, "#define SCALE 2.0\n#error bad\n",
                 kProgramSources);
    FAIL() << "the program built";
  } catch (const ShaderError& e) {
    glTestContext().takeDebugErrors();
    EXPECT_TRUE(contains(e.what(), "defines:2")) << e.what();
  }
}

TEST_F(ShaderBuild, ALinkErrorNamesTheStages) {
  const std::string error = buildError({{GL_VERTEX_SHADER, "test/fullscreen.vert.glsl"},
                                        {GL_FRAGMENT_SHADER, "test/no_main.frag.glsl"}});
  EXPECT_TRUE(contains(error, "does not link")) << error;
  EXPECT_TRUE(contains(error, "test/no_main.frag.glsl")) << error;
}

// Every layered program of the project builds on both paths of buildLayeredProgram: the vertex
// shader writing gl_Layer (llvmpipe has the extension) and the pass-through geometry shader of
// drivers without it, whose inputs and outputs must match the stages around it.
TEST_F(ShaderBuild, LayeredProgramsBuildWithAndWithoutVertexShaderLayers) {
  const LayeredStages shadow = {"realtime/lighting/shadow.vert.glsl",
                                "realtime/lighting/shadow.geom.glsl",
                                "realtime/lighting/shadow.frag.glsl"};
  const LayeredStages visibility = {
      "realtime/techniques/stochastic_radiosity/visibility.vert.glsl",
      "realtime/techniques/stochastic_radiosity/visibility.geom.glsl",
      "realtime/techniques/stochastic_radiosity/visibility.frag.glsl"};
  const std::pair<const LayeredStages*, const char*> programs[] = {
      {&shadow, "#define POINT_LIGHT 1\n"},
      {&shadow, "#define POINT_LIGHT 1\n#define VARIANCE_SHADOW_MAP 1\n"},
      {&shadow, ""},
      {&visibility, "#define HEMICUBE\n"},
      {&visibility, ""}};
  for (const auto& [stages, defines] : programs)
    for (const bool geometry_only : {false, true}) {
      const Program program = buildLayeredProgram(*stages, defines, geometry_only);
      GLint linked = 0;
      glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
      EXPECT_TRUE(linked) << stages->vertex << " " << defines << " " << geometry_only;
      GLint shaders = 0;
      glGetProgramiv(program.id(), GL_ATTACHED_SHADERS, &shaders);
      if (geometry_only) {
        EXPECT_EQ(shaders, 3) << "the geometry shader path";
      }
    }
}

}  // namespace
}  // namespace gib::rt::gl
