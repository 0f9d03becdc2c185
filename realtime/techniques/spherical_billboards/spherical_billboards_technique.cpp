#include "realtime/techniques/spherical_billboards/spherical_billboards_technique.h"

#include "realtime/gl/pass_profiler.h"
#include "realtime/gpu_scene/gpu_scene.h"
#include "realtime/render_target.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace gib::rt {

namespace {

constexpr std::string_view kVolumeShadowPass = "volume shadow";

}  // namespace

SphericalBillboardsTechnique::SphericalBillboardsTechnique(const ParameterValues& p)
    : sky_directions_(p.integer("sky_directions")), compositor_(p) {}

void SphericalBillboardsTechnique::prepare(const GpuScene& scene, int width, int height) {
  width_ = width;
  height_ = height;
  medium_.emplace(scene.scene(), "spherical_billboards");
  compositor_.prepare(scene, *medium_);
  volume_shadow_.emplace();
  // Transmittance directions: towards each light, then the sky's (the D directions the view
  // shading weighs the sky with).
  std::vector<glm::vec4> directions = medium_->towardsLights();
  const std::vector<glm::vec4> sky =
      std::max({medium_->sky().r, medium_->sky().g, medium_->sky().b}) > 0
          ? sphereDirections(sky_directions_)
          : std::vector<glm::vec4>{};
  directions.insert(directions.end(), sky.begin(), sky.end());
  directions_ = gl::Buffer::fromVector(directions);
  sky_directions_buffer_ = gl::Buffer::fromVector(sky);
}

void SphericalBillboardsTechnique::render(Frame& frame) {
  compositor_.renderSurfaces(frame);
  const int sky = int(sky_directions_buffer_.bytes() / sizeof(glm::vec4));
  const int stride = medium_->lightCount() + sky;
  {
    auto pass = frame.profiler.pass(kVolumeShadowPass);
    volume_shadow_->compute(*medium_, directions_, stride, transmittance_);
  }
  compositor_.shade({&transmittance_, stride, &sky_directions_buffer_, sky, nullptr},
                    frame.profiler);
  compositor_.sortAndSplat(frame);
}

std::vector<AuxiliaryImage> SphericalBillboardsTechnique::auxiliaryImages() {
  RenderTarget target(width_, height_);
  gl::PassProfiler untimed;
  Frame frame{target, untimed};
  const bool spherical = compositor_.spherical();
  auto imageWith = [&](bool with_spheres) {
    compositor_.setSpherical(with_spheres);
    target.clear(0, 0, 0);
    render(frame);
    return target.read();
  };
  const image::Image planar = imageWith(false), spheres = imageWith(true);
  compositor_.setSpherical(spherical);
  // The difference is a few per cent of the radiance: scaled so that its largest value is white.
  image::Image difference(width_, height_, 3);
  float largest = 0;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x)
      for (int c = 0; c < 3; ++c) {
        const float d = std::abs(planar.pixel(x, y)[c] - spheres.pixel(x, y)[c]);
        difference.pixel(x, y)[c] = d;
        largest = std::max(largest, d);
      }
  if (largest > 0)
    for (int y = 0; y < height_; ++y)
      for (int x = 0; x < width_; ++x)
        for (int c = 0; c < 3; ++c) difference.pixel(x, y)[c] /= largest;
  return {{"clipping",
           fmt::format("|planar − spherical billboards| over its largest value ({:.3g}): where "
                       "classic billboards clip against surfaces and the near plane (book Figs. "
                       "9.3, 9.8)",
                       largest),
           std::move(difference)}};
}

std::vector<TechniqueStatistic> SphericalBillboardsTechnique::statistics() const {
  return {{"particles", double(medium_ ? medium_->count() : 0)},
          {"lights", double(medium_ ? medium_->lightCount() : 0)},
          {"sky_directions", double(sky_directions_buffer_.bytes() / sizeof(glm::vec4))}};
}

TechniqueInfo sphericalBillboardsTechniqueInfo() {
  TechniqueInfo info;
  info.name = "spherical_billboards";
  info.description =
      "a particle medium with single scattering: volume-shadowed particles splatted as "
      "billboards whose opacity is the eye ray's optical depth in each sphere, clipped "
      "against surfaces";
  info.source =
      "Szirmay-Kalos et al., GPU-Based Techniques for Global Illumination Effects, "
      "§9.3 (spherical billboards) and §9.4 (illuminating participating media)";
  info.parameters = joinParameterTables(
      {{numericParameter("sky_directions", ParameterType::kInteger, "16", 0, 1024, "directions",
                         "directions over the sphere whose transmittance weighs the sky's single "
                         "scattering (0: the medium scatters no sky light)")},
       ParticleCompositor::parameters()});
  ParticleCompositor::declarePasses(info.passes);
  info.passes.add(passPath({kFramePass, kVolumeShadowPass}),
                  "each particle's transmittance towards the lights and the sky directions "
                  "through the rest of the medium");
  info.auxiliary_images = {
      {"clipping",
       "|planar − spherical billboards| over its largest value: where classic billboards clip "
       "(book Figs. 9.3, 9.8)"},
  };
  info.statistics = ParticleCompositor::statistics(
      {{"sky_directions", "directions whose transmittance weighs the sky"}});
  info.needs = {TechniqueNeed::kMedium};
  info.create = [](const ParameterValues& values) -> std::unique_ptr<Technique> {
    return std::make_unique<SphericalBillboardsTechnique>(values);
  };
  return info;
}

}  // namespace gib::rt
