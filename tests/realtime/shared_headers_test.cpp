// The headers C++ and GLSL share (`*_shared.h`, docs/architecture.md "Declared GPU layouts"):
// all of them compile together on both sides (one namespace in C++, one global scope in GLSL, so
// a clash fails here), and the constants and functions the GPU evaluates equal the C++ ones.
// Every shared header, generated from the build's list of them (realtime/CMakeLists.txt).
#include "gib/all_shared_headers.h"
#include "realtime/gl/shader_library.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace gib::rt {
namespace {

class SharedHeaders : public test::GlTest {};

// Every embedded shared header, so that a new one is covered without editing this test (the
// C++ side includes the same list, generated: gib/all_shared_headers.h).
std::vector<std::string> sharedHeaders() {
  std::vector<std::string> paths;
  for (const EmbeddedFile& file : gl::embeddedShaderFiles())
    if (file.path.ends_with("_shared.h")) paths.emplace_back(file.path);
  return paths;
}

// The GPU's values of a list of integer expressions, in order.
std::vector<int> evaluateOnGpu(const std::vector<std::string>& expressions) {
  std::string source;
  for (const std::string& header : sharedHeaders()) source += "#include \"" + header + "\"\n";
  source +=
      "layout(local_size_x = 1) in;\n"
      "layout(std430, binding = kTestFirstStorageBinding) buffer Results { int results[]; };\n"
      "void main() {\n";
  for (std::size_t i = 0; i < expressions.size(); ++i)
    source += "  results[" + std::to_string(i) + "] = " + expressions[i] + ";\n";
  source += "}\n";
  const gl::Program program = gl::buildProgram(
      {{GL_COMPUTE_SHADER, "test/shared.comp.glsl"}}, "",
      [&](std::string_view path) -> std::string_view {
        return path == "test/shared.comp.glsl" ? std::string_view(source) : gl::glslFile(path);
      });
  std::vector<int> results(expressions.size(), -12345);
  const gl::Buffer buffer = gl::Buffer::fromVector(results);
  buffer.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTestFirstStorageBinding);
  program.use();
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(results.size() * sizeof(int)), results.data());
  return results;
}

