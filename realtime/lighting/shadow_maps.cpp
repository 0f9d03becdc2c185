#include "realtime/lighting/shadow_maps.h"

#include "realtime/cube_faces.h"
#include "realtime/gl/gpu_commands.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/shader_library.h"
#include "realtime/lighting/lighting_shared.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace gib::rt {

namespace {

// Largest angle between a 90° face's axis and a direction it covers (to its corners).
const float kFaceHalfDiagonal = std::acos(1.0f / std::sqrt(3.0f));
// What a cleared map holds: nothing closer than the far plane (depth), or for a variance shadow
// map moments far beyond any scaled light distance.
constexpr float kFarDepth = 1.0f;
constexpr float kFarMoments[4] = {1e4f, 1e8f, 0, 0};

std::string kindDefines(LightSampleKind kind, bool variance) {
  std::string d = kind == LightSampleKind::kPoint ? "#define POINT_LIGHT 1\n" : "";
  if (variance) d += "#define VARIANCE_SHADOW_MAP 1\n";
  return d;
}

void setupDepthTexture(gl::Texture& texture, bool compare_filtered) {
  // Hard shadows take the nearest texel's comparison; PCF lets the hardware filter 2×2 of them.
  texture.setDepthCompare(true);
  const GLenum filter = compare_filtered ? GL_LINEAR : GL_NEAREST;
  texture.setFilter(filter, filter);
}

}  // namespace

void ShadowMaps::declarePasses(PassDeclarations& passes, std::string_view parent) {
  passes.add(passPath({parent, kShadowMapPass}), "the scene drawn from a light sample");
  passes.add(passPath({parent, kShadowMapFilterPass}),
             "variance shadow maps: the separable box filter of the moments");
}

ShadowMaps::ShadowMaps(const ShadowSettings& settings, const GpuScene& scene)
    : settings_(settings) {
  const glm::vec3 lo = scene.boundsMin(), hi = scene.boundsMax();
  centre_ = 0.5f * (lo + hi);
  radius_ = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  near_ = 1e-4f * radius_;
  far_ = 4.0f * radius_;  // from any light inside or near the scene to its far side

  const bool variance = settings.filter == ShadowFilter::kVariance;
  const std::string point_defines = kindDefines(LightSampleKind::kPoint, variance);
  const std::string flat_defines = kindDefines(LightSampleKind::kDirectional, variance);
  auto depthProgram = [](const std::string& defines) {
    return gl::buildProgram({{GL_VERTEX_SHADER, "realtime/lighting/shadow.vert.glsl"},
                             {GL_FRAGMENT_SHADER, "realtime/lighting/shadow.frag.glsl"}},
                            defines);
  };
  auto blurProgram = [](const std::string& defines) {
    return gl::buildProgram({{GL_COMPUTE_SHADER, "realtime/lighting/vsm_blur.comp.glsl"}}, defines);
  };
  depth_point_ = depthProgram(point_defines);
  depth_flat_ = depthProgram(flat_defines);
  const int n = settings.size;
  cube_depth_ = gl::Texture::makeCube(GL_DEPTH_COMPONENT32F, n);
  flat_depth_ = gl::Texture::make2D(GL_DEPTH_COMPONENT32F, n, n);
  if (variance) {
    blur_point_ = blurProgram(point_defines);
    blur_flat_ = blurProgram(flat_defines);
    cube_moments_ = gl::Texture::makeCube(GL_RG32F, n);
    cube_scratch_ = gl::Texture::makeCube(GL_RG32F, n);
    flat_moments_ = gl::Texture::make2D(GL_RG32F, n, n);
    flat_scratch_ = gl::Texture::make2D(GL_RG32F, n, n);
  } else {
    setupDepthTexture(cube_depth_, settings.filter == ShadowFilter::kPcf);
    setupDepthTexture(flat_depth_, settings.filter == ShadowFilter::kPcf);
  }
  for (int face = 0; face < 6; ++face) {
    cube_faces_[std::size_t(face)].attachDepth(cube_depth_, 0, face);
    if (variance) cube_faces_[std::size_t(face)].attachColor(0, cube_moments_, 0, face);
    cube_faces_[std::size_t(face)].setDrawBuffers(variance ? 1 : 0);
    cube_faces_[std::size_t(face)].checkComplete();
  }
  flat_.attachDepth(flat_depth_);
  if (variance) flat_.attachColor(0, flat_moments_);
  flat_.setDrawBuffers(variance ? 1 : 0);
  flat_.checkComplete();
}

std::string ShadowMaps::defines(LightSampleKind kind) const {
  return kindDefines(kind, settings_.filter == ShadowFilter::kVariance);
}

