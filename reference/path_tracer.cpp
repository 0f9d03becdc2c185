#include "reference/path_tracer.h"

#include "reference/bsdf.h"
#include "reference/sampling.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace gib::ref {

using scene::Rgb;

namespace {

// Power heuristic (β = 2) for one sample from each of two strategies.
float powerHeuristic(float pdf_a, float pdf_b) {
  float a = pdf_a * pdf_a;
  float b = pdf_b * pdf_b;
  return a + b > 0 ? a / (a + b) : 0.0f;
}

float maxComponent(const Rgb& c) {
  return std::max(c.r, std::max(c.g, c.b));
}

}  // namespace

// Shadow rays run from the offset origin to the target point itself, stopping `epsilon` short of
// it so that the surface the target lies on is not found.
bool PathTracer::segmentIsClear(const glm::vec3& origin, const glm::vec3& target) const {
  glm::vec3 d = target - origin;
  float length = glm::length(d);
  float eps = embree_.rayEpsilon();
  if (length <= 2 * eps) return true;
  return !embree_.occluded(origin, d / length, 0.0f, length - eps);
}

struct PathTracer::Vertex {
  glm::vec3 point;
  glm::vec3 normal;  // geometric normal turned towards wo
  const Bsdf* bsdf;
  float epsilon;
  glm::vec3 spawnOrigin() const { return point + epsilon * normal; }
};

PathTracer::PathTracer(const scene::Scene& scene, PathClass path_class)
    : scene_(scene),
      path_class_(path_class),
      embree_(scene),
      triangles_(scene),
      area_lights_(scene, triangles_),
      has_sky_(maxComponent(scene.sky_radiance) > 0) {}

Rgb PathTracer::estimateDirect(const Vertex& v, SampleStream& random, std::uint32_t& rays) const {
  Rgb result(0.0f);
  // Geometry (distances, cosines) is measured from the surface point itself; only shadow rays
  // start from the offset origin, so the offset does not bias inverse-square falloff.
  const glm::vec3 origin = v.spawnOrigin();
  const float eps = v.epsilon;

  // Area lights: one point chosen by power, weighted against BSDF sampling.
  if (!area_lights_.empty()) {
    float u_select = random.next();
    glm::vec2 u_point(random.next(), random.next());
    AreaLightSample s = area_lights_.sample(u_select, u_point);
    const TriangleRecord& light = triangles_[s.triangle];
    glm::vec3 to_light = s.point - v.point;
    float dist2 = glm::dot(to_light, to_light);
    float dist = std::sqrt(dist2);
    glm::vec3 wi = to_light / dist;
    float cos_light = -glm::dot(light.normal, wi);
    float cos_surface = glm::dot(v.normal, wi);
    if (cos_light > 0 && cos_surface > 0 && dist > 2 * eps) {
      Rgb f = v.bsdf->evaluate(wi);
      if (maxComponent(f) > 0) {
        ++rays;
        if (segmentIsClear(origin, s.point)) {
          float pdf_light = s.pdf_area * dist2 / cos_light;
          float weight = powerHeuristic(pdf_light, v.bsdf->pdf(wi));
          result +=
              f * scene_.materials[light.material].emission * (cos_surface * weight / pdf_light);
        }
      }
    }
  }

  // Constant sky: a uniform direction on the hemisphere, weighted against BSDF sampling.
  if (has_sky_) {
    glm::vec3 wi = Frame(v.normal).toWorld(sampleUniformHemisphere({random.next(), random.next()}));
    float cos_surface = glm::dot(v.normal, wi);
    Rgb f = v.bsdf->evaluate(wi);
    if (cos_surface > 0 && maxComponent(f) > 0) {
      ++rays;
      if (!embree_.occluded(origin, wi, 0.0f, std::numeric_limits<float>::infinity())) {
        float weight = powerHeuristic(kUniformHemispherePdf, v.bsdf->pdf(wi));
        result += f * scene_.sky_radiance * (cos_surface * weight / kUniformHemispherePdf);
      }
    }
  }

  // Spot lights: I(θ) = I·cosᵏθ inside the cone; irradiance I·cos/d².
  for (const scene::SpotLight& spot : scene_.spot_lights) {
    glm::vec3 to_light = spot.position - v.point;
    float dist2 = glm::dot(to_light, to_light);
    float dist = std::sqrt(dist2);
    glm::vec3 wi = to_light / dist;
    float cos_surface = glm::dot(v.normal, wi);
    float cos_axis = -glm::dot(wi, glm::normalize(spot.direction));
    float cos_cone = std::cos(glm::radians(spot.cone_angle_deg));
    if (cos_surface <= 0 || cos_axis < cos_cone || dist <= eps) continue;
    Rgb f = v.bsdf->evaluate(wi);
    if (maxComponent(f) <= 0) continue;
    ++rays;
    if (!segmentIsClear(origin, spot.position)) continue;
    Rgb intensity = spot.intensity * std::pow(std::max(cos_axis, 0.0f), spot.falloff_exponent);
    result += f * intensity * (cos_surface / dist2);
  }

  // Directional lights: irradiance E·cos on the surface.
  for (const scene::DirectionalLight& sun : scene_.directional_lights) {
    glm::vec3 wi = -glm::normalize(sun.direction);
    float cos_surface = glm::dot(v.normal, wi);
    if (cos_surface <= 0) continue;
    Rgb f = v.bsdf->evaluate(wi);
    if (maxComponent(f) <= 0) continue;
    ++rays;
    if (embree_.occluded(origin, wi, 0.0f, std::numeric_limits<float>::infinity())) continue;
    result += f * sun.irradiance * cos_surface;
  }
  return result;
}

