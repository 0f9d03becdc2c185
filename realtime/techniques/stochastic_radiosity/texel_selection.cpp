#include "realtime/techniques/stochastic_radiosity/texel_selection.h"

#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/shader_library.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace gib::rt {

namespace {

void bindLevel(GLuint unit, const gl::Texture& texture, int level, GLenum access) {
  glBindImageTexture(unit, texture.id(), level, GL_FALSE, 0, access, GL_R32F);
}

}  // namespace

TexelSelection::TexelSelection(SelectionMethod method, int resolution, int capacity)
    : method_(method), resolution_(resolution), capacity_(capacity) {
  if (resolution < 1 || !std::has_single_bit(unsigned(resolution)))
    throw std::invalid_argument("the power map's resolution must be a power of two");
  levels_ = std::bit_width(unsigned(resolution));  // log2 R + 1
  // Only the GPU descent reads the pyramid's levels above the texels.
  power_ = gl::Texture::make2D(GL_R32F, resolution, resolution,
                               method == SelectionMethod::kGpu ? levels_ : 1);
  power_.setFilter(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
  const std::vector<gpu::Shooter> initial(std::size_t(capacity), kNoShooter);
  shooters_ = gl::Buffer::fromVector(initial);
  if (method == SelectionMethod::kGpu) {
    sum_ = gl::buildProgram(
        {{GL_COMPUTE_SHADER, "realtime/techniques/stochastic_radiosity/power_pyramid.comp.glsl"}});
    descend_ = gl::buildProgram(
        {{GL_COMPUTE_SHADER, "realtime/techniques/stochastic_radiosity/select_descent.comp.glsl"}});
  }
}

void TexelSelection::buildPyramid() const {
  if (method_ != SelectionMethod::kGpu) return;
  sum_.use();
  // Passes of up to kPyramidLevelsPerPass levels each (two at the book's 128²).
  for (int finer = 0; finer + 1 < levels_; finer += gpu::kPyramidLevelsPerPass) {
    const int count = std::min(gpu::kPyramidLevelsPerPass, levels_ - 1 - finer);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    bindLevel(gpu::kImageSourceUnit, power_, finer, GL_READ_ONLY);
    for (int k = 0; k < gpu::kPyramidLevelsPerPass; ++k)  // unused units: the top, not written
      bindLevel(GLuint(gpu::kImageDestinationUnit + k), power_,
                std::min(finer + 1 + k, levels_ - 1), GL_WRITE_ONLY);
    sum_.set("u_levels", count);
    const int size = std::max(1, resolution_ >> (finer + count));
    sum_.set("u_top_size", glm::ivec2(size, size));
    const GLuint groups = GLuint((size + gpu::kPyramidGroupSize - 1) / gpu::kPyramidGroupSize);
    gl::dispatchCompute(groups, groups, 1);
  }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void TexelSelection::select(const std::vector<float>& u) {
  if (int(u.size()) > capacity_)
    throw std::invalid_argument("more selections than the Shooters buffer holds");
  if (method_ == SelectionMethod::kGpu)
    selectOnGpu(u);
  else
    selectOnCpu(u);
}

void TexelSelection::selectOnGpu(const std::vector<float>& u) {
  std::vector<gpu::Shooter> start(u.size(), kNoShooter);
  for (std::size_t i = 0; i < u.size(); ++i) start[i].u = u[i];
  shooters_.update(0, start.size() * sizeof(gpu::Shooter), start.data());
  shooters_.bindBase(GL_SHADER_STORAGE_BUFFER, gpu::kShootersBinding);
  descend_.use();
  descend_.set("u_count", int(u.size()));
  descend_.set("u_top", levels_ - 1);
  power_.bind(gpu::kRadiosityPowerUnit);
  const GLuint groups = GLuint((u.size() + gpu::kDescentGroupSize - 1) / gpu::kDescentGroupSize);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  gl::dispatchCompute(groups, 1, 1);  // every level in one pass
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_UNIFORM_BARRIER_BIT);
}

void TexelSelection::selectOnCpu(const std::vector<float>& u) {
  // The paper's scheme: read the whole map back, sum it, then walk it with a running sum until
  // the sum passes u·Φ. The read-back waits for every pass before it.
  std::vector<float>& power = read_back_;
  power.resize(std::size_t(resolution_) * std::size_t(resolution_));
  glGetTextureImage(power_.id(), 0, GL_RED, GL_FLOAT, GLsizei(power.size() * sizeof(float)),
                    power.data());
  double total = 0;
  for (float p : power) total += p;
  std::vector<gpu::Shooter> selected(u.size(), kNoShooter);
  for (std::size_t s = 0; s < u.size(); ++s) {
    gpu::Shooter& out = selected[s];
    out.u = u[s];
    out.total_power = float(total);
    if (total <= 0) continue;  // texel stays (−1, −1)
    const double target = double(u[s]) * total;
    double running = 0;
    std::size_t last_with_power = 0;
    std::size_t chosen = power.size();
    for (std::size_t i = 0; i < power.size(); ++i) {
      if (power[i] <= 0) continue;
      last_with_power = i;
      running += power[i];
      if (running > target) {
        chosen = i;
        break;
      }
    }
    if (chosen == power.size()) chosen = last_with_power;  // rounding at the very end
    out.texel = {int(chosen % std::size_t(resolution_)), int(chosen / std::size_t(resolution_))};
    out.power = power[chosen];
  }
  shooters_.update(0, selected.size() * sizeof(gpu::Shooter), selected.data());
}

std::vector<gpu::Shooter> TexelSelection::readSelections(int count) const {
  std::vector<gpu::Shooter> out(std::size_t(count), kNoShooter);
  glGetNamedBufferSubData(shooters_.id(), 0, GLsizeiptr(out.size() * sizeof(gpu::Shooter)),
                          out.data());
  return out;
}

}  // namespace gib::rt