glm::mat4 ShadowMaps::flatViewProjection(const LightSample& sample) const {
  const glm::vec3 axis = glm::normalize(sample.axis);
  const glm::vec3 eye = centre_ - axis * (2.0f * radius_);
  const glm::vec3 up = std::abs(axis.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::ortho(-radius_, radius_, -radius_, radius_, radius_, 3.0f * radius_) *
         glm::lookAt(eye, centre_, up);
}

void ShadowMaps::render(const GpuScene& scene, const LightSample& sample,
                        gl::PassProfiler& profiler) {
  {
    auto pass = profiler.pass(kShadowMapPass);
    glViewport(0, 0, settings_.size, settings_.size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    // Slope-scaled depth offset: the book's depth bias, scaled by the surface's slope in the map.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 2.0f);
    if (sample.kind == LightSampleKind::kPoint)
      renderCube(scene, sample);
    else
      renderFlat(scene, sample);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
  if (settings_.filter == ShadowFilter::kVariance) blur(sample.kind, profiler);
}

void ShadowMaps::clear(const gl::Framebuffer& framebuffer) const {
  glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &kFarDepth);
  if (settings_.filter == ShadowFilter::kVariance)
    glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, kFarMoments);
}

void ShadowMaps::renderCube(const GpuScene& scene, const LightSample& sample) {
  const float cone = std::acos(std::clamp(sample.cos_cone, -1.0f, 1.0f));
  depth_point_.use();
  glUniform3fv(depth_point_.uniform("u_light_position"), 1, glm::value_ptr(sample.position));
  glUniform1f(depth_point_.uniform("u_far"), far_);
  for (int face = 0; face < 6; ++face) {
    const gl::Framebuffer& fb = cube_faces_[std::size_t(face)];
    clear(fb);
    const glm::vec3 axis = kCubeFaceAxis[face];
    const float angle = std::acos(std::clamp(glm::dot(axis, sample.axis), -1.0f, 1.0f));
    if (angle >= cone + kFaceHalfDiagonal) continue;  // the sample sends no light this way
    fb.bind();
    const glm::mat4 view_projection = cubeFaceViewProjection(sample.position, face, near_, far_);
    glUniformMatrix4fv(depth_point_.uniform("u_face_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view_projection));
    scene.draw();
  }
}

void ShadowMaps::renderFlat(const GpuScene& scene, const LightSample& sample) {
  clear(flat_);
  flat_.bind();
  const glm::mat4 view_projection = flatViewProjection(sample);
  depth_flat_.use();
  glUniformMatrix4fv(depth_flat_.uniform("u_face_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(view_projection));
  glUniformMatrix4fv(depth_flat_.uniform("u_light_view_projection"), 1, GL_FALSE,
                     glm::value_ptr(view_projection));
  scene.draw();
}

void ShadowMaps::blur(LightSampleKind kind, gl::PassProfiler& profiler) {
  auto pass = profiler.pass(kShadowMapFilterPass);
  const bool cube = kind == LightSampleKind::kPoint;
  const gl::Program& program = cube ? blur_point_ : blur_flat_;
  const gl::Texture& moments = cube ? cube_moments_ : flat_moments_;
  const gl::Texture& scratch = cube ? cube_scratch_ : flat_scratch_;
  program.use();
  glUniform1i(program.uniform("u_radius"), settings_.blur_radius);
  glUniform1i(program.uniform("u_size"), settings_.size);
  const GLuint groups =
      GLuint((settings_.size + gpu::kVsmBlurGroupSize - 1) / gpu::kVsmBlurGroupSize);
  const GLboolean layered = cube ? GL_TRUE : GL_FALSE;
  // Horizontal into the scratch map, then vertical back.
  const gl::Texture* source[2] = {&moments, &scratch};
  const gl::Texture* destination[2] = {&scratch, &moments};
  const int steps[2][2] = {{1, 0}, {0, 1}};
  for (int i = 0; i < 2; ++i) {
    glBindImageTexture(gpu::kImageSourceUnit, source[i]->id(), 0, layered, 0, GL_READ_ONLY,
                       GL_RG32F);
    glBindImageTexture(gpu::kImageDestinationUnit, destination[i]->id(), 0, layered, 0,
                       GL_WRITE_ONLY, GL_RG32F);
    glUniform2i(program.uniform("u_step"), steps[i][0], steps[i][1]);
    gl::dispatchCompute(groups, groups, cube ? 6 : 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  }
}

void ShadowMaps::setLookupConstants(const gl::Program& program) const {
  auto set1f = [&](const char* name, float value) {
    glProgramUniform1f(program.id(), program.uniform(name), value);
  };
  auto set1i = [&](const char* name, int value) {
    glProgramUniform1i(program.id(), program.uniform(name), value);
  };
  set1f("u_near", near_);
  set1f("u_far", far_);
  set1i("u_shadow_map_size", settings_.size);
  set1f("u_ortho_extent", 2.0f * radius_);
  set1f("u_normal_offset", settings_.normal_offset);
  set1i("u_pcf_radius", settings_.filter == ShadowFilter::kPcf ? settings_.pcf_radius : 0);
  set1f("u_min_variance", settings_.min_variance);
}

void ShadowMaps::bindForLookup(const gl::Program& program, const LightSample& sample) const {
  const bool cube = sample.kind == LightSampleKind::kPoint;
  if (settings_.filter == ShadowFilter::kVariance)
    (cube ? cube_moments_ : flat_moments_).bind(gpu::kShadowMapUnit);
  else
    (cube ? cube_depth_ : flat_depth_).bind(gpu::kShadowMapUnit);
  const glm::mat4 view_projection = cube ? glm::mat4(1.0f) : flatViewProjection(sample);
  glProgramUniform3fv(program.id(), program.uniform("u_light_position"), 1,
                      glm::value_ptr(sample.position));
  glProgramUniform3fv(program.id(), program.uniform("u_light_axis"), 1,
                      glm::value_ptr(sample.axis));
  glProgramUniformMatrix4fv(program.id(), program.uniform("u_light_view_projection"), 1, GL_FALSE,
                            glm::value_ptr(view_projection));
}

}  // namespace gib::rt
