#include "reference/path_tracer.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace gib::ref {

using scene::Rgb;

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Power heuristic (β = 2) for one sample from each of two strategies.
float powerHeuristic(float pdf_a, float pdf_b) {
  float a = pdf_a * pdf_a;
  float b = pdf_b * pdf_b;
  return a + b > 0 ? a / (a + b) : 0.0f;
}

float maxComponent(const Rgb& c) {
  return std::max(c.r, std::max(c.g, c.b));
}

// The randomness of a tracking walk whose first draw is `first` (one of the sampler's
// dimensions). Without a medium no walk happens, and the point is not computed.
template <typename FirstDraw>
WalkRandom walkRandom(bool has_medium, PathSampler& sampler, FirstDraw&& first) {
  return has_medium ? WalkRandom(first(), sampler.independent())
                    : WalkRandom(sampler.independent());
}

}  // namespace

PathTracer::PathTracer(const scene::Scene& scene, PathClass path_class, bool light_paths,
                       bool environment_occlusion)
    : scene_(scene),
      path_class_(path_class),
      expression_(scene::compilePathClass(path_class)),
      light_paths_(light_paths),
      embree_(scene),
      triangles_(scene),
      area_lights_(scene, triangles_),
      density_(scene.medium.particles),
      has_sky_(maxComponent(scene.sky_radiance) > 0),
      environment_occlusion_(environment_occlusion) {
  if (!density_.empty()) medium_.emplace(density_);
  if (!scene.environment.empty()) environment_.emplace(scene.environment);
}

float PathTracer::segmentTransmittance(const glm::vec3& origin, const glm::vec3& target,
                                       WalkRandom random, std::uint32_t& rays) const {
  // Shadow rays stop `epsilon` short of the target so that the surface it lies on is not found.
  glm::vec3 d = target - origin;
  float length = glm::length(d);
  float eps = embree_.rayEpsilon();
  if (length <= 2 * eps) return 1.0f;
  d /= length;
  ++rays;
  if (embree_.occluded(origin, d, 0.0f, length - eps)) return 0.0f;
  return medium_ ? medium_->transmittance(origin, d, length, random) : 1.0f;
}

float PathTracer::rayTransmittance(const glm::vec3& origin, const glm::vec3& direction,
                                   WalkRandom random, std::uint32_t& rays) const {
  ++rays;
  if (embree_.occluded(origin, direction, 0.0f, kInfinity)) return 0.0f;
  return medium_ ? medium_->transmittance(origin, direction, kInfinity, random) : 1.0f;
}

float PathTracer::environmentTransmittance(const glm::vec3& origin, const glm::vec3& wi,
                                           PathSampler& sampler, std::uint32_t& rays) const {
  if (!environment_occlusion_) return 1.0f;
  return rayTransmittance(origin, wi,
                          walkRandom(medium_.has_value(), sampler,
                                     [&] { return sampler.get1D(VertexDimension::kSkyShadow); }),
                          rays);
}

float PathTracer::environmentLightWeight(float pdf_light, float pdf_scattering) const {
  return environment_occlusion_ ? powerHeuristic(pdf_light, pdf_scattering) : 1.0f;
}

