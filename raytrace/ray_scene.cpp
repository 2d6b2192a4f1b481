#include "raytrace/ray_scene.h"

#include "scene/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#if TWINRASTER_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace twr {

#if TWINRASTER_HAVE_EMBREE

bool rayTracerAvailable() { return true; }
std::string rayTracerDescription() { return std::string("Embree ") + RTC_VERSION_STRING; }

struct RayScene::Device {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  // Embree's geometry id -> the draw item's first global triangle id.
  std::vector<std::uint32_t> firstTriangleId;
  std::string lastError;  // Embree's last message (rememberError)
  ~Device() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

// Embree reports through a callback; the constructor turns the last one into an InputError.
void rememberError(void* user, RTCError, const char* message) {
  if (user && message) *static_cast<std::string*>(user) = message;
}

}  // namespace

RayScene::RayScene(const Scene& scene) : device_(std::make_unique<Device>()) {
  std::string& lastError = device_->lastError;
  device_->device = rtcNewDevice(nullptr);
  if (!device_->device) throw InputError("ray tracer: Embree could not create a device");
  rtcSetDeviceErrorFunction(device_->device, rememberError, &lastError);
  device_->scene = rtcNewScene(device_->device);
  // Rays from a surface graze its neighbours: the robust flag makes Embree's triangle test
  // watertight at shared edges, so a ray never slips between two triangles of one surface.
  rtcSetSceneFlags(device_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(device_->scene, RTC_BUILD_QUALITY_HIGH);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const DrawItem& item : flattenScene(scene)) {
    const Mesh& mesh = *item.mesh;
    const std::size_t count = mesh.triangleCount();
    if (count == 0) continue;
    const glm::dmat4 worldFromModel(item.worldFromModel);
    RTCGeometry geometry = rtcNewGeometry(device_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), 3 * count));
    auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                        RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), count));
    if (!vertices || !indices) {
      rtcReleaseGeometry(geometry);
      throw InputError("ray tracer: Embree could not allocate " + std::to_string(count) + " triangles: " + lastError);
    }
    // Three vertices of its own per triangle: the indices then never point outside the buffer,
    // whatever the mesh holds (the renderers refuse such meshes before anything is traced).
    for (std::size_t t = 0; t < count; ++t) {
      for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t index = mesh.indices[3 * t + k];
        const glm::dvec3 p = index < mesh.vertices.size() ? glm::dvec3(mesh.vertices[index].posModel) : glm::dvec3(0.0);
        const glm::dvec3 world(worldFromModel * glm::dvec4(p, 1.0));
        for (int c = 0; c < 3; ++c) vertices[9 * t + 3 * k + static_cast<std::size_t>(c)] = static_cast<float>(world[c]);
        if (std::isfinite(world.x) && std::isfinite(world.y) && std::isfinite(world.z)) {
          lo = glm::min(lo, world);
          hi = glm::max(hi, world);
        }
        indices[3 * t + k] = static_cast<std::uint32_t>(3 * t + k);
      }
    }
    rtcCommitGeometry(geometry);
    const unsigned id = rtcAttachGeometry(device_->scene, geometry);
    rtcReleaseGeometry(geometry);
    if (device_->firstTriangleId.size() <= id) device_->firstTriangleId.resize(id + 1, 0);
    device_->firstTriangleId[id] = item.firstTriangleId;
    triangles_ += count;
  }
  rtcCommitScene(device_->scene);
  if (rtcGetDeviceError(device_->device) != RTC_ERROR_NONE || !lastError.empty()) {
    throw InputError("ray tracer: Embree could not build the scene: " + lastError);
  }
  extent_ = triangles_ && lo.x <= hi.x ? glm::length(hi - lo) : 0.0;
}

RayScene::~RayScene() = default;

RayHit RayScene::intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tMin, double tMax) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit r{};
  r.ray.org_x = static_cast<float>(origin.x);
  r.ray.org_y = static_cast<float>(origin.y);
  r.ray.org_z = static_cast<float>(origin.z);
  r.ray.dir_x = static_cast<float>(dir.x);
  r.ray.dir_y = static_cast<float>(dir.y);
  r.ray.dir_z = static_cast<float>(dir.z);
  r.ray.tnear = static_cast<float>(tMin);
  r.ray.tfar = static_cast<float>(std::min(tMax, static_cast<double>(std::numeric_limits<float>::max())));
  r.ray.mask = 0xFFFFFFFFu;
  r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(device_->scene, &context, &r);
  RayHit hit;
  if (r.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.hit = true;
  hit.triangleId = device_->firstTriangleId[r.hit.geomID] + r.hit.primID;
  hit.t = r.ray.tfar;
  hit.u = r.hit.u;
  hit.v = r.hit.v;
  return hit;
}

#else  // built without Embree: the interface stays, tracing says what is missing

bool rayTracerAvailable() { return false; }
std::string rayTracerDescription() {
  return "this build has no ray tracer: Intel Embree 3 was not found when it was configured (Debian: apt install "
         "libembree-dev, then configure and build again)";
}

struct RayScene::Device {};

RayScene::RayScene(const Scene&) { throw InputError(rayTracerDescription()); }
RayScene::~RayScene() = default;
RayHit RayScene::intersect(const glm::dvec3&, const glm::dvec3&, double, double) const { return {}; }

#endif

}  // namespace twr
