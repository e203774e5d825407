// What the hierarchy's traversals do in a leaf: test its objects as Primitives, and keep a ray's closest hit.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <type_traits>

#include "raytrace/accel/sphere_group.hpp"
#include "raytrace/accel/triangle_group.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/shapes/sphere.hpp"
#include "raytrace/shapes/triangle.hpp"

namespace rt {

// A leaf object as the hierarchy tests it: a sphere or a triangle from the hierarchy's own array in leaf order,
// with the very test its class uses (Sphere::nearestRoot, Triangle::solve: the same bits), but without a virtual
// call, a visit to the object's memory or a hit record for every candidate; any other shape through its own
// intersect().
template <class T> struct Primitive {
  enum class Kind : int32_t { TextbookSphere, RobustSphere, Triangle, Other };

  Vec3<T> a{0}, ab{0}, ac{0};  // a triangle's vertex and edges; a sphere's centre in a and its radius in ab.x
  Kind kind = Kind::Other;
  int id = 0;  // the object's: ties go to the lower

  static Primitive of(const Object<T>& object) {
    Primitive p;
    p.id = object.id();
    if (const auto* s = dynamic_cast<const Sphere<T>*>(&object)) {
      p.kind = s->robust() ? Kind::RobustSphere : Kind::TextbookSphere;
      p.a = s->center();
      p.ab.x = s->radius();
    } else if (const auto* t = dynamic_cast<const Triangle<T>*>(&object); t && !t->degenerate()) {
      p.kind = Kind::Triangle;
      p.a = t->a(), p.ab = t->ab(), p.ac = t->ac();
    }
    return p;
  }

  // For spheres and triangles only: the t of the object's closest hit strictly inside `range`, if any (what
  // intersect() would report), and whether it meets the ray there at all (occludes()).
  bool hitT(const Ray<T>& ray, Interval<T> range, T& t) const {
    if (kind == Kind::Triangle) {
      T u, v;
      return Triangle<T>::solve(a, ab, ac, ray, range, t, u, v);
    }
    return Sphere<T>::nearestRoot(a, ab.x, kind == Kind::RobustSphere, ray, range, t);
  }
  bool meets(const Ray<T>& ray, Interval<T> range) const {
    if (kind == Kind::Triangle) {
      T t, u, v;
      return Triangle<T>::solve(a, ab, ac, ray, range, t, u, v);
    }
    return Sphere<T>::meets(a, ab.x, kind == Kind::RobustSphere, ray, range);
  }
};

// The next representable value above t: the smallest limit that still admits a hit at exactly t. A hit's t is
// positive, where this is one step of the bit pattern; std::nextafter covers the rest.
template <class T> T nextUp(T t) {
  using Bits = std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>;
  constexpr T inf = std::numeric_limits<T>::infinity();
  if (!(t > T(0) && t < inf)) return std::nextafter(t, inf);
  Bits bits;
  std::memcpy(&bits, &t, sizeof t);
  ++bits;
  std::memcpy(&t, &bits, sizeof t);
  return t;
}

// One ray's closest hit so far while a traversal tests leaves, starting from `best`: a sphere's or a
// triangle's as its t and object, whose hit record finish() makes once, at the end; any other shape's as the
// record its intersect() gives. Equal t go to the lower object id.
template <class T> class ClosestSoFar {
 public:
  explicit ClosestSoFar(const std::optional<Hit<T>>& best)
      : t_(best ? best->t : std::numeric_limits<T>::infinity()),
        id_(best ? best->object->id() : std::numeric_limits<int>::max()) {}

  // Tests the leaf object `object` (as `p`) on the ray inside `range`; true when it is the new closest hit.
  bool test(const Primitive<T>& p, const Object<T>& object, const Ray<T>& ray, Interval<T> range,
            std::optional<Hit<T>>& best) {
    if (p.kind == Primitive<T>::Kind::Other) {
      auto hit = object.intersect(ray, range);
      if (!hit || !(hit->t < t_ || p.id < id_)) return false;
      best = hit;
      t_ = hit->t, id_ = p.id, deferred_ = nullptr;
      return true;
    }
    T t;
    if (!p.hitT(ray, range, t) || !(t < t_ || p.id < id_)) return false;
    t_ = t, id_ = p.id, deferred_ = &object, sphere_ = p.kind != Primitive<T>::Kind::Triangle;
    if (sphere_) center_ = p.a, radius_ = p.ab.x;
    return true;
  }
  // Tests the triangles or spheres of `group` (objects[group.object[k]]) on the ray inside `range`; true when
  // one of them is the new closest hit.
  template <class Group>
  bool test(const Group& group, const Object<T>* const* objects, const Ray<T>& ray, Interval<T> range) {
    typename Group::Lanes t;
    return take(group, group.hits(ray, range, t), t, objects);
  }
  T t() const { return t_; }
  // The lanes `met` of a group, hit at t[k], taken in the order (t, then id) that makes the answer the one of
  // testing the lanes one by one; true when one is the new closest hit. A sphere's centre and radius are kept
  // from the group, whose lanes are in cache, for finish(): on a large scene its entry elsewhere would be one
  // more miss per ray.
  template <class Group, class Lanes>
  bool take(const Group& group, uint32_t met, const Lanes& t, const Object<T>* const* objects) {
    bool closer = false;
    for (; met; met &= met - 1) {
      const int k = __builtin_ctz(met);
      if (!(t[k] < t_ || (t[k] == t_ && group.id[k] < id_))) continue;
      t_ = t[k], id_ = group.id[k], deferred_ = objects[group.object[k]];
      sphere_ = std::is_same_v<Group, SphereGroup<T>>;
      if constexpr (std::is_same_v<Group, SphereGroup<T>>) {
        center_ = {group.center[0][k], group.center[1][k], group.center[2][k]};
        radius_ = group.radius[k];
      }
      closer = true;
    }
    return closer;
  }
  // The record of a sphere's or triangle's hit: a sphere's made from its t as its intersect() makes it, a
  // triangle's by its intersect(), which finds the same t again.
  void finish(const Ray<T>& ray, T tMin, std::optional<Hit<T>>& best) const {
    if (!deferred_) return;
    if (sphere_) {
      best = Sphere<T>::hitAt(center_, radius_, ray, t_, deferred_);
    } else {
      best = deferred_->intersect(ray, {tMin, nextUp(t_)});
    }
  }

 private:
  T t_;
  int id_;
  const Object<T>* deferred_ = nullptr;
  bool sphere_ = false;  // whether deferred_ is a sphere, of centre_ and radius_; else a triangle
  Vec3<T> center_{0};
  T radius_ = 0;
};

}  // namespace rt