Rgb PathTracer::estimateDirect(const ScatteringVertex& v, PathSampler& sampler,
                               std::uint32_t& rays) const {
  // Geometry (distances, cosines) is measured from the scattering point itself; only shadow rays
  // start from the offset origin, so the offset does not bias inverse-square falloff.
  Rgb result(0.0f);
  const glm::vec3 origin = v.spawnOrigin();
  const bool has_medium = medium_.has_value();

  // Area lights: one point chosen by power, weighted against BSDF or phase sampling.
  if (!area_lights_.empty()) {
    const AreaLightSample s = area_lights_.sample(sampler.get2D(VertexDimension::kLightPoint));
    const TriangleRecord& light = triangles_[s.triangle];
    const glm::vec3 to_light = s.point - v.point;
    const float dist2 = glm::dot(to_light, to_light);
    const glm::vec3 wi = to_light / std::sqrt(dist2);
    const float cos_light = -glm::dot(light.normal, wi);
    const Rgb f = v.evaluate(wi);
    if (cos_light > 0 && dist2 > 0 && maxComponent(f) > 0) {
      const float transmittance = segmentTransmittance(
          origin, s.point,
          walkRandom(has_medium, sampler,
                     [&] { return sampler.get1D(VertexDimension::kLightShadow); }),
          rays);
      if (transmittance > 0) {
        const float pdf_light = s.pdf_area * dist2 / cos_light;
        const float weight = powerHeuristic(pdf_light, v.pdf(wi));
        result +=
            f * scene_.materials[light.material].emission * (transmittance * weight / pdf_light);
      }
    }
  }

  // Constant sky: a uniform direction, weighted against BSDF or phase sampling.
  if (has_sky_) {
    const glm::vec3 wi = v.sampleSkyDirection(sampler.get2D(VertexDimension::kSkyDirection));
    const Rgb f = v.evaluate(wi);
    const float pdf_sky = v.skyPdf(wi);
    if (pdf_sky > 0 && maxComponent(f) > 0) {
      const float transmittance = environmentTransmittance(origin, wi, sampler, rays);
      if (transmittance > 0)
        result += f * scene_.sky_radiance *
                  (transmittance * environmentLightWeight(pdf_sky, v.pdf(wi)) / pdf_sky);
    }
  }

  // Environment map: a direction drawn by the map's luminance (the sky's dimensions: a scene has
  // a constant sky or a map, never both), weighted against BSDF or phase sampling.
  if (environment_ && !environment_->black()) {
    const scene::EnvironmentSample s =
        environment_->sample(sampler.get2D(VertexDimension::kSkyDirection));
    const Rgb f = s.pdf > 0 ? v.evaluate(s.direction) : Rgb(0.0f);
    if (maxComponent(f) > 0 && maxComponent(s.radiance) > 0) {
      const float transmittance = environmentTransmittance(origin, s.direction, sampler, rays);
      if (transmittance > 0)
        result += f * s.radiance *
                  (transmittance * environmentLightWeight(s.pdf, v.pdf(s.direction)) / s.pdf);
    }
  }

  // Spot lights: I(θ) = I·cosᵏθ inside the cone; irradiance I·cos/d². Delta light j's shadow
  // walk starts from its own dimension (spots first, then directional lights).
  std::size_t delta_light = 0;
  auto delta_light_walk = [&](std::size_t j) {
    return walkRandom(has_medium, sampler, [&] { return sampler.deltaLightShadow(j); });
  };
  for (const scene::SpotLight& spot : scene_.spot_lights) {
    const std::size_t j = delta_light++;
    const glm::vec3 to_light = spot.position - v.point;
    const float dist2 = glm::dot(to_light, to_light);
    const glm::vec3 wi = to_light / std::sqrt(dist2);
    const float cos_axis = -glm::dot(wi, glm::normalize(spot.direction));
    if (cos_axis < std::cos(glm::radians(spot.cone_angle_deg))) continue;
    const Rgb f = v.evaluate(wi);
    if (maxComponent(f) <= 0) continue;
    const float transmittance =
        segmentTransmittance(origin, spot.position, delta_light_walk(j), rays);
    if (transmittance <= 0) continue;
    const Rgb intensity =
        spot.intensity * std::pow(std::max(cos_axis, 0.0f), spot.falloff_exponent);
    result += f * intensity * (transmittance / dist2);
  }

  // Directional lights: irradiance E on a plane perpendicular to the light.
  for (const scene::DirectionalLight& sun : scene_.directional_lights) {
    const std::size_t j = delta_light++;
    const glm::vec3 wi = -glm::normalize(sun.direction);
    const Rgb f = v.evaluate(wi);
    if (maxComponent(f) <= 0) continue;
    const float transmittance = rayTransmittance(origin, wi, delta_light_walk(j), rays);
    if (transmittance > 0) result += f * sun.irradiance * transmittance;
  }
  return result;
}

