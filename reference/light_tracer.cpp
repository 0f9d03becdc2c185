#include "reference/light_tracer.h"

#include "reference/sampling.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gib::ref {

namespace {

using scene::PathEvent;
using scene::PathExpression;

float maxComponent(const Rgb& c) {
  return std::max(c.r, std::max(c.g, c.b));
}

// A direction in the spot's cone with density ∝ cosᵏθ: invert the cumulative
// (1 − μ^(k+1))/(1 − μ_edge^(k+1)).
glm::vec3 sampleSpotDirection(const scene::SpotLight& spot, glm::vec2 u) {
  const float k = spot.falloff_exponent;
  const float edge_power = std::pow(scene::spotEdgeCosine(spot), k + 1.0f);
  const float cos_theta =
      std::clamp(std::pow(1.0f - u.x * (1.0f - edge_power), 1.0f / (k + 1.0f)), -1.0f, 1.0f);
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float phi = 2.0f * kPi * u.y;
  return Frame(glm::normalize(spot.direction))
      .toWorld({sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta});
}

}  // namespace

bool LightTracer::applies(const scene::Scene& scene) {
  return scene.hasIdealSpecular() && scene.medium.empty();
}

LightTracer::LightTracer(const scene::Scene& scene, const PathTracer& tracer, int width, int height)
    : scene_(scene),
      tracer_(tracer),
      width_(width),
      height_(height),
      camera_(scene::makeCameraFrame(scene.camera, width, height)) {
  pixel_area_ = (2.0f * camera_.tan_half_fov_y * camera_.aspect / float(width)) *
                (2.0f * camera_.tan_half_fov_y / float(height));
  // A bounding sphere of the geometry, for the particles of directional lights.
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const scene::Mesh& mesh : scene.meshes)
    for (const glm::vec3& p : mesh.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  if (lo.x <= hi.x) {
    scene_centre_ = 0.5f * (lo + hi);
    scene_radius_ = 0.5f * glm::length(hi - lo) * 1.01f;
  }
  // Light powers Φ: π·Le·A for a one-sided Lambertian emitter, I·∫cosᵏθ dω for a spot, E·πR²
  // for a directional light through the bounding sphere's disc.
  const TriangleTable& triangles = tracer.triangles();
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const scene::Material& m = scene.materials[triangles[t].material];
    if (m.isEmissive()) area_power_ += kPi * m.emission * triangles[t].area;
  }
  auto add = [&](const Rgb& power) {
    total_power_ += scene::luminance(power);
    light_cdf_.push_back(total_power_);
  };
  add(area_power_);
  for (const scene::SpotLight& spot : scene.spot_lights)
    add(spot.intensity * scene::spotSolidAngleIntegral(spot));
  for (const scene::DirectionalLight& sun : scene.directional_lights)
    add(sun.irradiance * (kPi * scene_radius_ * scene_radius_));
}

bool LightTracer::emit(PathSampler& sampler, Emission& e) const {
  if (!(total_power_ > 0)) return false;
  sampler.startVertex(0);
  glm::vec2 u = sampler.get2D(VertexDimension::kLightPoint);
  const float pick = u.x * total_power_;
  const std::size_t light = std::min<std::size_t>(
      std::upper_bound(light_cdf_.begin(), light_cdf_.end(), pick) - light_cdf_.begin(),
      light_cdf_.size() - 1);
  const float low = light == 0 ? 0.0f : light_cdf_[light - 1];
  const float share = (light_cdf_[light] - low) / total_power_;
  if (!(share > 0)) return false;
  u.x = reuseAfterChoice(u.x, low / total_power_, 1.0f / share);
  const glm::vec2 v = sampler.get2D(VertexDimension::kSkyDirection);

  if (light == 0) {
    // An area light: a point by power (the next-event sampler), a cosine-distributed direction.
    const AreaLightSample s = tracer_.areaLights().sample(u);
    const TriangleRecord& tri = tracer_.triangles()[s.triangle];
    e.origin = s.point;
    e.normal = tri.normal;
    e.direction = Frame(tri.normal).toWorld(sampleCosineHemisphere(v));
    // Le·cos θ / (pdf_area · cos θ/π) = π·Le / pdf_area.
    e.flux = scene_.materials[tri.material].emission * (kPi / (s.pdf_area * share));
    return s.pdf_area > 0;
  }
  const std::size_t spots = scene_.spot_lights.size();
  if (light - 1 < spots) {
    const scene::SpotLight& spot = scene_.spot_lights[light - 1];
    e.origin = spot.position;
    e.normal = glm::vec3(0.0f);
    e.direction = sampleSpotDirection(spot, u);
    // Density ∝ I(θ): every particle carries the spot's power.
    e.flux = spot.intensity * (scene::spotSolidAngleIntegral(spot) / share);
    return true;
  }
  const scene::DirectionalLight& sun = scene_.directional_lights[light - 1 - spots];
  const glm::vec3 d = glm::normalize(sun.direction);
  const Frame frame(d);
  const float r = scene_radius_ * std::sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  e.origin = scene_centre_ - 2.0f * scene_radius_ * d +
             r * (std::cos(phi) * frame.s + std::sin(phi) * frame.t);
  e.normal = glm::vec3(0.0f);
  e.direction = d;
  e.flux = sun.irradiance * (kPi * scene_radius_ * scene_radius_ / share);
  return true;
}

