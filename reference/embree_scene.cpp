#include "reference/embree_scene.h"

#include <embree3/rtcore.h>

#include <fmt/format.h>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace gib::ref {

namespace {

void onEmbreeError(void*, RTCError code, const char* message) {
  // Embree calls this from the failing API call; throwing through C code is undefined, so we
  // record nothing here and let the caller's check below report it. Print for diagnosis.
  fmt::print(stderr, "embree error {}: {}\n", int(code), message ? message : "");
}

void check(RTCDevice device, const char* what) {
  RTCError code = rtcGetDeviceError(device);
  if (code != RTC_ERROR_NONE)
    throw std::runtime_error(fmt::format("Embree failed in {} (error {})", what, int(code)));
}

}  // namespace

struct EmbreeScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  // What the device holds (its memory monitor's running sum; Embree calls it from its build
  // threads, hence atomic).
  std::atomic<std::int64_t> bytes{0};
};

namespace {

bool countEmbreeBytes(void* user, ssize_t bytes, bool) {
  static_cast<std::atomic<std::int64_t>*>(user)->fetch_add(std::int64_t(bytes));
  return true;  // never refuse an allocation
}

}  // namespace

EmbreeScene::EmbreeScene(const scene::Scene& scene) : impl_(std::make_unique<Impl>()) {
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw std::runtime_error("cannot create an Embree device");
  rtcSetDeviceErrorFunction(impl_->device, onEmbreeError, nullptr);
  rtcSetDeviceMemoryMonitorFunction(impl_->device, countEmbreeBytes, &impl_->bytes);
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);

  float extent = 0;
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const scene::Mesh& mesh = scene.meshes[m];
    RTCGeometry geometry = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree reads vertices with 16-byte loads: rtcSetNewGeometryBuffer pads the buffer for us.
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
        std::max<std::size_t>(mesh.positions.size(), 1)));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        vertices[3 * i + k] = mesh.positions[i][k];
        extent = std::max(extent, std::abs(mesh.positions[i][k]));
      }
    }
    auto* indices = static_cast<std::uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), mesh.triangles.size()));
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) indices[3 * i + k] = mesh.triangles[i][k];
    rtcCommitGeometry(geometry);
    // Geometry ids are assigned in order, so a hit's geomID is the mesh index.
    rtcAttachGeometryByID(impl_->scene, geometry, m);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(impl_->scene);
  check(impl_->device, "building the scene");
  // Hit points carry an error of a few ulps of their largest coordinate; 1e-5 of the extent is
  // ~100 ulps, far above that and far below any feature of our scenes.
  ray_epsilon_ = std::max(1e-5f * extent, 1e-6f);
}

std::size_t EmbreeScene::bytes() const {
  return std::size_t(std::max<std::int64_t>(0, impl_->bytes.load()));
}

EmbreeScene::~EmbreeScene() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

Hit EmbreeScene::intersect(const glm::vec3& origin, const glm::vec3& direction, float t_near,
                           float t_far) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray.org_x = origin.x;
  rh.ray.org_y = origin.y;
  rh.ray.org_z = origin.z;
  rh.ray.dir_x = direction.x;
  rh.ray.dir_y = direction.y;
  rh.ray.dir_z = direction.z;
  rh.ray.tnear = t_near;
  rh.ray.tfar = t_far;
  rh.ray.mask = 0xffffffffu;
  rh.ray.time = 0.0f;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &context, &rh);
  Hit hit;
  if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
    hit.t = rh.ray.tfar;
    hit.mesh = rh.hit.geomID;
    hit.triangle = rh.hit.primID;
  }
  return hit;
}

bool EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3& direction, float t_near,
                           float t_far) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray;
  ray.org_x = origin.x;
  ray.org_y = origin.y;
  ray.org_z = origin.z;
  ray.dir_x = direction.x;
  ray.dir_y = direction.y;
  ray.dir_z = direction.z;
  ray.tnear = t_near;
  ray.tfar = t_far;
  ray.mask = 0xffffffffu;
  ray.time = 0.0f;
  ray.flags = 0;
  rtcOccluded1(impl_->scene, &context, &ray);
  // Embree marks an occluded ray by setting tfar to −inf.
  return ray.tfar < 0.0f;
}

