#include "raytrace/accel/scene.hpp"

#include <optional>

#include "raytrace/util/parallel.hpp"
#include "raytrace/shapes/make_object.hpp"

namespace rt {

template <class T>
Scene<T>::Scene(const SceneDesc& desc, const Arithmetic& arithmetic, Hierarchy hierarchy, int threads)
    : desc_(desc), arithmetic_(arithmetic) {
  shapes_.reserve(desc.lights.size());  // no reallocation: lights_ point into them
  areas_.reserve(desc.lights.size());
  for (const LightDesc& l : desc.lights) {
    const LightShape* shape = LightShape::needed(l) ? &shapes_.emplace_back(l) : nullptr;
    Light<T>& light = lights_.emplace_back();
    light.position = Vec3<T>(l.position);
    light.color = l.color;
    light.shape = shape;
    light.shadowless = l.shadowless;
    light.mediaInteraction = l.mediaInteraction;
    light.mediaAttenuation = l.mediaAttenuation && (!desc.media.empty() || !desc.fogs.empty());
    if (l.area) light.area = &areas_.emplace_back(*l.area);
    if (l.parallelTo && glm::length(l.position - *l.parallelTo) > 0) {
      light.parallel = Vec3<T>(glm::normalize(l.position - *l.parallelTo));
    }
    const size_t index = lights_.size() - 1;
    if (index < desc.projectedThrough.size() && desc.projectedThrough[index]) {
      through_.resize(desc.projectedThrough.size());
      through_[index] = makeObject<T>(*desc.projectedThrough[index], arithmetic.sphere, 0, false);
    }
    light.sampled = light.area || light.parallel || projected(index) || light.mediaAttenuation;
  }
  const bool course = arithmetic.tier == Tier::Course;
  const size_t n = desc.objects.size();
  objects_.resize(n);
  // Unbounded objects (planes, or boxes overflowing T) have no box to put in a hierarchy; they are always
  // tested in turn.
  std::vector<char> finite(n);  // not vector<bool>, whose neighbouring entries share words the threads write
  parallelForChunks(n, kObjectChunk, threads, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      auto object = makeObject<T>(desc.objects[i], arithmetic.sphere, int(i) + 1, course);
      const auto box = object->bounds();
      const auto finite3 = [](const Vec3<T>& v) { return !glm::any(glm::isinf(v)) && !glm::any(glm::isnan(v)); };
      finite[i] = box && finite3(box->min) && finite3(box->max);
      objects_[i] = std::move(object);
    }
  });
  // The objects in turn or in a hierarchy, as `hierarchy` asks; `take` picks the objects of the set.
  const auto split = [&](const auto& take, std::vector<const Object<T>*>& scanned, std::optional<Bvh<T>>& bvh) {
    std::vector<const Object<T>*> bounded;
    for (size_t i = 0; i < n; ++i) {
      if (take(i)) (finite[i] ? bounded : scanned).push_back(objects_[i].get());
    }
    const bool build = hierarchy == Hierarchy::Always ||
                       (hierarchy == Hierarchy::Auto && bounded.size() >= kHierarchyMinObjects);
    if (build) {
      bvh.emplace(bounded, threads);
    } else {
      scanned.clear();
      for (size_t i = 0; i < n; ++i) {
        if (take(i)) scanned.push_back(objects_[i].get());
      }
    }
  };
  split([](size_t) { return true; }, scanned_, hierarchy_);
  // A subset of the objects, made when `take` leaves some out.
  const auto subset = [&](const auto& take, std::optional<Subset>& into) {
    bool all = true;
    for (size_t i = 0; i < n && all; ++i) all = take(i);
    if (!all) split(take, into.emplace().scanned, into->hierarchy);
  };
  subset([&](size_t i) { return !desc.objects[i].noShadow; }, casters_);
  subset([&](size_t i) { return !desc.objects[i].noImage; }, imaged_);
  subset([&](size_t i) { return !desc.objects[i].noReflection; }, reflected_);
  subset([&](size_t i) { return !desc.objects[i].noRadiosity; }, gathered_);
}

// One ray: the packet queries' steps below, straight to the hierarchy's one-ray queries, without the arrays
// of a packet (docs/performance.md).
template <class T>
std::optional<Hit<T>> Scene<T>::closestHit(const Ray<T>& ray, Interval<T> range, Sight sight) const {
  std::optional<Hit<T>> hit;
  const Subset* part = seen(sight);
  for (const Object<T>* object : part ? part->scanned : scanned_) object->closerHits(&ray, 1, range, &hit);
  if (const auto& hierarchy = part ? part->hierarchy : hierarchy_) hierarchy->closestHit(ray, range, hit);
  if (hit) hit->point = hitPoint(ray, *hit);
  return hit;
}

template <class T>
bool Scene<T>::occluded(const Ray<T>& ray, Interval<T> range, const Object<T>** lastOccluder) const {
  if (lastOccluder && *lastOccluder && (*lastOccluder)->occludes(&ray, &range, 1)) return true;
  const auto& scanned = casters_ ? casters_->scanned : scanned_;
  const auto& hierarchy = casters_ ? casters_->hierarchy : hierarchy_;
  const Object<T>* found = nullptr;
  for (auto object = scanned.begin(); !found && object != scanned.end(); ++object) {
    if ((*object)->occludes(&ray, &range, 1)) found = *object;
  }
  if (!found && hierarchy) found = hierarchy->occluder(ray, range);
  if (found && lastOccluder) *lastOccluder = found;
  return found != nullptr;
}

template <class T>
void Scene<T>::closestHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* hits,
                           Sight sight) const {
  for (int i = 0; i < n; ++i) hits[i].reset();
  const Subset* part = seen(sight);
  for (const Object<T>* object : part ? part->scanned : scanned_) object->closerHits(rays, n, range, hits);
  if (const auto& hierarchy = part ? part->hierarchy : hierarchy_) hierarchy->closestHits(rays, n, range, hits);
  for (int i = 0; i < n; ++i) {
    if (hits[i]) hits[i]->point = hitPoint(rays[i], *hits[i]);
  }
}

template <class T> Vec3<T> Scene<T>::hitPoint(const Ray<T>& ray, const Hit<T>& hit) const {
  return arithmetic_.tier == Tier::Course ? ray.at(hit.t) : hit.point;
}

template <class T>
void Scene<T>::occluded(const Ray<T>* rays, const Interval<T>* ranges, int n, bool* shadowed,
                        const Object<T>** lastOccluder) const {
  const Object<T>* occluders[Bvh<T>::kPacket] = {};
  uint32_t open = (uint32_t(1) << n) - 1;  // the rays that nothing occludes so far
  // The cached occluder first, then the unbounded objects in file order, then the hierarchy: each ray's
  // occluder is the first that meets it.
  if (*lastOccluder) open &= ~(*lastOccluder)->noteOccluder(rays, ranges, open, occluders);
  const auto& scanned = casters_ ? casters_->scanned : scanned_;
  const auto& hierarchy = casters_ ? casters_->hierarchy : hierarchy_;
  for (const Object<T>* object : scanned) {
    if (!open) break;
    open &= ~object->noteOccluder(rays, ranges, open, occluders);
  }
  if (open && hierarchy) hierarchy->occluders(rays, ranges, open, occluders);
  for (int i = 0; i < n; ++i) {
    shadowed[i] = occluders[i] != nullptr;
    if (occluders[i]) *lastOccluder = occluders[i];
  }
}

template class Scene<float>;
template class Scene<double>;

}  // namespace rt
