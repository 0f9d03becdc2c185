#include "realtime/techniques/illumination_network/illumination_network_technique.h"

#include "realtime/gl/finished_time.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/shader_library.h"
#include "realtime/gpu_scene/gpu_scene.h"

#include <glm/geometric.hpp>

namespace gib::rt {

namespace {

constexpr std::string_view kScatteringPass = "scattering";
constexpr std::string_view kTransportPass = "transport";

// W[d, i] = p(ω_d·ω_i) / Σ_d' p(ω_d'·ω_i) at [d × D + i]: the scattering pass's phase function
// between the network's directions, each column summing to one.
std::vector<float> phaseMatrix(const std::vector<glm::vec4>& directions, float g) {
  const std::size_t n = directions.size();
  std::vector<float> matrix(n * n);
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0;
    for (std::size_t d = 0; d < n; ++d) {
      const float p = gpu::henyeyGreensteinPhase(
          glm::dot(glm::vec3(directions[d]), glm::vec3(directions[i])), g);
      matrix[d * n + i] = p;
      sum += p;
    }
    for (std::size_t d = 0; d < n; ++d) matrix[d * n + i] = float(matrix[d * n + i] / sum);
  }
  return matrix;
}

// Mean number of links from a particle to the sky over all (particle, direction) pairs.
double meanChainLength(const std::vector<gpu::NetworkLink>& links, int directions) {
  if (links.empty()) return 0;
  const std::size_t n = links.size() / std::size_t(directions);
  double total = 0;
  for (std::size_t p = 0; p < n; ++p)
    for (int i = 0; i < directions; ++i)
      for (int current = int(p); links[std::size_t(current) * directions + i].particle >= 0;
           current = links[std::size_t(current) * directions + i].particle)
        ++total;
  return total / double(links.size());
}

}  // namespace

IlluminationNetworkTechnique::IlluminationNetworkTechnique(const ParameterValues& p)
    : direction_count_(p.integer("directions")), compositor_(p) {}

void IlluminationNetworkTechnique::prepare(const GpuScene& scene, int /*width*/, int /*height*/) {
  medium_.emplace(scene.scene(), "illumination_network");
  compositor_.prepare(scene, *medium_);
  const std::string folder = "realtime/techniques/illumination_network/";
  auto build = [&](const char* file) {
    gl::Program program = gl::buildProgram({{GL_COMPUTE_SHADER, folder + file}});
    medium_->setUniforms(program);
    // Scattering works on one particle's directions at a time: it has no particle count.
    program.setIfPresent("u_count", medium_->count());
    program.set("u_direction_count", direction_count_);
    return program;
  };
  visibility_program_ = build("visibility.comp.glsl");
  emission_program_ = build("emission.comp.glsl");
  scattering_program_ = build("scattering.comp.glsl");
  transport_program_ = build("transport.comp.glsl");

  directions_ = sphereDirections(direction_count_);
  directions_buffer_ = gl::Buffer::fromVector(directions_);
  phase_matrix_ = gl::Texture::make2D(GL_R32F, direction_count_, direction_count_);
  phase_matrix_.upload(phaseMatrix(directions_, medium_->g()).data(), GL_RED);
  phase_matrix_.setFilter(GL_NEAREST, GL_NEAREST);
  const std::size_t cells = std::size_t(medium_->count()) * std::size_t(direction_count_);
  visibility_ = gl::Buffer(cells * sizeof(gpu::NetworkLink), nullptr);
  emission_ = gl::Buffer(cells * sizeof(glm::vec4), nullptr);
  source_ = gl::Buffer(cells * sizeof(glm::vec4), nullptr);
  incoming_ = gl::Buffer(cells * sizeof(glm::vec4), nullptr);

  visibility_ms_ = gl::finishedMilliseconds([&] {
    visibility_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kVisibilityBinding);
    dispatch(visibility_program_);
  });
  emission_ms_ = gl::finishedMilliseconds([&] {
    const gl::Buffer towards = gl::Buffer::fromVector(medium_->towardsLights());
    VolumeShadow().compute(*medium_, towards, medium_->lightCount(), transmittance_);
    transmittance_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kTransmittanceBinding);
    emission_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kEmissionBinding);
    dispatch(emission_program_);
  });
  // Iteration 0: nothing scattered yet (J = 0), the sky through each chain.
  const float zero[4] = {0, 0, 0, 0};
  glClearNamedBufferData(source_.id(), GL_RGBA32F, GL_RGBA, GL_FLOAT, zero);
  transport();
  iterations_ = 0;
  mean_chain_ = meanChainLength(visibility(), direction_count_);
}

