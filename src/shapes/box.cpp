#include "raytrace/shapes/box.hpp"

#include <limits>
#include <utility>

namespace rt {

// The slab test (Kay & Kajiya 1986; docs/reference/csc473.md §c.11): the ray is inside the box between the largest
// slab entry t and the smallest slab exit t. The entry face is the outward normal of a hit from outside; from
// inside (entry ≤ range.min) the hit is the exit face, whose outward normal points along the ray.
// The face comes from the slab that set the bound, not from comparing the point with the faces (§c.11 uses a
// 0.001 tolerance for that), so it is right for boxes of any size.
template <class T>
std::optional<Hit<T>> Box<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  T tNear = -std::numeric_limits<T>::infinity(), tFar = std::numeric_limits<T>::infinity();
  int nearAxis = -1, farAxis = -1;
  for (int i = 0; i < 3; ++i) {
    if (ray.dir[i] == T(0)) {
      // Parallel to this slab: 0·∞ would be NaN for an origin on a face, so decide directly. A ray lying in
      // a face plane counts as inside, so it grazes the face rather than slipping through a crack.
      if (ray.origin[i] < min_[i] || ray.origin[i] > max_[i]) return std::nullopt;
      continue;
    }
    const T inv = T(1) / ray.dir[i];
    T t0 = (min_[i] - ray.origin[i]) * inv, t1 = (max_[i] - ray.origin[i]) * inv;
    if (inv < T(0)) std::swap(t0, t1);
    if (t0 > tNear) { tNear = t0; nearAxis = i; }
    if (t1 < tFar) { tFar = t1; farAxis = i; }
  }
  if (tNear > tFar) return std::nullopt;  // inclusive: a ray through an edge or corner hits it

  Hit<T> hit;
  int axis;
  T outward;  // the sign of the face normal along `axis`
  if (range.surrounds(tNear)) {
    hit.t = tNear;
    axis = nearAxis;
    outward = ray.dir[axis] > T(0) ? T(-1) : T(1);
  } else if (range.surrounds(tFar)) {
    hit.t = tFar;
    axis = farAxis;
    outward = ray.dir[axis] > T(0) ? T(1) : T(-1);
  } else {
    return std::nullopt;
  }
  // Re-projected onto the face (docs/reference/stability.md F4): exactly on its plane, and within its rectangle.
  hit.point = glm::clamp(ray.at(hit.t), min_, max_);
  hit.point[axis] = outward > T(0) ? max_[axis] : min_[axis];
  hit.normal = Vec3<T>(0);
  hit.normal[axis] = outward;
  hit.object = this;
  return hit;
}

template class Box<float>;
template class Box<double>;

}  // namespace rt
