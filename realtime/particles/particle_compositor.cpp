#include "realtime/particles/particle_compositor.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
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
  s.surface_shadow = p.boolean("surface_shadow");
  return s;
}

}  // namespace

ParticleCompositor::ParticleCompositor(const ParameterValues& parameters)
    : billboard_(billboardSettings(parameters)), surface_lighting_(parameters) {
  if (billboard_.surface_shadow)
    surface_lighting_.lighting().setShadingDefines("#define GIB_MEDIUM_TRANSMITTANCE 1\n");
}

ParameterTable ParticleCompositor::parameters() {
  return joinParameterTables(
      {{
           choiceParameter(
               "billboard", "spherical", {"spherical", "planar"},
               "spherical: each fragment's segment in the particle's sphere clipped "
               "against surfaces and the near plane (§9.3.1); planar: classic billboards "
               "depth-tested at the particle's centre, which clip where they meet a "
               "surface (Fig. 9.3)"),
           choiceParameter("opacity", "linear", {"linear", "gouraud", "homogeneous"},
                           "a fragment's opacity: the linear fall-off integrated exactly along its "
                           "segment, the book's 1 − exp(−τ(1 − d/r)Δs), or constant density "
                           "1 − exp(−τΔs)"),
           booleanParameter(
               "surface_shadow", true,
               "surfaces lit through the medium: each light sample attenuated by the "
               "particles' optical depth towards it (N particles per pixel and sample)"),
       },
       SurfaceLighting::parameters()});
}

std::vector<DeclaredOutput> ParticleCompositor::statistics(std::vector<DeclaredOutput> own) {
  std::vector<DeclaredOutput> statistics = {{"particles", "particles of the medium"},
                                            {"lights", "directional lights"}};
  statistics.insert(statistics.end(), own.begin(), own.end());
  return statistics;
}

void ParticleCompositor::declarePasses(PassDeclarations& passes) {
  SurfaceLighting::declarePasses(passes);
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
  surface_lighting_.prepare(scene, scene.width(), scene.height());
  const std::string folder = "realtime/particles/";
  shading_ = gl::buildProgram({{GL_COMPUTE_SHADER, folder + "view_shading.comp.glsl"}});
  sort_ = gl::buildProgram({{GL_COMPUTE_SHADER, folder + "depth_sort.comp.glsl"}});
  splat_ = gl::buildProgram({{GL_VERTEX_SHADER, folder + "billboard.vert.glsl"},
                             {GL_FRAGMENT_SHADER, folder + "billboard.frag.glsl"}});
  setSpherical(billboard_.spherical);
  splat_.set("u_opacity", billboard_.opacity);
  splat_.set("u_inverse_view_projection",
             glm::inverse(scene.camera().projection * scene.camera().view));
  // What does not change between frames (the medium, its lights, the camera) is set once; the
  // sort reads only where the particles are.
  medium.setUniforms(shading_);
  for (const gl::Program* program : {&shading_, &sort_}) {
    program->set("u_count", medium.count());
    program->set("u_eye", scene.camera().position);
  }
  source_ = gl::Buffer(std::size_t(medium.count()) * sizeof(glm::vec4), nullptr);
  order_ = gl::Buffer(std::size_t(medium.count()) * sizeof(std::uint32_t), nullptr);
}

void ParticleCompositor::setSpherical(bool spherical) {
  billboard_.spherical = spherical;
  splat_.set("u_spherical", spherical ? 1 : 0);
}

void ParticleCompositor::renderSurfaces(Frame& frame) {
  const GpuScene& scene = *scene_;
  surface_lighting_.drawSurfaces(scene, frame.target, frame.profiler);
  if (scene.vertexCount() == 0) return;
  medium_->bind();  // the shading passes' medium_transmittance.glsl reads the particles
  surface_lighting_.addDirect(scene, &frame.target, frame.profiler);
}

void ParticleCompositor::shade(const ParticleIncoming& incoming, gl::PassProfiler& profiler) {
  auto pass = profiler.pass(kParticleShadingPass);
  const ParticleMedium& medium = *medium_;
  medium.bind();
  shading_.set("u_stride", incoming.stride);
  shading_.set("u_direction_count", incoming.direction_count);
  shading_.set("u_sky_through_transmittance", incoming.radiance ? 0 : 1);
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
  frame.target.bind();  // and its viewport
  scene.bindSceneBuffers();
  surface_lighting_.gbuffer().bindTextures();
  order_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kParticleOrderBinding);
  source_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kParticleSourceBinding);
  splat_.use();
  // Premultiplied "over": colour = α·S + (1 − α)·behind; the target's alpha is left as it is.
  const gl::PipelineScope over(
      {.blend = gl::BlendFactors{GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE}});
  empty_vertex_array_.bind();
  gl::drawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(medium.count()));
}

}  // namespace gib::rt