void LightTracer::connectToCamera(const glm::vec3& point, const glm::vec3& normal, const Bsdf& bsdf,
                                  const Rgb& flux, std::uint32_t& rays,
                                  std::vector<LightSplat>& splats) const {
  const glm::vec3 to_camera = camera_.origin - point;
  const float dist2 = glm::dot(to_camera, to_camera);
  if (!(dist2 > 0)) return;
  const float dist = std::sqrt(dist2);
  const glm::vec3 w = to_camera / dist;
  // Where the point lands on the image plane at distance 1 in front of the eye.
  const float cos_camera = -glm::dot(w, camera_.forward);
  if (cos_camera <= 0) return;
  const glm::vec3 on_plane = -w / cos_camera;
  const float px =
      (glm::dot(on_plane, camera_.right) / (camera_.tan_half_fov_y * camera_.aspect) + 1.0f) *
      0.5f * float(width_);
  const float py =
      (1.0f - glm::dot(on_plane, camera_.up) / camera_.tan_half_fov_y) * 0.5f * float(height_);
  if (!(px >= 0 && px < float(width_) && py >= 0 && py < float(height_))) return;
  const Rgb f = bsdf.evaluateProjected(w, Transport::kImportance);
  if (maxComponent(f) <= 0) return;
  const float eps = tracer_.embree().rayEpsilon();
  ++rays;
  if (tracer_.embree().occluded(point + eps * normal, w, 0.0f, dist - 2.0f * eps)) return;
  // The pixel's box-filtered radiance is (1/A)∫ L dω / cos³θ over its image-plane area A, and
  // dω = cos θx dA/r² at the point: the particle's flux times f·cos over A·cos³θ·r². Dividing by
  // the pixel count makes one path per pixel and sample an estimate of the pixel means.
  const float scale = 1.0f / (pixel_area_ * cos_camera * cos_camera * cos_camera * dist2 *
                              float(width_) * float(height_));
  const std::uint32_t x = std::min(std::uint32_t(px), std::uint32_t(width_ - 1));
  const std::uint32_t y = std::min(std::uint32_t(py), std::uint32_t(height_ - 1));
  splats.push_back({y * std::uint32_t(width_) + x, flux * f * scale});
}

std::uint32_t LightTracer::trace(PathSampler& sampler, std::vector<LightSplat>& splats) const {
  std::uint32_t connections = 0;
  const std::uint32_t rays = walk(sampler, [&](const Landing& landing) {
    connectToCamera(landing.point, landing.normal, *landing.bsdf, landing.flux, connections,
                    splats);
  });
  return rays + connections;
}

std::uint32_t LightTracer::walk(PathSampler& sampler, const LandingVisitor& visit) const {
  std::uint32_t rays = 0;
  Emission e;
  if (!emit(sampler, e)) return rays;
  const PathExpression& expression = tracer_.pathExpression();
  const EmbreeScene& embree = tracer_.embree();
  const TriangleTable& triangles = tracer_.triangles();
  const float eps = embree.rayEpsilon();
  const float initial = maxComponent(e.flux);

  glm::vec3 origin = e.origin + eps * e.normal;
  glm::vec3 direction = e.direction;
  Rgb flux = e.flux;
  int state = expression.lightStart();
  for (int vertex = 1; vertex < PathTracer::kMaxBounceGuard; ++vertex) {
    sampler.startVertex(vertex);
    ++rays;
    const Hit hit = embree.intersect(origin, direction);
    if (!hit.valid()) break;
    const TriangleRecord& tri = triangles[triangles.globalIndex(hit.mesh, hit.triangle)];
    const scene::Material& material = scene_.materials[tri.material];
    const glm::vec3 wo = -direction;
    const glm::vec3 point = origin + hit.t * direction;
    const TriangleTable::OrientedNormals normals = triangles.orientedNormals(tri, point, wo);
    flux *= glassTransmittance(material, normals.front, hit.t);
    glm::vec3 normal = normals.geometric;
    const Bsdf bsdf(material, normal, normals.shading, wo, normals.front);
    const PathEvent event = bsdf.isSpecular() ? PathEvent::kSpecular : PathEvent::kDiffuse;
    // A path whose first vertex is diffuse is the path tracer's, whatever follows.
    if (vertex == 1 && event == PathEvent::kDiffuse) break;
    state = expression.lightStep(state, event);
    if (state == PathExpression::kDead) break;
    if (event == PathEvent::kDiffuse && expression.lightAcceptsEye(state))
      visit({point, normal, &bsdf, flux, vertex});
    if (bsdf.isBlack()) break;

    const BsdfSample s =
        bsdf.sample(sampler.get2D(VertexDimension::kDirection), Transport::kImportance);
    if (maxComponent(s.weight) <= 0) break;
    flux *= s.weight;
    if (s.refracted) normal = -normal;
    // Russian roulette on the flux relative to the light's, as the path tracer's on throughput.
    if (vertex >= PathTracer::kRouletteStartBounce) {
      const float q = std::min(1.0f, std::sqrt(maxComponent(flux) / initial));
      if (q < 1.0f) {
        if (sampler.get1D(VertexDimension::kRoulette) >= q) break;
        flux /= q;
      }
    }
    origin = point + eps * normal;
    direction = s.wi;
  }
  return rays;
}

}  // namespace gib::ref