RadianceSample PathTracer::radiance(const glm::vec3& camera_origin,
                                    const glm::vec3& camera_direction, PathSampler& sampler,
                                    const Hit* first_hit) const {
  using scene::PathEvent;
  using scene::PathExpression;
  RadianceSample out;
  // `state` is the path expression's automaton after reading E and the vertices so far, from the
  // eye (scene/path_expression.h): a contribution counts when reading L next accepts.
  auto record = [&](int state, int bounces, const Rgb& contribution) {
    if (!expression_.eyeAcceptsLight(state)) return;
    out.total += contribution;
    if (bounces <= 1) out.direct += contribution;
  };

  glm::vec3 origin = camera_origin;
  glm::vec3 direction = camera_direction;
  Rgb throughput(1.0f);
  int bounces = 0;  // scattering vertices so far
  int state = expression_.eyeStart();
  // What the first vertex the eye sees is: the light tracer's paths end on a diffuse one.
  bool eye_vertex_diffuse = false;
  // What the MIS weight of emission reached by a sampled direction needs of the vertex that
  // sampled it: the density of `direction` under its sampling (none for a specular vertex, which
  // next-event estimation cannot reach), and where it was.
  float previous_pdf = 0;
  bool previous_specular = false;
  bool previous_in_medium = false;
  glm::vec3 previous_normal(0.0f);

  for (;;) {
    // Find the next surface, then whether the medium scatters the path before it. The vertex
    // found is number `bounces`, and draws from that vertex's dimensions.
    sampler.startVertex(bounces);
    ++out.rays;
    const Hit hit = first_hit ? *first_hit : embree_.intersect(origin, direction);
    first_hit = nullptr;
    const float t_surface = hit.valid() ? hit.t : kInfinity;
    const float t_medium =
        medium_ ? medium_->sampleCollision(
                      origin, direction, t_surface,
                      {sampler.get1D(VertexDimension::kFreeFlight), sampler.independent()})
                : kInfinity;

    ScatteringVertex vertex;
    std::optional<Bsdf> bsdf;
    PathEvent event = PathEvent::kMedium;
    if (t_medium < t_surface) {
      // A real collision in the medium: the albedo is the scattering share of it.
      vertex.point = origin + t_medium * direction;
      vertex.direction = direction;
      vertex.g = scene_.medium.g;
      throughput *= scene_.medium.albedo;
    } else if (!hit.valid()) {
      // The path leaves the scene: the sky. Without the environment's occlusion, next-event
      // estimation carried all of it at the vertex that sampled this direction, unless that
      // vertex was specular (or the camera), which next-event estimation cannot serve.
      if (!environment_occlusion_ && bounces > 0 && !previous_specular) break;
      if (has_sky_) {
        const float weight =
            bounces == 0 || previous_specular
                ? 1.0f
                : powerHeuristic(previous_pdf,
                                 skySamplingPdf(previous_in_medium, previous_normal, direction));
        record(state, bounces, throughput * scene_.sky_radiance * weight);
      }
      if (environment_) {
        const float weight = bounces == 0 || previous_specular
                                 ? 1.0f
                                 : powerHeuristic(previous_pdf, environment_->pdf(direction));
        record(state, bounces, throughput * scene_.environment.radiance(direction) * weight);
      }
      break;
    } else {
      const std::uint32_t tri_index = triangles_.globalIndex(hit.mesh, hit.triangle);
      const TriangleRecord& tri = triangles_[tri_index];
      const scene::Material& material = scene_.materials[tri.material];
      const glm::vec3 wo = -direction;

      // Emission reached by the camera ray or by sampling (one-sided: front faces only). A path
      // the light tracer carries (its vertex next to the light specular, the eye's diffuse) is
      // left to it.
      const float cos_emitter = glm::dot(tri.normal, wo);
      if (material.isEmissive() && cos_emitter > 0 &&
          !(light_paths_ && previous_specular && eye_vertex_diffuse)) {
        float weight = 1.0f;
        if (bounces > 0 && !previous_specular) {
          const float pdf_light = area_lights_.pdfArea(tri_index) * hit.t * hit.t / cos_emitter;
          weight = powerHeuristic(previous_pdf, pdf_light);
        }
        record(state, bounces, throughput * material.emission * weight);
      }
      vertex.point = origin + hit.t * direction;
      const TriangleTable::OrientedNormals normals =
          triangles_.orientedNormals(tri, vertex.point, wo);
      throughput *= glassTransmittance(material, normals.front, hit.t);
      vertex.normal = normals.geometric;
      vertex.shading_normal = normals.shading;
      vertex.epsilon = embree_.rayEpsilon();
      bsdf.emplace(material, vertex.normal, vertex.shading_normal, wo, normals.front);
      if (bsdf->isBlack()) break;
      vertex.bsdf = &*bsdf;
      event = bsdf->isSpecular() ? PathEvent::kSpecular : PathEvent::kDiffuse;
    }

    // Scatter: this vertex is bounce number `bounces`. A state from which the class cannot be
    // reached any more ends the path.
    state = expression_.eyeStep(state, event);
    if (state == PathExpression::kDead) break;
    if (bounces == 0) eye_vertex_diffuse = event == PathEvent::kDiffuse;
    ++bounces;
    const bool specular = event == PathEvent::kSpecular;
    if (!specular && expression_.eyeAcceptsLight(state))
      record(state, bounces, throughput * estimateDirect(vertex, sampler, out.rays));

    // Continue the path by sampling the BSDF or the phase function.
    glm::vec3 wi;
    float pdf;
    if (vertex.inMedium()) {
      wi = sampleHenyeyGreenstein(direction, vertex.g, sampler.get2D(VertexDimension::kDirection));
      pdf = vertex.pdf(wi);
      // The phase function is its own density: the weight f/pdf is exactly 1.
    } else {
      const BsdfSample s = bsdf->sample(sampler.get2D(VertexDimension::kDirection));
      if (maxComponent(s.weight) <= 0) break;
      wi = s.wi;
      pdf = s.pdf;
      throughput *= s.weight;
      // A refracted path leaves from the other side of the surface.
      if (s.refracted) vertex.normal = -vertex.normal;
    }

    // Russian roulette: survive with probability q and divide by q, which keeps the estimator
    // unbiased. q follows the throughput, so weights never grow: a fixed cap below one (0.95,
    // say) would let the weights of long paths in a lossless medium grow as 0.95^−k, a heavy tail
    // that hides energy in rare paths at any practical sample count. q = √throughput rather than
    // the throughput itself ends paths later (survivors' weights fall as √throughput): 5–11%
    // more efficient on every built-in scene (docs/rendering.md, "Rendering ground truth": its
    // Russian roulette).
    if (bounces >= kRouletteStartBounce) {
      const float q = std::min(1.0f, std::sqrt(maxComponent(throughput)));
      if (q < 1.0f) {
        if (sampler.get1D(VertexDimension::kRoulette) >= q) break;
        throughput /= q;
      }
    }
    // Only a closed, lossless scene keeps a path going forever; end it there.
    if (bounces >= kMaxBounceGuard) break;
    origin = vertex.spawnOrigin();
    direction = wi;
    previous_pdf = pdf;
    previous_specular = specular;
    previous_in_medium = vertex.inMedium();
    previous_normal = vertex.normal;
  }
  return out;
}

}  // namespace gib::ref