void IlluminationNetworkTechnique::dispatch(const gl::Program& program) const {
  medium_->bind();
  directions_buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kSphereDirectionsBinding);
  program.use();
  gl::dispatchCompute(particleGroups(medium_->count()), GLuint(direction_count_), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void IlluminationNetworkTechnique::transport() {
  visibility_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kVisibilityBinding);
  source_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kSourceBinding);
  incoming_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kIncomingRadianceBinding);
  dispatch(transport_program_);
}

void IlluminationNetworkTechnique::step(gl::PassProfiler& profiler) {
  {
    auto pass = profiler.pass(kScatteringPass);
    incoming_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kIncomingRadianceBinding);
    emission_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kEmissionBinding);
    source_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kSourceBinding);
    phase_matrix_.bind(gpu::kPhaseMatrixUnit);
    scattering_program_.use();
    gl::dispatchCompute(particleGroups(direction_count_), GLuint(medium_->count()), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  {
    auto pass = profiler.pass(kTransportPass);
    transport();
  }
  ++iterations_;
}

void IlluminationNetworkTechnique::render(Frame& frame) {
  compositor_.renderSurfaces(frame);
  compositor_.shade(
      {&transmittance_, medium_->lightCount(), &directions_buffer_, direction_count_, &incoming_},
      frame.profiler);
  compositor_.sortAndSplat(frame);
}

std::vector<gpu::NetworkLink> IlluminationNetworkTechnique::visibility() const {
  return gl::readBuffer<gpu::NetworkLink>(visibility_,
                                          visibility_.bytes() / sizeof(gpu::NetworkLink));
}
std::vector<glm::vec4> IlluminationNetworkTechnique::emission() const {
  return gl::readBuffer<glm::vec4>(emission_, emission_.bytes() / sizeof(glm::vec4));
}
std::vector<glm::vec4> IlluminationNetworkTechnique::incoming() const {
  return gl::readBuffer<glm::vec4>(incoming_, incoming_.bytes() / sizeof(glm::vec4));
}
std::vector<float> IlluminationNetworkTechnique::lightTransmittance() const {
  return gl::readBuffer<float>(transmittance_,
                               std::size_t(medium_->count()) * std::size_t(medium_->lightCount()));
}

std::vector<TechniqueStatistic> IlluminationNetworkTechnique::statistics() const {
  const double cells = double(medium_ ? medium_->count() : 0) * direction_count_;
  return {{"particles", double(medium_ ? medium_->count() : 0)},
          {"directions", double(direction_count_)},
          {"lights", double(medium_ ? medium_->lightCount() : 0)},
          // V (8 bytes), E, J and I (16 bytes each) per particle and direction.
          {"network_mb", cells * (8 + 3 * 16) / (1024.0 * 1024.0)},
          {"mean_chain_length", mean_chain_},
          {"prepare_visibility_ms", visibility_ms_},
          {"prepare_emission_ms", emission_ms_}};
}

TechniqueInfo illuminationNetworkTechniqueInfo() {
  TechniqueInfo info;
  info.name = "illumination_network";
  info.description =
      "multiple scattering in a particle medium: the book's illumination network iterated on "
      "the GPU (each iteration one more scattering order), particles splatted as spherical "
      "billboards";
  info.source =
      "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, "
      "§9.6 (participating media illumination networks)";
  info.parameters = joinParameterTables(
      {{numericParameter("directions", ParameterType::kInteger, "128", 1,
                         gpu::kMaxNetworkDirections, "directions",
                         "D sample directions shared by all particles, spread evenly over the "
                         "sphere (the book: 128)")},
       ParticleCompositor::parameters()});
  ParticleCompositor::declarePasses(info.passes);
  info.passes.add(std::string(kIterationPass),
                  "one iteration: one more scattering order in the network");
  info.passes.add(passPath({kIterationPass, kScatteringPass}),
                  "J = E + a·Σ_d I p / Σ_d p: each particle's radiance towards each direction");
  info.passes.add(passPath({kIterationPass, kTransportPass}),
                  "I gathered along each particle's chain in V, the sky at its end");
  info.statistics = ParticleCompositor::statistics({
      {"directions", "sample directions shared by all particles"},
      {"network_mb", "memory of the network (V, E, J, I per particle and direction)"},
      {"mean_chain_length", "mean particles along a direction's visibility chain"},
      {"prepare_visibility_ms", "time to build the visibility network"},
      {"prepare_emission_ms", "time to compute the first-order emission"},
  });
  info.needs = {TechniqueNeed::kMedium};
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<IlluminationNetworkTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
