// The same scene in Embree 3: spheres as its sphere primitive (RTC_GEOMETRY_TYPE_SPHERE_POINT), triangles as
// its triangles, and the unbounded objects (planes) tested by hand before Embree is asked, as our Scene tests
// them before its hierarchy. The answers are in our terms: the id of the object hit and its t.
#pragma once

#include <embree3/rtcore.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "raytrace/accel/scene.hpp"

namespace rt::bench {

// One ray's answer: the object hit (its 1-based id, 0 for none) and where; for any-hit queries only whether.
struct Answer {
  int object = 0;
  float t = 0;
};

template <class T> class EmbreeScene {
 public:
  static constexpr int kPacket = 16;

  // Builds Embree's hierarchy with `threads` threads; `high` asks for its best (and slowest) build. `config`:
  // more of rtcNewDevice's settings, comma-separated (such as hair_accel=bvh4obb.virtualcurve4v, the 4-wide
  // hierarchy for spheres where Embree would build an 8-wide one).
  EmbreeScene(const Scene<T>& scene, int threads, bool high, const std::string& config) {
    device_ = rtcNewDevice(("threads=" + std::to_string(threads) + (config.empty() ? "" : "," + config)).c_str());
    if (!device_) throw std::runtime_error("Embree: no device");
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, high ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM);
    const SceneDesc& desc = scene.desc();
    std::vector<float> spheres, vertices;
    for (size_t i = 0; i < desc.objects.size(); ++i) {
      const ObjectDesc& o = desc.objects[i];
      const int id = int(i) + 1;
      if (!scene.objects()[i]->bounds()) {
        unbounded_.push_back(scene.objects()[i].get());
      } else if (!o.transforms.empty()) {
        throw std::runtime_error("object " + std::to_string(id) + " is transformed: only plain spheres, "
                                 "triangles and planes are mapped to Embree");
      } else if (const auto* s = std::get_if<SphereDesc>(&o.shape)) {
        spheres.insert(spheres.end(), {float(s->center.x), float(s->center.y), float(s->center.z),
                                       float(s->radius)});
        sphereIds_.push_back(id);
      } else if (const auto* t = std::get_if<TriangleDesc>(&o.shape)) {
        for (const glm::dvec3& v : {t->a, t->b, t->c}) vertices.insert(vertices.end(), {float(v.x), float(v.y), float(v.z)});
        triangleIds_.push_back(id);
      } else {
        throw std::runtime_error("object " + std::to_string(id) +
                                 " is neither sphere, triangle nor plane: it has no Embree counterpart here");
      }
    }
    if (!sphereIds_.empty()) {
      RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                            4 * sizeof(float), sphereIds_.size()));
      std::copy(spheres.begin(), spheres.end(), v);
      sphereGeometry_ = attach(g);
    }
    if (!triangleIds_.empty()) {
      RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                            3 * sizeof(float), 3 * triangleIds_.size()));
      std::copy(vertices.begin(), vertices.end(), v);
      auto* index = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(uint32_t), triangleIds_.size()));
      for (uint32_t k = 0; k < 3 * triangleIds_.size(); ++k) index[k] = k;
      triangleGeometry_ = attach(g);
    }
    rtcCommitScene(scene_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw std::runtime_error("Embree: the build failed");
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  ~EmbreeScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }

  // Closest hits of rays [first, first + n), n ≤ kPacket, through rtcIntersect16 (packet) or rtcIntersect1.
  void closest(const Ray<T>* rays, const Interval<T>* ranges, int n, bool packet, Answer* out) const {
    Answer planes[kPacket];
    for (int i = 0; i < n; ++i) planes[i] = unboundedHit(rays[i], ranges[i]);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    if (!packet) {
      context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
      for (int i = 0; i < n; ++i) {
        RTCRayHit h;
        setRay(h.ray, rays[i], ranges[i], planes[i]);
        h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &h);
        out[i] = h.hit.geomID == RTC_INVALID_GEOMETRY_ID ? planes[i] : Answer{id(h.hit.geomID, h.hit.primID), h.ray.tfar};
      }
      return;
    }
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(64) RTCRayHit16 h;
    alignas(64) int valid[kPacket];
    for (int i = 0; i < kPacket; ++i) {
      valid[i] = i < n ? -1 : 0;
      RTCRay one{};
      if (i < n) setRay(one, rays[i], ranges[i], planes[i]);
      h.ray.org_x[i] = one.org_x, h.ray.org_y[i] = one.org_y, h.ray.org_z[i] = one.org_z;
      h.ray.dir_x[i] = one.dir_x, h.ray.dir_y[i] = one.dir_y, h.ray.dir_z[i] = one.dir_z;
      h.ray.tnear[i] = one.tnear, h.ray.tfar[i] = one.tfar;
      h.ray.time[i] = 0, h.ray.mask[i] = ~0u, h.ray.id[i] = 0, h.ray.flags[i] = 0;
      h.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect16(valid, scene_, &context, &h);
    for (int i = 0; i < n; ++i) {
      out[i] = h.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID ? planes[i]
                                                          : Answer{id(h.hit.geomID[i], h.hit.primID[i]), h.ray.tfar[i]};
    }
  }

  // Whether anything blocks rays [first, first + n) inside their ranges: rtcOccluded16 or rtcOccluded1.
  void occluded(const Ray<T>* rays, const Interval<T>* ranges, int n, bool packet, bool* blocked) const {
    for (int i = 0; i < n; ++i) {
      blocked[i] = false;
      for (const Object<T>* o : unbounded_) blocked[i] = blocked[i] || o->intersect(rays[i], ranges[i]);
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    if (!packet) {
      context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
      for (int i = 0; i < n; ++i) {
        if (blocked[i]) continue;
        RTCRay r;
        setRay(r, rays[i], ranges[i], {});
        rtcOccluded1(scene_, &context, &r);
        blocked[i] = r.tfar < 0;
      }
      return;
    }
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(64) RTCRay16 r;
    alignas(64) int valid[kPacket];
    for (int i = 0; i < kPacket; ++i) {
      valid[i] = i < n && !blocked[i] ? -1 : 0;
      RTCRay one{};
      if (i < n) setRay(one, rays[i], ranges[i], {});
      r.org_x[i] = one.org_x, r.org_y[i] = one.org_y, r.org_z[i] = one.org_z;
      r.dir_x[i] = one.dir_x, r.dir_y[i] = one.dir_y, r.dir_z[i] = one.dir_z;
      r.tnear[i] = one.tnear, r.tfar[i] = one.tfar;
      r.time[i] = 0, r.mask[i] = ~0u, r.id[i] = 0, r.flags[i] = 0;
    }
    rtcOccluded16(valid, scene_, &context, &r);
    for (int i = 0; i < n; ++i) blocked[i] = blocked[i] || (valid[i] && r.tfar[i] < 0);
  }

 private:
  unsigned attach(RTCGeometry g) {
    rtcCommitGeometry(g);
    const unsigned id = rtcAttachGeometry(scene_, g);
    rtcReleaseGeometry(g);
    return id;
  }
  int id(unsigned geometry, unsigned primitive) const {
    return geometry == sphereGeometry_ ? sphereIds_[primitive] : triangleIds_[primitive];
  }
  // The nearest unbounded object's hit; the ray's far end when there is none.
  Answer unboundedHit(const Ray<T>& ray, Interval<T> range) const {
    Answer a{0, float(range.max)};
    for (const Object<T>* o : unbounded_) {
      if (auto hit = o->intersect(ray, range)) a = {o->id(), float(hit->t)}, range.max = hit->t;
    }
    return a;
  }
  static void setRay(RTCRay& r, const Ray<T>& ray, Interval<T> range, Answer far) {
    r.org_x = float(ray.origin.x), r.org_y = float(ray.origin.y), r.org_z = float(ray.origin.z);
    r.dir_x = float(ray.dir.x), r.dir_y = float(ray.dir.y), r.dir_z = float(ray.dir.z);
    r.tnear = float(range.min);
    r.tfar = far.object ? far.t : float(range.max);
    r.time = 0, r.mask = ~0u, r.id = 0, r.flags = 0;
  }

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<const Object<T>*> unbounded_;
  std::vector<int> sphereIds_, triangleIds_;
  unsigned sphereGeometry_ = RTC_INVALID_GEOMETRY_ID, triangleGeometry_ = RTC_INVALID_GEOMETRY_ID;
};

}  // namespace rt::bench