namespace {

RTCRay embreeRay(const scene::Ray& r) {
  RTCRay ray;
  ray.org_x = r.origin.x;
  ray.org_y = r.origin.y;
  ray.org_z = r.origin.z;
  ray.dir_x = r.direction.x;
  ray.dir_y = r.direction.y;
  ray.dir_z = r.direction.z;
  ray.tnear = r.t_near;
  ray.tfar = r.t_far;
  ray.mask = 0xffffffffu;
  ray.time = 0.0f;
  ray.flags = 0;
  return ray;
}

// The streams' arrays, reused by each thread from call to call.
thread_local std::vector<RTCRayHit> ray_hits;
thread_local std::vector<RTCRay> shadow_rays;

}  // namespace

void EmbreeScene::intersect(std::span<const scene::Ray> rays, std::span<Hit> hits,
                            bool coherent) const {
  if (hits.size() != rays.size()) throw std::invalid_argument("one hit per ray");
  ray_hits.resize(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    ray_hits[i].ray = embreeRay(rays[i]);
    ray_hits[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
    ray_hits[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags =
      coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  rtcIntersect1M(impl_->scene, &context, ray_hits.data(), unsigned(rays.size()), sizeof(RTCRayHit));
  for (std::size_t i = 0; i < rays.size(); ++i) {
    hits[i] = Hit{};
    if (ray_hits[i].hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
    hits[i].t = ray_hits[i].ray.tfar;
    hits[i].mesh = ray_hits[i].hit.geomID;
    hits[i].triangle = ray_hits[i].hit.primID;
  }
}

void EmbreeScene::occluded(std::span<const scene::Ray> rays,
                           std::span<std::uint8_t> blocked) const {
  if (blocked.size() != rays.size()) throw std::invalid_argument("one answer per ray");
  shadow_rays.resize(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) shadow_rays[i] = embreeRay(rays[i]);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  rtcOccluded1M(impl_->scene, &context, shadow_rays.data(), unsigned(rays.size()), sizeof(RTCRay));
  // Embree marks an occluded ray by setting tfar to −inf.
  for (std::size_t i = 0; i < rays.size(); ++i) blocked[i] = shadow_rays[i].tfar < 0.0f ? 1 : 0;
}

std::string embreeVersion() {
  return fmt::format("{}.{}.{}", RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH);
}

namespace {

class EmbreeRayCaster final : public scene::RayCaster {
 public:
  explicit EmbreeRayCaster(std::shared_ptr<const EmbreeScene> embree)
      : embree_(std::move(embree)) {}
  scene::RayHit intersect(const glm::vec3& origin, const glm::vec3& direction,
                          float t_near) const override {
    return embree_->intersect(origin, direction, t_near);
  }
  void intersect(std::span<const scene::Ray> rays, std::span<scene::RayHit> hits,
                 bool coherent) const override {
    embree_->intersect(rays, hits, coherent);
  }
  void occluded(std::span<const scene::Ray> rays, std::span<std::uint8_t> blocked) const override {
    embree_->occluded(rays, blocked);
  }
  float rayEpsilon() const override { return embree_->rayEpsilon(); }

 private:
  std::shared_ptr<const EmbreeScene> embree_;
};

}  // namespace

std::unique_ptr<scene::RayCaster> embreeRayCaster(std::shared_ptr<const EmbreeScene> embree) {
  return std::make_unique<EmbreeRayCaster>(std::move(embree));
}

scene::RayCasterFactory embreeRayCasterFactory() {
  return [](const scene::Scene& scene) -> std::unique_ptr<scene::RayCaster> {
    return embreeRayCaster(std::make_shared<const EmbreeScene>(scene));
  };
}

}  // namespace gib::ref
