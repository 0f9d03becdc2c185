// scene/fresnel_shared.h on the GPU: the shader library embeds it, its C++-only part drops out,
// and the four Fresnel functions evaluated in a compute shader agree with the C++ ones over a grid
// of angles and indices (a dielectric seen from outside and from inside, past its critical angle,
// and a conductor).
#include "scene/fresnel_shared.h"

#include "realtime/gl/binding_plan_shared.h"
#include "realtime/gl/objects.h"
#include "realtime/gl/shader_library.h"
#include "support/gl_test_context.h"

#include <gtest/gtest.h>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace gib::rt {
namespace {

using test::GlTest;

constexpr int kAngles = 129;  // cos θ' = i/128: from grazing to perpendicular incidence
constexpr float kIor = 1.5f;
// Gold near 650 nm, per channel (the test metal).
const glm::vec3 kGoldN(0.18f, 0.42f, 1.37f), kGoldK(3.42f, 2.35f, 1.77f);
// Both sides evaluate the same float expressions, but the shader compiler may fuse multiplies
// and adds and its sqrt and division need not round as the CPU's do: a few ulps of each term.
// Reflectances lie in [0, 1], where 1e-6 is 8 ulps of 1 and far below any reflectance a technique
// could tell apart.
constexpr float kTolerance = 1e-6f;

float cosine(int i) {
  return float(i) / float(kAngles - 1);
}

// Per angle: x the dielectric from outside (η = ior), y from inside (η = 1/ior), z the
// approximation with gold's F⊥; then the conductor's rgb; then F⊥ once.
std::vector<glm::vec4> evaluateOnGpu() {
  const std::string source =
      "#include \"realtime/gl/binding_plan_shared.h\"\n"
      "#include \"scene/fresnel_shared.h\"\n"
      "layout(local_size_x = 1) in;\n"
      "layout(std430, binding = kTestFirstStorageBinding) buffer Out { vec4 o[]; };\n"
      "uniform int u_angles;\n"
      "uniform float u_ior;\n"
      "uniform vec3 u_n;\n"
      "uniform vec3 u_k;\n"
      "void main() {\n"
      "  int i = int(gl_WorkGroupID.x);\n"
      "  float c = float(i) / float(u_angles - 1);\n"
      "  vec3 f0 = fresnelAtNormalIncidence(u_n, u_k);\n"
      "  o[2 * i] = vec4(fresnelDielectric(c, u_ior), fresnelDielectric(c, 1.0 / u_ior),\n"
      "                  fresnelApproximation(f0, c).g, 0.0);\n"
      "  o[2 * i + 1] = vec4(fresnelConductor(c, u_n, u_k), 0.0);\n"
      "  if (i == 0) o[2 * u_angles] = vec4(f0, 0.0);\n"
      "}\n";
  const gl::Program program = gl::buildProgram(
      {{GL_COMPUTE_SHADER, "test/fresnel.comp.glsl"}}, "",
      [&](std::string_view path) -> std::string_view {
        return path == "test/fresnel.comp.glsl" ? std::string_view(source) : gl::glslFile(path);
      });
  std::vector<glm::vec4> out(2 * kAngles + 1, glm::vec4(-7.0f));
  const gl::Buffer buffer = gl::Buffer::fromVector(out);
  buffer.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTestFirstStorageBinding);
  program.use();
  glUniform1i(program.uniform("u_angles"), kAngles);
  glUniform1f(program.uniform("u_ior"), kIor);
  glUniform3f(program.uniform("u_n"), kGoldN.r, kGoldN.g, kGoldN.b);
  glUniform3f(program.uniform("u_k"), kGoldK.r, kGoldK.g, kGoldK.b);
  glDispatchCompute(kAngles, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(out.size() * sizeof(glm::vec4)), out.data());
  return out;
}

TEST_F(GlTest, FresnelFunctionsAgreeWithTheirCppVersions) {
  const std::vector<glm::vec4> gpu = evaluateOnGpu();
  const glm::vec3 f0 = scene::fresnelAtNormalIncidence(kGoldN, kGoldK);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu[2 * kAngles][c], f0[c], kTolerance) << c;
  int total_internal_reflection = 0;
  for (int i = 0; i < kAngles; ++i) {
    const float cos_i = cosine(i);
    const glm::vec4 dielectric = gpu[2 * i], conductor = gpu[2 * i + 1];
    EXPECT_NEAR(dielectric.x, scene::fresnelDielectric(cos_i, kIor), kTolerance) << cos_i;
    const float inside = scene::fresnelDielectric(cos_i, 1.0f / kIor);
    EXPECT_NEAR(dielectric.y, inside, kTolerance) << cos_i;
    // Past the critical angle both sides return exactly 1 (no leak of light through TIR).
    if (inside == 1.0f) {
      ++total_internal_reflection;
      EXPECT_EQ(dielectric.y, 1.0f) << cos_i;
    }
    EXPECT_NEAR(dielectric.z, scene::fresnelApproximation(f0, cos_i).g, kTolerance) << cos_i;
    const glm::vec3 expected = scene::fresnelConductor(cos_i, kGoldN, kGoldK);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(conductor[c], expected[c], kTolerance) << cos_i << c;
  }
  // cos θc = √(1 − 1/1.5²) ≈ 0.745: the grid's first 96 angles lie past it.
  EXPECT_EQ(total_internal_reflection, 96);
}

}  // namespace
}  // namespace gib::rt
