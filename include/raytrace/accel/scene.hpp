// The renderable scene at one precision: objects, lights and the two ray queries every ray kind uses.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "raytrace/accel/bvh.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/scene/arithmetic.hpp"
#include "raytrace/scene/description.hpp"
#include "raytrace/scene/area_light.hpp"
#include "raytrace/scene/light_shape.hpp"

namespace rt {

// A light as shading reads it. A light whose strength varies over the scene (a spotlight, or one that fades
// with distance) has `shape`; the others, every course light among them, skip that work.
template <class T> struct Light {
  Vec3<T> position;
  Color color;
  const LightShape* shape = nullptr;
  bool shadowless = false;  // casts no shadows: no shadow ray is traced toward it
  bool mediaInteraction = true;  // lights scattering media (POV-Ray's media_interaction)
  bool mediaAttenuation = false;  // dimmed by the scene's fogs and media on its way (POV-Ray's media_attenuation)
  // An area light, a parallel one or one the scene's media dim (`sampled`) is lit by the tracer one hit at a
  // time, not in packets.
  bool sampled = false;
  const AreaLight* area = nullptr;
  std::optional<Vec3<T>> parallel;  // a parallel light's unit direction toward the light
};

// Which objects a ray sees (POV-Ray's no_image, no_reflection and no_radiosity, §3.4.5.5 "No_Image,
// No_Reflection"): an image ray (the eye's, or one refracted from it) does not see no_image objects, a ray
// reflected on its way does not see no_reflection ones, a gathered ray (-gi) no no_radiosity ones, a shadow ray
// followed through transparent surfaces no no_shadow ones.
enum class Sight { All, Image, Reflected, Gathered, Shadow };

template <class T> class Scene {
 public:
  using Real = T;
  // `arithmetic` must be resolved (no Auto) and match T; see chooseArithmetic(). `threads` build the hierarchy;
  // the scene is the same for any number.
  Scene(const SceneDesc& desc, const Arithmetic& arithmetic, Hierarchy hierarchy = Hierarchy::Auto, int threads = 1);

  // The closest hit strictly inside `range` over all objects. Equal t resolve to the object that comes first
  // in the file, so results never depend on traversal order (docs/reference/stability.md F13).
  std::optional<Hit<T>> closestHit(const Ray<T>& ray, Interval<T> range, Sight sight = Sight::All) const;
  // Whether anything at all lies strictly inside `range`: the any-hit query of shadow rays. `lastOccluder`, when
  // given, is the object that occluded the previous shadow ray toward the same light, tested first
  // (neighbouring shadow rays are mostly occluded by the same object: the shadow cache of Haines & Greenberg,
  // "The Light Buffer", 1986), and receives the occluder of this one. The answer is the same with or without it.
  bool occluded(const Ray<T>& ray, Interval<T> range, const Object<T>** lastOccluder = nullptr) const;

  // The same two queries for a packet of n ≤ Bvh<T>::kPacket coherent rays (bvh.hpp), each answered exactly as
  // the one-ray query answers it: hits[i] = closestHit(rays[i], range); shadowed[i] = occluded(rays[i],
  // ranges[i], lastOccluder).
  void closestHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* hits,
                   Sight sight = Sight::All) const;
  void occluded(const Ray<T>* rays, const Interval<T>* ranges, int n, bool* shadowed,
                const Object<T>** lastOccluder) const;

  const SceneDesc& desc() const { return desc_; }
  const Arithmetic& arithmetic() const { return arithmetic_; }
  const std::vector<Light<T>>& lights() const { return lights_; }
  // projected_through (POV-Ray 3.7 manual, "Projected_Through"): whether light l has an object, and the part of
  // a shadow ray's `segment` toward it that may shadow the point, or nothing where the light cannot reach it: a
  // ray that misses the object brings no light, and only what lies before the object casts a shadow. Such a
  // light is sampled.
  bool projected(size_t l) const { return l < through_.size() && through_[l]; }
  std::optional<Interval<T>> reaching(size_t l, const Ray<T>& ray, Interval<T> segment) const {
    if (!projected(l)) return segment;
    const std::optional<Hit<T>> met = through_[l]->intersect(ray, segment);
    if (!met) return std::nullopt;
    return Interval<T>{segment.min, met->t};
  }
  const std::vector<std::unique_ptr<Object<T>>>& objects() const { return objects_; }
  // The hierarchy over the bounded objects, or nothing when every object is tested in turn.
  const std::optional<Bvh<T>>& hierarchy() const { return hierarchy_; }

 private:
  // The point a hit reports: the shape's own, re-projected onto the surface, except in the course tier, which
  // takes o + t·d as its reference does (scene/arithmetic.hpp).
  Vec3<T> hitPoint(const Ray<T>& ray, const Hit<T>& hit) const;

  const SceneDesc& desc_;
  Arithmetic arithmetic_;
  std::vector<Light<T>> lights_;
  std::vector<LightShape> shapes_;  // lights_[i].shape points into it
  std::vector<AreaLight> areas_;    // and lights_[i].area into this
  std::vector<std::unique_ptr<Object<T>>> through_;  // by light, as SceneDesc::projectedThrough
  std::vector<std::unique_ptr<Object<T>>> objects_;
  std::vector<const Object<T>*> scanned_;  // tested one by one in file order: planes, or all without hierarchy
  std::optional<Bvh<T>> hierarchy_;
  // A part of the objects, in turn and in a hierarchy as the whole is.
  struct Subset {
    std::vector<const Object<T>*> scanned;
    std::optional<Bvh<T>> hierarchy;
  };
  // The objects that cast shadows, when some do not (POV-Ray's no_shadow): shadow rays ask these alone.
  std::optional<Subset> casters_;
  // The objects image, reflected and gathered rays see, when some are hidden from them (Sight).
  std::optional<Subset> imaged_, reflected_, gathered_;
  // The subset a ray of that sight asks, or null for all the objects.
  const Subset* seen(Sight sight) const {
    const std::optional<Subset>& part =
        sight == Sight::Image       ? imaged_
        : sight == Sight::Reflected ? reflected_
        : sight == Sight::Gathered  ? gathered_
                                    : casters_;
    return sight != Sight::All && part ? &*part : nullptr;
  }
};

}  // namespace rt
