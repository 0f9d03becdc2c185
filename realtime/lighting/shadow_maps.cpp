#include "realtime/lighting/shadow_maps.h"

#include "realtime/cube_faces.h"
#include "realtime/gl/gpu_commands.h"
#include "realtime/gl/pass_profiler.h"
#include "realtime/gl/pipeline_state.h"
#include "realtime/gl/shader_library.h"
#include "realtime/lighting/light_sample_shared.h"
#include "realtime/lighting/lighting_shared.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gib::rt {

namespace {

// Largest angle between a 90° face's axis and a direction it covers (to its corners).
const float kFaceHalfDiagonal = std::acos(1.0f / std::sqrt(3.0f));
// What a cleared map holds: nothing closer than the far plane (depth), or for a variance shadow
// map moments far beyond any scaled light distance.
constexpr float kFarDepth = 1.0f;
constexpr float kFarMoments[4] = {1e4f, 1e8f, 0, 0};
// The maps of one kind of a batch may take this much memory (a GPU has far more; llvmpipe keeps
// them in host memory): 16 cube maps of 512² depth, or 8 with variance moments.
constexpr double kBatchBudgetBytes = 256.0 * 1024 * 1024;
// The shadow pass names a face by its records' base instance (kVertexInstanceLocation).
static_assert(gpu::kMaxShadowFaces <= gpu::kMaxVertexInstances);

// `single`: batches of one sample, whose point-sample maps are one cube map rather than a
// cube-map array of one (llvmpipe samples a cube map about a tenth faster).
std::string kindDefines(LightSampleKind kind, bool variance, bool single) {
  std::string d = kind == LightSampleKind::kPoint ? "#define POINT_LIGHT 1\n" : "";
  if (kind == LightSampleKind::kPoint && single) d += "#define SINGLE_CUBE_MAP 1\n";
  if (variance) d += "#define VARIANCE_SHADOW_MAP 1\n";
  return d;
}

void setupDepthTexture(gl::Texture& texture, bool compare_filtered) {
  // Hard shadows take the nearest texel's comparison; PCF lets the hardware filter 2×2 of them.
  texture.setDepthCompare(true);
  const GLenum filter = compare_filtered ? GL_LINEAR : GL_NEAREST;
  texture.setFilter(filter, filter);
}

// What the shadow pass keeps of the scene for a sample (shadow.vert.glsl clips the rest): for a
// point sample whose cone is at most a hemisphere, the half-space in front of the plane through
// it across its axis, dot(plane, (p, 1)) ≥ 0; else everything.
glm::vec4 keptHalfSpace(const LightSample& sample) {
  if (sample.kind != LightSampleKind::kPoint || sample.cos_cone < 0.0f) return kKeepEverything;
  return glm::vec4(sample.axis, -glm::dot(sample.axis, sample.position));
}

// The texels of cube face `face` around point sample `sample` that can hold anything drawn, as
// packed column and row ranges (ShadowFace::layer_slot.zw): all of them, or, where the shadow
// pass clips what lies behind the sample's plane (shadow.vert.glsl: a cone of at most a
// hemisphere), the bounding box of the part of the face in front of the plane, widened by
// `margin` texels. The face's normalised coordinates (u, v) look along u·s + v·t + f (the axes
// glm::lookAt builds from the face's axis f and up vector), which is in front when
// u·(s·a) + v·(t·a) + f·a ≥ 0 for the sample's axis a.
glm::ivec2 drawnTexels(const LightSample& sample, int face, int size, int margin) {
  const int everything = gpu::packTexelRange(0, size);
  const glm::vec4 kept = keptHalfSpace(sample);
  if (kept == kKeepEverything) return {everything, everything};
  const glm::vec3 f = kCubeFaceAxis[face];
  const glm::vec3 s = glm::normalize(glm::cross(f, kCubeFaceUp[face]));
  const glm::vec3 t = glm::cross(s, f);
  const glm::vec3 a = glm::normalize(glm::vec3(kept));
  auto front = [&](glm::vec2 p) {
    return p.x * glm::dot(s, a) + p.y * glm::dot(t, a) + glm::dot(f, a);
  };
  // The face's square clipped by the half-plane front ≥ 0: its corners in front, and where an
  // edge crosses the line.
  const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  glm::vec2 lo(2.0f), hi(-2.0f);
  for (int i = 0; i < 4; ++i) {
    const glm::vec2 p = corners[i], q = corners[(i + 1) % 4];
    const float fp = front(p), fq = front(q);
    if (fp >= 0.0f) lo = glm::min(lo, p), hi = glm::max(hi, p);
    if ((fp < 0.0f) != (fq < 0.0f)) {
      const glm::vec2 crossing = p + (q - p) * (fp / (fp - fq));
      lo = glm::min(lo, crossing), hi = glm::max(hi, crossing);
    }
  }
  if (lo.x > hi.x) return {gpu::packTexelRange(0, 0), gpu::packTexelRange(0, 0)};  // none
  auto range = [&](float low, float high) {
    const int first = int(std::floor((low + 1.0f) * 0.5f * float(size))) - margin;
    const int end = int(std::ceil((high + 1.0f) * 0.5f * float(size))) + margin;
    return gpu::packTexelRange(std::clamp(first, 0, size), std::clamp(end, 0, size));
  };
  return {range(lo.x, hi.x), range(lo.y, hi.y)};
}

}  // namespace

