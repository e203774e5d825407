#include "raytrace/accel/scene.hpp"

#include <cmath>
#include <optional>
#include <type_traits>

#include "raytrace/shapes/box.hpp"
#include "raytrace/shapes/cone.hpp"
#include "raytrace/shapes/cylinder.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/shapes/plane.hpp"
#include "raytrace/shapes/sphere.hpp"
#include "raytrace/shapes/transformed.hpp"
#include "raytrace/shapes/triangle.hpp"

namespace rt {

namespace {

template <class T>
std::unique_ptr<Object<T>> makeObject(const ObjectDesc& desc, const Arithmetic& arithmetic, int id) {
  const Material& m = desc.material;
  return std::visit(
      [&](const auto& s) -> std::unique_ptr<Object<T>> {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, SphereDesc>) {
          return std::make_unique<Sphere<T>>(Vec3<T>(s.center), T(s.radius), arithmetic.sphere, m, id);
        } else if constexpr (std::is_same_v<S, PlaneDesc>) {
          return std::make_unique<Plane<T>>(Vec3<T>(glm::normalize(s.normal)), T(s.distance), m, id);
        } else if constexpr (std::is_same_v<S, TriangleDesc>) {
          return std::make_unique<Triangle<T>>(Vec3<T>(s.a), Vec3<T>(s.b), Vec3<T>(s.c), m, id);
        } else if constexpr (std::is_same_v<S, BoxDesc>) {
          return std::make_unique<Box<T>>(Vec3<T>(s.min), Vec3<T>(s.max), m, id);
        } else if constexpr (std::is_same_v<S, ConeDesc>) {
          return std::make_unique<Cone<T>>(Vec3<T>(s.base), T(s.baseRadius), Vec3<T>(s.cap), T(s.capRadius), m, id);
        } else {
          static_assert(std::is_same_v<S, CylinderDesc>, "every ShapeDesc kind must be built here");
          return std::make_unique<Cylinder<T>>(Vec3<T>(s.base), Vec3<T>(s.cap), T(s.radius), m, id);
        }
      },
      desc.shape);
}

// "Model no more than a scene needs": a sphere moved by a similarity (any mix of rotations, uniform scales and
// translations, as on the thousands of spheres of balls2 and gnarly) is still a sphere, centred at M·c with
// radius s·r. Folding the matrix into it saves the two matrix products per test and keeps its bounds tight.
// The similarity test is LᵀL = s²·I for the linear part L, up to the rounding of the rotation matrices.
// Nothing when there is nothing to fold: not a sphere, or not moved, or not by a similarity.
std::optional<ObjectDesc> foldSimilarityIntoSphere(const ObjectDesc& desc) {
  const auto* sphere = std::get_if<SphereDesc>(&desc.shape);
  if (!sphere || desc.transforms.empty()) return std::nullopt;
  const glm::dmat4 worldFromObject = desc.worldFromObject();
  const glm::dmat3 linear(worldFromObject);
  const glm::dmat3 gram = glm::transpose(linear) * linear;
  const double s2 = gram[0][0];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (std::abs(gram[i][j] - (i == j ? s2 : 0.0)) > 1e-12 * s2) return std::nullopt;
    }
  }
  ObjectDesc folded = desc;
  folded.shape = SphereDesc{glm::dvec3(worldFromObject * glm::dvec4(sphere->center, 1.0)),
                            std::sqrt(s2) * sphere->radius};
  folded.transforms.clear();
  return folded;
}

}  // namespace