TEST_F(SharedHeaders, ConstantsAndFunctionsAreTheSameOnTheGpu) {
  using namespace gpu;
  std::vector<std::pair<std::string, int>> cases = {
      {"kGBufferNormalUnit", kGBufferNormalUnit},
      {"kShadowMapUnit", kShadowMapUnit},
      {"kAtlasEmissionUnit", kAtlasEmissionUnit},
      {"kMaterialsUnit", kMaterialsUnit},
      {"kMaterialTexels", kMaterialTexels},
      {"kCameraBinding", kCameraBinding},
      {"kLightSamplesBinding", kLightSamplesBinding},
      {"kShadowFacesBinding", kShadowFacesBinding},
      {"kGBufferViewsBinding", kGBufferViewsBinding},
      {"kMaxGBufferViewsPerDraw", kMaxGBufferViewsPerDraw},
      {"kMaxLightBatch", kMaxLightBatch},
      {"kMaxShadowFaces", kMaxShadowFaces},
      {"kMaterialPhong", kMaterialPhong},
      {"kVertexAtlasUvLocation", kVertexAtlasUvLocation},
      {"kVertexInstanceLocation", kVertexInstanceLocation},
      {"kMaxVertexInstances", kMaxVertexInstances},
      {"kVsmBlurGroupSize", kVsmBlurGroupSize},
      {"kVsmBlurSegment", kVsmBlurSegment},
      {"kShMaxCoefficients", kShMaxCoefficients},
      {"shCoefficientCount(1)", shCoefficientCount(1)},
      {"shBand(8)", shBand(8)},
      {"shBand(9)", shBand(9)},
      {"kProbeCoefficientsBinding", kProbeCoefficientsBinding},
      {"kProbeCoefficientsUnit", kProbeCoefficientsUnit},
      {"kProjectionWeightsBinding", kProjectionWeightsBinding},
      {"probeCoefficientIndex(3, 5)", probeCoefficientIndex(3, 5)},
      {"probeTile(7, 4)", probeTile(7, 4)},
      {"tileOrigin(probeTile(7, 4), 9, 16).x", tileOrigin(probeTile(7, 4), 9, 16).x},
      {"tileOrigin(probeTile(7, 4), 9, 16).y", tileOrigin(probeTile(7, 4), 9, 16).y},
      {"kShootersBinding", kShootersBinding},
      {"kVisibilityUnit", kVisibilityUnit},
      {"kRadiosityPowerUnit", kRadiosityPowerUnit},
      {"kPyramidLevelsPerPass", kPyramidLevelsPerPass},
      {"kDescentGroupSize", kDescentGroupSize},
      {"kSelectedPanesBinding", kSelectedPanesBinding},
      {"kPanesUnit", kPanesUnit},
      {"kIndirectUnit", kIndirectUnit},
      {"int(luminance(vec3(1.0, 0.0, 0.0)) * 1e4 + 0.5)", int(kLuminanceRed * 1e4 + 0.5)},
      // The CPU weighs jittered samples where the GPU placed them: the same bits on both sides.
      {"kCoverageTrianglesBinding", kCoverageTrianglesBinding},
      {"kCoverageUnit", kCoverageUnit},
      {"kWeighGroupSize", kWeighGroupSize},
      {"int(windowSolidAngle(vec4(-0.5, -0.3, 0.7, 0.4), 1.2) * 1e4 + 0.5)",
       int(windowSolidAngle(vec4(-0.5f, -0.3f, 0.7f, 0.4f), 1.2f) * 1e4f + 0.5f)},
      {"kRadianceAtlasUnit", kRadianceAtlasUnit},
      {"kGBufferAlbedoUnit", kGBufferAlbedoUnit},
      {"kProjectionHemispherical", kProjectionHemispherical},
      {"kGatherSumGroupSize", kGatherSumGroupSize},
      {"int(kPerspectiveFieldOfViewDegrees)", int(kPerspectiveFieldOfViewDegrees)},
      {"int(coverageHash(123456789u) >> 1u)", int(coverageHash(123456789u) >> 1u)},
      {"int(coverageSampleOffset(7u, 1234u, 999u, 5, 8).x * 16777216.0)",
       int(coverageSampleOffset(7u, 1234u, 999u, 5, 8).x * 16777216.0f)},
      {"int(coverageSampleOffset(7u, 1234u, 999u, 3, 4).y * 16777216.0)",
       int(coverageSampleOffset(7u, 1234u, 999u, 3, 4).y * 16777216.0f)},
  };
  // The irradiance cache's record, weight, extrapolation and zone (the CPU octree and the GPU
  // splatting must interpolate alike), the light samples' irradiance and the BRDF (the CPU cache
  // lights with them what the shading passes light).
  IrradianceRecord record{};
  record.position_radius = vec4(1, 2, 3, 0.5f);
  record.normal = vec4(0, 1, 0, 0);
  record.irradiance = vec4(1, 2, 3, 0);
  record.rotation[1] = vec4(0.5f, 0, 0.25f, 0);
  record.translation[0] = vec4(1, -1, 0.5f, 0);
  const std::string glsl_record =
      "IrradianceRecord(vec4(1, 2, 3, 0.5), vec4(0, 1, 0, 0), vec4(1, 2, 3, 0), "
      "vec4[3](vec4(0), vec4(0.5, 0, 0.25, 0), vec4(0)), vec4[3](vec4(1, -1, 0.5, 0), vec4(0), "
      "vec4(0)))";
  const vec3 p(1.2f, 2.05f, 3.1f), n = glm::normalize(vec3(0.3f, 1.0f, -0.2f));
  const std::string glsl_pn = "vec3(1.2, 2.05, 3.1), normalize(vec3(0.3, 1.0, -0.2))";
  auto fixed = [](float v) { return int(std::floor(v * 1e4f + 0.5f)); };
  auto fixedGlsl = [](const std::string& e) { return "int(floor((" + e + ") * 1e4 + 0.5))"; };
  const GpuLightSample spot{vec4(0, 2, 0, 0), vec4(0, -1, 0, 0.5f), vec4(3, 3, 3, 2), mat4(1.0f)};
  const std::string glsl_spot =
      "GpuLightSample(vec4(0, 2, 0, 0), vec4(0, -1, 0, 0.5), vec4(3, 3, 3, 2), mat4(1.0))";
  const vec3 wo = glm::normalize(vec3(0.2f, 0, 1)), wi = glm::normalize(vec3(-0.1f, 0.1f, 1));
  cases.insert(
      cases.end(),
      {{"kRecordsBinding", kRecordsBinding},
       {"kSplatSumsUnit", kSplatSumsUnit},
       {"kRecordSamplingHemicube", kRecordSamplingHemicube},
       {"kRecordSums", kRecordSums},
       {"kRecordSumGroupSize", kRecordSumGroupSize},
       {fixedGlsl("recordWeight(" + glsl_record + ", " + glsl_pn + ")"),
        fixed(recordWeight(record, p, n))},
       {fixedGlsl("recordIrradiance(" + glsl_record + ", " + glsl_pn + ").x"),
        fixed(recordIrradiance(record, p, n).x)},
       {fixedGlsl("recordIrradiance(" + glsl_record + ", " + glsl_pn + ").y"),
        fixed(recordIrradiance(record, p, n).y)},
       {fixedGlsl("sphereScreenRect(mat4(1.0), mat4(1.0), vec3(0.1, 0.2, -3.0), 0.5).z"),
        fixed(sphereScreenRect(mat4(1.0f), mat4(1.0f), vec3(0.1f, 0.2f, -3.0f), 0.5f).z)},
       {fixedGlsl("basisBitangent(normalize(vec3(0.3, -0.5, 0.8))).x"),
        fixed(basisBitangent(glm::normalize(vec3(0.3f, -0.5f, 0.8f))).x)},
       {fixedGlsl("pointSampleIrradiance(" + glsl_spot + ", vec3(0.5, 0, 0.2)).x"),
        fixed(pointSampleIrradiance(spot, vec3(0.5f, 0, 0.2f)).x)},
       {fixedGlsl("evaluateBrdf(vec3(0.5), vec3(0.3), 20.0, true, vec3(0, 0, 1), "
                  "normalize(vec3(0.2, 0, 1)), normalize(vec3(-0.1, 0.1, 1))).x"),
        fixed(evaluateBrdf(vec3(0.5f), vec3(0.3f), 20.0f, true, vec3(0, 0, 1), wo, wi).x)},
       // The particles' closed forms (billboards, volume shadow, network) and layout.
       {fixedGlsl("chordOpticalDepth(1.7, 1.3, 0.4, -0.5, 0.9)"),
        fixed(chordOpticalDepth(1.7f, 1.3f, 0.4f, -0.5f, 0.9f))},
       {fixedGlsl("chordOpticalDepth(1.7, 1.3, 0.0, -5.0, 5.0)"),
        fixed(chordOpticalDepth(1.7f, 1.3f, 0.0f, -5.0f, 5.0f))},
       {fixedGlsl("henyeyGreensteinPhase(0.3, 0.6)"), fixed(henyeyGreensteinPhase(0.3f, 0.6f))},
       {fixedGlsl("phaseTableCoordinate(-0.25)"), fixed(phaseTableCoordinate(-0.25f))},
       {"kParticlesBinding", kParticlesBinding},
       {"kIncomingRadianceBinding", kIncomingRadianceBinding},
       {"kPhaseMatrixUnit", kPhaseMatrixUnit},
       {"kSourceBinding", kSourceBinding}});
  std::vector<std::string> expressions;
  for (const auto& [expression, value] : cases) expressions.push_back(expression);
  const std::vector<int> gpu_values = evaluateOnGpu(expressions);
  for (std::size_t i = 0; i < cases.size(); ++i)
    EXPECT_EQ(gpu_values[i], cases[i].second) << cases[i].first;
}

