#include "realtime/particles/particle_compositor.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/shader_library.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/particles/particle_shared.h"
#include "realtime/render_target.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

namespace gib::rt {

namespace {

BillboardSettings billboardSettings(const ParameterValues& p) {
  BillboardSettings s;
  s.spherical = p.text("billboard") == "spherical";
  const std::string& opacity = p.text("opacity");
  s.opacity = opacity == "gouraud"       ? gpu::kOpacityGouraud
              : opacity == "homogeneous" ? gpu::kOpacityHomogeneous
                                         : gpu::kOpacityLinear;
  s.surface_shadow = p.text("surface_shadow") == "true";
  return s;
}

}  // namespace

ParticleCompositor::ParticleCompositor(const ParameterValues& parameters)
    : billboard_(billboardSettings(parameters)),
      lighting_(shadowSettings(parameters), parameters.integer("light_samples")) {
  if (billboard_.surface_shadow)
    lighting_.setShadingDefines("#define GIB_MEDIUM_TRANSMITTANCE 1\n");
}

ParameterTable ParticleCompositor::parameters() {
  ParameterTable table = {
      choiceParameter("billboard", "spherical", {"spherical", "planar"},
                      "spherical: each fragment's segment in the particle's sphere clipped "
                      "against surfaces and the near plane (§9.3.1); planar: classic billboards "
                      "depth-tested at the particle's centre, which clip where they meet a "
                      "surface (Fig. 9.3)"),
      choiceParameter("opacity", "linear", {"linear", "gouraud", "homogeneous"},
                      "a fragment's opacity: the linear fall-off integrated exactly along its "
                      "segment, the book's 1 − exp(−τ(1 − d/r)Δs), or constant density "
                      "1 − exp(−τΔs)"),
      choiceParameter("surface_shadow", "true", {"true", "false"},
                      "surfaces lit through the medium: each light sample attenuated by the "
                      "particles' optical depth towards it (N particles per pixel and sample)"),
  };
  for (const ParameterSpec& spec : directLightingParameters()) table.push_back(spec);
  return table;
}

void ParticleCompositor::declarePasses(PassDeclarations& passes) {
  passes.add(passPath({kFramePass, kGBufferPass}), "what each pixel's primary ray hits");
  DirectLighting::declarePasses(passes, kFramePass);
  passes.add(passPath({kFramePass, kParticleShadingPass}),
             "each particle's radiance towards the eye from the lights and its incoming light");
  passes.add(passPath({kFramePass, kParticleSortPass}),
             "the particles ranked back to front by their distance from the eye");
  passes.add(passPath({kFramePass, kBillboardPass}),
             "a billboard per particle: the opacity of its ray segment, blended back to front");
}

void ParticleCompositor::prepare(const GpuScene& scene, const ParticleMedium& medium) {
  scene_ = &scene;
  medium_ = &medium;
  gbuffer_.emplace(scene.width(), scene.height());
  lighting_.prepare(scene);
  const std::string folder = "realtime/particles/";
  shading_ = gl::buildProgram({{GL_COMPUTE_SHADER, folder + "view_shading.comp.glsl"}});
  sort_ = gl::buildProgram({{GL_COMPUTE_SHADER, folder + "depth_sort.comp.glsl"}});
  splat_ = gl::buildProgram({{GL_VERTEX_SHADER, folder + "billboard.vert.glsl"},
                             {GL_FRAGMENT_SHADER, folder + "billboard.frag.glsl"}});
  setSpherical(billboard_.spherical);
  glProgramUniform1i(splat_.id(), splat_.uniform("u_opacity"), billboard_.opacity);
  const glm::mat4 inverse = glm::inverse(scene.camera().projection * scene.camera().view);
  glProgramUniformMatrix4fv(splat_.id(), splat_.uniform("u_inverse_view_projection"), 1, GL_FALSE,
                            glm::value_ptr(inverse));
  // What does not change between frames (the medium, its lights, the camera) is set once.
  for (const gl::Program* program : {&shading_, &sort_}) {
    medium.setUniforms(*program);
    glProgramUniform1i(program->id(), program->uniform("u_count"), medium.count());
    glProgramUniform3fv(program->id(), program->uniform("u_eye"), 1,
                        glm::value_ptr(scene.camera().position));
  }
  source_ = gl::Buffer(std::size_t(medium.count()) * sizeof(glm::vec4), nullptr);
  order_ = gl::Buffer(std::size_t(medium.count()) * sizeof(std::uint32_t), nullptr);
}

void ParticleCompositor::setSpherical(bool spherical) {
  billboard_.spherical = spherical;
  glProgramUniform1i(splat_.id(), splat_.uniform("u_spherical"), spherical ? 1 : 0);
}

void ParticleCompositor::renderSurfaces(Frame& frame) {
  const GpuScene& scene = *scene_;
  gbuffer_->render(scene, &frame.profiler);
  lighting_.writeEmission(scene, *gbuffer_, frame.target, frame.profiler);
  if (scene.vertexCount() == 0) return;
  medium_->bind();  // the shading passes' medium_transmittance.glsl reads the particles
  lighting_.addDirect(scene, {{&*gbuffer_, &frame.target}}, frame.profiler);
}

void ParticleCompositor::shade(const ParticleIncoming& incoming, gl::PassProfiler& profiler) {
  auto pass = profiler.pass(kParticleShadingPass);
  const ParticleMedium& medium = *medium_;
  medium.bind();
  const GLuint id = shading_.id();
  glProgramUniform1i(id, shading_.uniform("u_stride"), incoming.stride);
  glProgramUniform1i(id, shading_.uniform("u_direction_count"), incoming.direction_count);
  glProgramUniform1i(id, shading_.uniform("u_sky_through_transmittance"),
                     incoming.radiance ? 0 : 1);
  incoming.transmittance->bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTransmittanceBinding);
  incoming.directions->bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kSphereDirectionsBinding);
  if (incoming.radiance)
    incoming.radiance->bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kIncomingRadianceBinding);
  source_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kParticleSourceBinding);
  shading_.use();
  gl::dispatchCompute(particleGroups(medium.count()), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void ParticleCompositor::sortAndSplat(Frame& frame) {
  const GpuScene& scene = *scene_;
  const ParticleMedium& medium = *medium_;
  medium.bind();
  {
    auto pass = frame.profiler.pass(kParticleSortPass);
    order_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kParticleOrderBinding);
    sort_.use();
    gl::dispatchCompute(particleGroups(medium.count()), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  auto pass = frame.profiler.pass(kBillboardPass);
  frame.target.bind();
  glViewport(0, 0, frame.target.width(), frame.target.height());
  scene.bindSceneBuffers();
  gbuffer_->bindTextures();
  order_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kParticleOrderBinding);
  source_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kParticleSourceBinding);
  splat_.use();
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  // Premultiplied "over": colour = α·S + (1 − α)·behind; the target's alpha is left as it is.
  glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  empty_vertex_array_.bind();
  gl::drawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(medium.count()));
  glDisable(GL_BLEND);
}

}  // namespace gib::rt