int shadowBatchCapacity(const ShadowSettings& settings, std::size_t sample_count) {
  const bool variance = settings.filter == ShadowFilter::kVariance;
  // Per cube map: depth, and for variance maps the moments and the filter's scratch (RG32F).
  const double bytes = 6.0 * double(settings.size) * double(settings.size) * (variance ? 20 : 4);
  const double fit = settings.batch_capacity > 0 ? double(settings.batch_capacity)
                                                 : std::floor(kBatchBudgetBytes / bytes);
  const double most = double(std::min<std::size_t>(sample_count, gpu::kMaxLightBatch));
  return int(std::max(1.0, std::min(fit, most)));
}

std::vector<std::span<const LightSample>> lightSampleBatches(std::span<const LightSample> samples,
                                                             int capacity) {
  if (capacity < 1) throw std::invalid_argument("a batch holds at least one light sample");
  std::vector<std::span<const LightSample>> batches;
  // Samples of one kind are contiguous in the scenes' sample lists (points, then directions),
  // but nothing here relies on it: a batch ends where the kind changes.
  std::size_t begin = 0;
  while (begin < samples.size()) {
    std::size_t end = begin + 1;
    while (end < samples.size() && end - begin < std::size_t(capacity) &&
           samples[end].kind == samples[begin].kind)
      ++end;
    batches.push_back(samples.subspan(begin, end - begin));
    begin = end;
  }
  return batches;
}

void ShadowMaps::declarePasses(PassDeclarations& passes, std::string_view parent) {
  passes.add(passPath({parent, kShadowMapPass}), "the scene drawn from a batch of light samples");
  passes.add(passPath({parent, kShadowMapFilterPass}),
             "variance shadow maps: the separable box filter of the batch's moments");
}

ShadowMaps::ShadowMaps(const ShadowSettings& settings, const GpuScene& scene, int capacity)
    : settings_(settings), capacity_(capacity) {
  if (capacity < 1 || capacity > gpu::kMaxLightBatch)
    throw std::invalid_argument(fmt::format(
        "a shadow map batch holds 1 to {} light samples, not {}", gpu::kMaxLightBatch, capacity));
  const glm::vec3 lo = scene.boundsMin(), hi = scene.boundsMax();
  centre_ = 0.5f * (lo + hi);
  radius_ = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  near_ = 1e-4f * radius_;
  far_ = 4.0f * radius_;  // from any light inside or near the scene to its far side
}

ShadowMaps::Layers& ShadowMaps::layers(LightSampleKind kind) {
  const bool cube = kind == LightSampleKind::kPoint;
  Layers& maps = cube ? cube_ : flat_;
  if (maps.framebuffer) return maps;
  const bool variance = settings_.filter == ShadowFilter::kVariance;
  const std::string defines = kindDefines(kind, variance, capacity_ == 1);
  maps.depth_program = gl::buildLayeredProgram(
      {"realtime/lighting/shadow.vert.glsl", "realtime/lighting/shadow.geom.glsl",
       "realtime/lighting/shadow.frag.glsl"},
      defines, settings_.layer_from_geometry_shader);
  const int n = settings_.size;
  auto make = [&](GLenum format) {
    if (!cube) return gl::Texture::make2DArray(format, n, n, capacity_);
    return capacity_ == 1 ? gl::Texture::makeCube(format, n)
                          : gl::Texture::makeCubeArray(format, n, capacity_);
  };
  maps.depth = make(GL_DEPTH_COMPONENT32F);
  if (variance) {
    maps.blur_program = gl::buildProgram(
        {{GL_COMPUTE_SHADER, "realtime/lighting/vsm_blur.comp.glsl"}},
        defines + fmt::format("#define VSM_BLUR_RADIUS {}\n", settings_.blur_radius));
    maps.moments = make(GL_RG32F);
    maps.scratch = make(GL_RG32F);
  } else {
    setupDepthTexture(maps.depth, settings_.filter == ShadowFilter::kPcf);
  }
  gl::Framebuffer& fb = maps.framebuffer.emplace();
  fb.attachDepth(maps.depth);  // every layer: a layered framebuffer
  if (variance) fb.attachColor(0, maps.moments);
  fb.setDrawBuffers(variance ? 1 : 0);
  fb.checkComplete();
  return maps;
}