// A compute program of `source` (which may #include embedded files), for layout queries.
gl::Program layoutProgram(const std::string& source) {
  return gl::buildProgram({{GL_COMPUTE_SHADER, "test/layout.comp.glsl"}}, "",
                          [&](std::string_view path) -> std::string_view {
                            return path == "test/layout.comp.glsl" ? std::string_view(source)
                                                                   : gl::glslFile(path);
                          });
}

// One property (GL_OFFSET, GL_TOP_LEVEL_ARRAY_STRIDE) of a named resource of `program`.
std::size_t resourceProperty(const gl::Program& program, GLenum interface, const char* name,
                             GLenum what) {
  const GLuint index = glGetProgramResourceIndex(program.id(), interface, name);
  EXPECT_NE(index, GL_INVALID_INDEX) << name;
  GLint value = -1;
  glGetProgramResourceiv(program.id(), interface, index, 1, &what, 1, nullptr, &value);
  return std::size_t(value);
}

// The offsets and array strides of the shared structs as the driver lays them out (std430
// storage, std140 uniform block) are the C++ structs' own, so a record written by one side is
// read field for field by the other.
TEST_F(SharedHeaders, SharedStructsHaveTheCppLayoutInTheDriver) {
  const std::string source =
      "#include \"realtime/gpu_scene/scene.glsl\"\n"
      "#include \"realtime/techniques/stochastic_radiosity/selection.glsl\"\n"
      "layout(local_size_x = 1) in;\n"
      "void main() {\n"
      "  shooters[0].u = camera.position.x + camera.image_size.y;\n"
      "  shooters[1].power = 1.0;\n"
      "}\n";
  const gl::Program program = layoutProgram(source);
  auto property = [&](GLenum interface, const char* name, GLenum what) {
    return resourceProperty(program, interface, name, what);
  };
  EXPECT_EQ(property(GL_BUFFER_VARIABLE, "shooters[0].u", GL_OFFSET), offsetof(gpu::Shooter, u));
  EXPECT_EQ(property(GL_BUFFER_VARIABLE, "shooters[0].power", GL_TOP_LEVEL_ARRAY_STRIDE),
            sizeof(gpu::Shooter));
  EXPECT_EQ(property(GL_UNIFORM, "camera.position", GL_OFFSET), offsetof(gpu::Camera, position));
  EXPECT_EQ(property(GL_UNIFORM, "camera.image_size", GL_OFFSET),
            offsetof(gpu::Camera, image_size));
}