template <class T>
Scene<T>::Scene(const SceneDesc& desc, const Arithmetic& arithmetic, Hierarchy hierarchy, int threads)
    : desc_(desc), arithmetic_(arithmetic) {
  for (const LightDesc& l : desc.lights) lights_.push_back(Light<T>{Vec3<T>(l.position), l.color});
  // The course tier does what its reference does: every transformed object is intersected on the transformed
  // ray, with the matrix composed in T from the file's steps.
  const bool course = arithmetic.tier == Tier::Course;
  const size_t n = desc.objects.size();
  objects_.resize(n);
  // Unbounded objects (planes, or boxes overflowing T) have no box to put in a hierarchy; they are always
  // tested in turn.
  std::vector<char> finite(n);  // not vector<bool>, whose neighbouring entries share words the threads write
  parallelForChunks(n, kObjectChunk, threads, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const int id = int(i) + 1;
      const std::optional<ObjectDesc> folded = course ? std::nullopt : foldSimilarityIntoSphere(desc.objects[i]);
      const ObjectDesc& o = folded ? *folded : desc.objects[i];
      auto object = makeObject<T>(o, arithmetic, id);
      const Mat4<T> m = course ? composeTransforms<T>(o.transforms) : Mat4<T>(o.worldFromObject());
      // An identity transform (`translate <0,0,0>`) costs nothing: the shape is used as it is.
      if (m != Mat4<T>(T(1))) {
        object = std::make_unique<Transformed<T>>(std::move(object), m, o.material, id, course);
      }
      const auto box = object->bounds();
      const auto finite3 = [](const Vec3<T>& v) { return !glm::any(glm::isinf(v)) && !glm::any(glm::isnan(v)); };
      finite[i] = box && finite3(box->min) && finite3(box->max);
      objects_[i] = std::move(object);
    }
  });
  std::vector<const Object<T>*> bounded;
  for (size_t i = 0; i < n; ++i) (finite[i] ? bounded : scanned_).push_back(objects_[i].get());
  const bool build = hierarchy == Hierarchy::Always ||
                     (hierarchy == Hierarchy::Auto && bounded.size() >= kHierarchyMinObjects);
  if (build) {
    hierarchy_.emplace(bounded, threads);
  } else {
    scanned_.clear();
    for (const auto& o : objects_) scanned_.push_back(o.get());
  }
}

// One ray: the packet queries' steps below, straight to the hierarchy's one-ray queries, without the arrays
// of a packet (docs/performance.md).
template <class T>
std::optional<Hit<T>> Scene<T>::closestHit(const Ray<T>& ray, Interval<T> range) const {
  std::optional<Hit<T>> hit;
  for (const Object<T>* object : scanned_) object->closerHits(&ray, 1, range, &hit);
  if (hierarchy_) hierarchy_->closestHit(ray, range, hit);
  if (hit) hit->point = hitPoint(ray, *hit);
  return hit;
}

template <class T>
bool Scene<T>::occluded(const Ray<T>& ray, Interval<T> range, const Object<T>** lastOccluder) const {
  if (lastOccluder && *lastOccluder && (*lastOccluder)->occludes(&ray, &range, 1)) return true;
  const Object<T>* found = nullptr;
  for (auto object = scanned_.begin(); !found && object != scanned_.end(); ++object) {
    if ((*object)->occludes(&ray, &range, 1)) found = *object;
  }
  if (!found && hierarchy_) found = hierarchy_->occluder(ray, range);
  if (found && lastOccluder) *lastOccluder = found;
  return found != nullptr;
}

template <class T>
void Scene<T>::closestHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* hits) const {
  for (int i = 0; i < n; ++i) hits[i].reset();
  for (const Object<T>* object : scanned_) object->closerHits(rays, n, range, hits);
  if (hierarchy_) hierarchy_->closestHits(rays, n, range, hits);
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
  for (const Object<T>* object : scanned_) {
    if (!open) break;
    open &= ~object->noteOccluder(rays, ranges, open, occluders);
  }
  if (open && hierarchy_) hierarchy_->occluders(rays, ranges, open, occluders);
  for (int i = 0; i < n; ++i) {
    shadowed[i] = occluders[i] != nullptr;
    if (occluders[i]) *lastOccluder = occluders[i];
  }
}

template class Scene<float>;
template class Scene<double>;

}  // namespace rt