RadianceSample PathTracer::radiance(const glm::vec3& camera_origin,
                                    const glm::vec3& camera_direction, SampleStream& random) const {
  RadianceSample out;
  auto record = [&](int bounces, const Rgb& contribution) {
    if (!path_class_.contains(bounces)) return;
    out.total += contribution;
    if (bounces <= 1) out.direct += contribution;
  };

  glm::vec3 origin = camera_origin;
  glm::vec3 direction = camera_direction;
  Rgb throughput(1.0f);
  int bounces = 0;               // scattering vertices so far
  float previous_bsdf_pdf = 0;   // density of `direction` at the previous vertex
  glm::vec3 previous_normal(0);  // that vertex's normal, for the sky's MIS density

  for (;;) {
    // Find the next vertex.
    ++out.rays;
    Hit hit = embree_.intersect(origin, direction);
    if (!hit.valid()) {
      if (has_sky_) {
        float weight = 1.0f;
        if (bounces > 0) {
          float pdf_sky = glm::dot(previous_normal, direction) > 0 ? kUniformHemispherePdf : 0;
          weight = powerHeuristic(previous_bsdf_pdf, pdf_sky);
        }
        record(bounces, throughput * scene_.sky_radiance * weight);
      }
      break;
    }
    const std::uint32_t tri_index = triangles_.globalIndex(hit.mesh, hit.triangle);
    const TriangleRecord& tri = triangles_[tri_index];
    const scene::Material& material = scene_.materials[tri.material];
    const glm::vec3 wo = -direction;
    const glm::vec3 point = origin + hit.t * direction;

    // Emission reached by the camera ray or by BSDF sampling (one-sided: front faces only).
    float cos_emitter = glm::dot(tri.normal, wo);
    if (material.isEmissive() && cos_emitter > 0) {
      float weight = 1.0f;
      if (bounces > 0) {
        float pdf_light = area_lights_.pdfArea(tri_index) * hit.t * hit.t / cos_emitter;
        weight = powerHeuristic(previous_bsdf_pdf, pdf_light);
      }
      record(bounces, throughput * material.emission * weight);
    }
    if (bounces >= path_class_.max_bounces) break;

    // Scatter: this vertex is bounce number `bounces`.
    ++bounces;
    glm::vec3 normal = cos_emitter >= 0 ? tri.normal : -tri.normal;
    Bsdf bsdf(material, normal, wo);
    if (bsdf.isBlack()) break;
    Vertex vertex{point, normal, &bsdf, embree_.rayEpsilon()};
    if (bounces >= path_class_.min_bounces)
      record(bounces, throughput * estimateDirect(vertex, random, out.rays));

    // Continue the path by sampling the BSDF.
    float u_lobe = random.next();
    BsdfSample s = bsdf.sample(u_lobe, {random.next(), random.next()});
    float cos_wi = glm::dot(normal, s.wi);
    if (s.pdf <= 0 || cos_wi <= 0 || maxComponent(s.f) <= 0) break;
    throughput *= s.f * (cos_wi / s.pdf);

    // Russian roulette: survive with probability q and divide by q, which keeps the estimator
    // unbiased; q follows the throughput so that dim paths end early.
    if (bounces >= kRouletteStartBounce) {
      float q = std::min(0.95f, maxComponent(throughput));
      if (random.next() >= q) break;
      throughput /= q;
    }
    origin = vertex.spawnOrigin();
    direction = s.wi;
    previous_bsdf_pdf = s.pdf;
    previous_normal = normal;
  }
  return out;
}

}  // namespace gib::ref