std::string ShadowMaps::defines(LightSampleKind kind) const {
  return kindDefines(kind, settings_.filter == ShadowFilter::kVariance, capacity_ == 1);
}

glm::mat4 ShadowMaps::flatViewProjection(const LightSample& sample) const {
  const glm::vec3 axis = glm::normalize(sample.axis);
  const glm::vec3 eye = centre_ - axis * (2.0f * radius_);
  const glm::vec3 up = std::abs(axis.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::ortho(-radius_, radius_, -radius_, radius_, radius_, 3.0f * radius_) *
         glm::lookAt(eye, centre_, up);
}

void ShadowMaps::render(const GpuScene& scene, std::span<const LightSample> batch,
                        gl::PassProfiler& profiler) {
  if (batch.empty() || int(batch.size()) > capacity_)
    throw std::invalid_argument(
        fmt::format("a batch of {} light samples for maps of {}", batch.size(), capacity_));
  const LightSampleKind kind = batch.front().kind;
  for (const LightSample& sample : batch)
    if (sample.kind != kind) throw std::invalid_argument("a batch of light samples of two kinds");
  batch_kind_ = kind;
  batch_size_ = int(batch.size());
  std::vector<gpu::GpuLightSample> records;
  for (const LightSample& s : batch) {
    const glm::mat4 view_projection =
        kind == LightSampleKind::kPoint ? glm::mat4(1.0f) : flatViewProjection(s);
    records.push_back(toGpuLightSample(s, view_projection));
  }

  // The layers to draw: every cube face a point sample can light (the others are cleared, not
  // drawn), or each directional sample's map.
  std::vector<gpu::ShadowFace> faces;
  for (int slot = 0; slot < batch_size_; ++slot) {
    const LightSample& sample = batch[std::size_t(slot)];
    if (kind != LightSampleKind::kPoint) {
      const int everything = gpu::packTexelRange(0, settings_.size);
      faces.push_back({records[std::size_t(slot)].view_projection,
                       glm::ivec4(slot, slot, everything, everything)});
      continue;
    }
    const float cone = std::acos(std::clamp(sample.cos_cone, -1.0f, 1.0f));
    for (int face = 0; face < 6; ++face) {
      const float angle =
          std::acos(std::clamp(glm::dot(kCubeFaceAxis[face], sample.axis), -1.0f, 1.0f));
      if (angle >= cone + kFaceHalfDiagonal) continue;  // the sample sends no light this way
      const glm::ivec2 drawn = drawnTexels(sample, face, settings_.size, settings_.blur_radius + 1);
      faces.push_back({cubeFaceViewProjection(sample.position, face, near_, far_),
                       glm::ivec4(6 * slot + face, slot, drawn.x, drawn.y)});
    }
  }
  // Each face draws the chunks of triangles its frustum may touch, in front of the plane its
  // sample clips at (shadow.vert.glsl), through records whose base instance names the face.
  std::vector<DrawArraysIndirectCommand> draws;
  for (std::size_t f = 0; f < faces.size(); ++f)
    scene.appendViewRecords(faces[f].view_projection, GLuint(f), settings_.cull_faces, draws,
                            keptHalfSpace(batch[std::size_t(faces[f].layer_slot.y)]));
  // The uniform blocks are bound at their declared sizes, whatever part of them a batch fills.
  constexpr std::size_t kSamplesBlock = sizeof(gpu::GpuLightSample) * gpu::kMaxLightBatch;
  constexpr std::size_t kFacesBlock = sizeof(gpu::ShadowFace) * gpu::kMaxShadowFaces;
  stream_.beginRound(
      {kSamplesBlock, kFacesBlock, draws.size() * sizeof(DrawArraysIndirectCommand)});
  samples_offset_ = stream_.push(records, kSamplesBlock);
  stream_.bindRange(GL_UNIFORM_BUFFER, gpu::kLightSamplesBinding, samples_offset_, kSamplesBlock);
  const std::size_t faces_offset = stream_.push(faces, kFacesBlock);
  stream_.bindRange(GL_UNIFORM_BUFFER, gpu::kShadowFacesBinding, faces_offset, kFacesBlock);
  const std::size_t draws_offset = stream_.push(draws);

  Layers& maps = layers(kind);
  {
    auto pass = profiler.pass(kShadowMapPass);
    // Slope-scaled depth offset: the book's depth bias, scaled by the surface's slope in the map.
    // What lies behind a point sample's plane is clipped (shadow.vert.glsl).
    const gl::PipelineScope state({
        .depth_test = GL_LESS,
        .polygon_offset = gl::PolygonOffset{1.5f, 2.0f},
        .clip_distances = 1,
        .viewport = gl::PixelRect{0, 0, settings_.size, settings_.size},
    });
    // A layered framebuffer's clear clears every layer: nothing closer than the far plane, or
    // for variance maps moments far beyond any scaled light distance.
    glClearNamedFramebufferfv(maps.framebuffer->id(), GL_DEPTH, 0, &kFarDepth);
    if (settings_.filter == ShadowFilter::kVariance)
      glClearNamedFramebufferfv(maps.framebuffer->id(), GL_COLOR, 0, kFarMoments);
    maps.framebuffer->bind();
    maps.depth_program.use();
    // Only a point sample's variance map stores distances, over u_far; the other maps store depth
    // alone (light_space.glsl, shadow.frag.glsl), and their programs have no u_far.
    maps.depth_program.setIfPresent("u_far", far_);
    scene.drawRecords(stream_.id(), draws_offset, draws.size());
  }
  if (settings_.filter == ShadowFilter::kVariance) blur(kind, int(faces.size()), profiler);
}

void ShadowMaps::blur(LightSampleKind kind, int face_count, gl::PassProfiler& profiler) {
  auto pass = profiler.pass(kShadowMapFilterPass);
  Layers& maps = layers(kind);
  const gl::Program& program = maps.blur_program;
  program.use();
  // Work groups: lines of the layer, segments along them, and the faces the shadow pass drew
  // (its face list is still bound: the layers the others are cleared to stay as they are).
  const GLuint lines =
      GLuint((settings_.size + gpu::kVsmBlurGroupSize - 1) / gpu::kVsmBlurGroupSize);
  const GLuint segments =
      GLuint((settings_.size + gpu::kVsmBlurSegment - 1) / gpu::kVsmBlurSegment);
  // Along rows into the scratch maps, then along columns back.
  const gl::Texture* source[2] = {&maps.moments, &maps.scratch};
  const gl::Texture* destination[2] = {&maps.scratch, &maps.moments};
  const int steps[2][2] = {{1, 0}, {0, 1}};
  for (int i = 0; i < 2; ++i) {
    glBindImageTexture(gpu::kImageSourceUnit, source[i]->id(), 0, GL_TRUE, 0, GL_READ_ONLY,
                       GL_RG32F);
    glBindImageTexture(gpu::kImageDestinationUnit, destination[i]->id(), 0, GL_TRUE, 0,
                       GL_WRITE_ONLY, GL_RG32F);
    program.set("u_step", glm::ivec2(steps[i][0], steps[i][1]));
    gl::dispatchCompute(lines, segments, GLuint(face_count));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  }
}

void ShadowMaps::setLookupConstants(const gl::Program& program) const {
  // What a lookup reads depends on the program's defines (shadow_lookup.glsl): a point sample's
  // cube maps are compared at depths between u_near and u_far (its variance maps store distances
  // over u_far alone), a directional map's texels span u_ortho_extent, and only a variance map
  // has a variance floor. The linker drops the others.
  program.setIfPresent("u_near", near_);
  program.setIfPresent("u_far", far_);
  program.set("u_shadow_map_size", settings_.size);
  program.setIfPresent("u_ortho_extent", 2.0f * radius_);
  program.set("u_normal_offset", settings_.normal_offset);
  program.set("u_pcf_radius", settings_.filter == ShadowFilter::kPcf ? settings_.pcf_radius : 0);
  program.setIfPresent("u_min_variance", settings_.min_variance);
}

const gl::Texture& ShadowMaps::lookupMaps() const {
  const Layers& maps = batch_kind_ == LightSampleKind::kPoint ? cube_ : flat_;
  return settings_.filter == ShadowFilter::kVariance ? maps.moments : maps.depth;
}

void ShadowMaps::bindForLookup(const gl::Program& program) const {
  lookupMaps().bind(gpu::kShadowMapUnit);
  stream_.bindRange(GL_UNIFORM_BUFFER, gpu::kLightSamplesBinding, samples_offset_,
                    sizeof(gpu::GpuLightSample) * gpu::kMaxLightBatch);
  program.set("u_light_sample_count", batch_size_);
}

}  // namespace gib::rt