// A batch of light samples, the shadow pass's faces and the G-buffer's views (uniform blocks,
// std140): the second element's members sit where the C++ arrays put them.
TEST_F(SharedHeaders, UniformBlocksHaveTheCppLayoutInTheDriver) {
  const gl::Program program = layoutProgram(
      "#include \"realtime/gl/binding_plan_shared.h\"\n"
      "#include \"realtime/lighting/light_sample_shared.h\"\n"
      "#include \"realtime/gbuffer/gbuffer_views_shared.h\"\n"
      "layout(std140, binding = kLightSamplesBinding) uniform LightSampleBlock {\n"
      "  GpuLightSample samples[kMaxLightBatch];\n"
      "};\n"
      "layout(std140, binding = kShadowFacesBinding) uniform ShadowFaceBlock {\n"
      "  ShadowFace faces[kMaxShadowFaces];\n"
      "};\n"
      "layout(std140, binding = kGBufferViewsBinding) uniform GBufferViewBlock {\n"
      "  GBufferViewRecord views[kMaxGBufferViewsPerDraw];\n"
      "};\n"
      "layout(std430, binding = kTestFirstStorageBinding) buffer Out { vec4 o; };\n"
      "layout(local_size_x = 1) in;\n"
      "void main() {\n"
      "  int k = int(o.w);\n"
      "  o = samples[k].position + samples[k].axis + samples[k].intensity +\n"
      "      samples[k].view_projection[0] + faces[k].view_projection[1] + "
      "vec4(faces[k].layer_slot) + views[k].view_projection[2] + views[k].eye;\n"
      "}\n");
  auto offset = [&](const char* name) {
    return resourceProperty(program, GL_UNIFORM, name, GL_OFFSET);
  };
  using gpu::GpuLightSample;
  using gpu::ShadowFace;
  EXPECT_EQ(offset("samples[1].position"), sizeof(GpuLightSample));
  EXPECT_EQ(offset("samples[1].axis"), sizeof(GpuLightSample) + offsetof(GpuLightSample, axis));
  EXPECT_EQ(offset("samples[1].intensity"),
            sizeof(GpuLightSample) + offsetof(GpuLightSample, intensity));
  EXPECT_EQ(offset("samples[1].view_projection"),
            sizeof(GpuLightSample) + offsetof(GpuLightSample, view_projection));
  EXPECT_EQ(offset("faces[1].view_projection"), sizeof(ShadowFace));
  EXPECT_EQ(offset("faces[1].layer_slot"), sizeof(ShadowFace) + offsetof(ShadowFace, layer_slot));
  using gpu::GBufferViewRecord;
  EXPECT_EQ(offset("views[1].view_projection"), sizeof(GBufferViewRecord));
  EXPECT_EQ(offset("views[1].eye"), sizeof(GBufferViewRecord) + offsetof(GBufferViewRecord, eye));
  EXPECT_EQ(offset("views[1].excluded_triangles"),
            sizeof(GBufferViewRecord) + offsetof(GBufferViewRecord, excluded_triangles));
}

