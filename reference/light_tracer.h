// The light tracer (docs/rendering.md, "Caustics: light tracing"): particles leave the lights,
// follow mirrors and glass, and each diffuse surface they reach is connected to the pinhole
// camera, which adds their light to the pixel it projects to. It carries exactly the paths the
// path tracer leaves to it (PathTracer's `light_paths`): the vertex next to the light specular and
// the vertex the eye sees diffuse, L S (D|S)* D E in Heckbert's notation, within the path class.
// Those are the caustics, which a path tracer cannot reach from a delta light at all and reaches
// slowly from a small area light. A light path that meets a diffuse surface first ends there.
#pragma once

#include "reference/path_sampler.h"
#include "reference/path_tracer.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace gib::ref {

// Light one path adds to one pixel, already divided by the pixel count (see LightTracer::trace).
struct LightSplat {
  std::uint32_t pixel = 0;
  Rgb value{0.0f};
};

class LightTracer {
 public:
  // Whether the light tracer has paths to carry in `scene`: mirrors or glass, and no medium (it
  // does not trace participating media; the cloud has no specular surface).
  static bool applies(const scene::Scene& scene);

  // Shares the path tracer's BVH, triangles, light sampler and path class.
  LightTracer(const scene::Scene& scene, const PathTracer& tracer, int width, int height);

  // Traces one light path with `sampler`'s dimensions (vertex 0: the light; vertex i: the i-th
  // scattering) and appends its splats. Tracing one path per pixel and sample makes the splats,
  // summed into the pixels' sums, an estimator of the same pixel means the camera paths estimate
  // (each splat is divided by the pixel count). Returns the rays traced.
  std::uint32_t trace(PathSampler& sampler, std::vector<LightSplat>& splats) const;

  // A diffuse vertex of a light path that the path class accepts as the eye's vertex: where a
  // particle lands and the flux it brings (before the surface reflects it).
  struct Landing {
    glm::vec3 point{0.0f};
    glm::vec3 normal{0.0f};  // geometric, on the side the particle arrives from
    const Bsdf* bsdf = nullptr;
    Rgb flux{0.0f};
    int vertex = 0;  // 1 is the first scattering vertex
  };
  using LandingVisitor = std::function<void(const Landing&)>;
  // The light path alone, without the camera: calls `visit` at each landing (what `trace`
  // connects to the camera). Tests measure the flux it carries. Returns the rays traced.
  std::uint32_t walk(PathSampler& sampler, const LandingVisitor& visit) const;

 private:
  struct Emission {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f};
    glm::vec3 normal{0.0f};  // of an area light, to offset the first ray; zero otherwise
    Rgb flux{0.0f};          // the particle's weight: power over the density of choosing it
  };
  // Chooses a light by power and a particle leaving it.
  bool emit(PathSampler& sampler, Emission& emission) const;
  // The camera's view of a diffuse vertex: its splat, if the camera sees the point.
  void connectToCamera(const glm::vec3& point, const glm::vec3& normal, const Bsdf& bsdf,
                       const Rgb& flux, std::uint32_t& rays, std::vector<LightSplat>& splats) const;

  const scene::Scene& scene_;
  const PathTracer& tracer_;
  int width_;
  int height_;
  scene::CameraFrame camera_;
  float pixel_area_;  // of one pixel on the image plane at distance 1
  // The lights' power (luminance), cumulative: area lights together, then each spot, then each
  // directional light.
  std::vector<float> light_cdf_;
  float total_power_ = 0;
  Rgb area_power_{0.0f};
  glm::vec3 scene_centre_{0.0f};
  float scene_radius_ = 0;
};

}  // namespace gib::ref