// The irradiance cache's records (std430 storage): the gradients' arrays where C++ puts them.
TEST_F(SharedHeaders, IrradianceRecordHasTheCppLayoutInTheDriver) {
  const gl::Program program = layoutProgram(
      "#include \"realtime/techniques/irradiance_cache_splatting/record_face.glsl\"\n"
      "layout(local_size_x = 1) in;\n"
      "void main() { records[0].translation[2] = records[1].rotation[1] + records[2].normal; }\n");
  auto property = [&](const char* name, GLenum what) {
    return resourceProperty(program, GL_BUFFER_VARIABLE, name, what);
  };
  using gpu::IrradianceRecord;
  EXPECT_EQ(property("records[0].normal", GL_OFFSET), offsetof(IrradianceRecord, normal));
  EXPECT_EQ(property("records[0].rotation[0]", GL_OFFSET), offsetof(IrradianceRecord, rotation));
  EXPECT_EQ(property("records[0].translation[0]", GL_OFFSET),
            offsetof(IrradianceRecord, translation));
  EXPECT_EQ(property("records[0].normal", GL_TOP_LEVEL_ARRAY_STRIDE), sizeof(IrradianceRecord));
}

// The light path map's selected panes (its own binding, so a program of its own).
TEST_F(SharedHeaders, SelectedPaneHasTheCppLayoutInTheDriver) {
  const gl::Program program = layoutProgram(
      "#include \"realtime/techniques/light_path_map/light_path_map_shared.h\"\n"
      "layout(std430, binding = kSelectedPanesBinding) buffer SelectedPanes {\n"
      "  SelectedPane selected[];\n"
      "};\n"
      "layout(local_size_x = 1) in;\n"
      "void main() { selected[0].layer = int(selected[1].weight.x); }\n");
  EXPECT_EQ(resourceProperty(program, GL_BUFFER_VARIABLE, "selected[0].layer", GL_OFFSET),
            offsetof(gpu::SelectedPane, layer));
  EXPECT_EQ(resourceProperty(program, GL_BUFFER_VARIABLE, "selected[0].weight",
                             GL_TOP_LEVEL_ARRAY_STRIDE),
            sizeof(gpu::SelectedPane));
}

}  // namespace
}  // namespace gib::rt
