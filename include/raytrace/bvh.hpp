// Bounding volume hierarchy over the bounded objects of a scene (csc473-course.md §c.13; the build is the
// binned SAH of Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", 2007).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <algorithm>
#include <ostream>
#include <vector>

#include "raytrace/object.hpp"

namespace rt {

// Whether a scene puts its bounded objects into a hierarchy (--hierarchy). Auto builds one from
// kHierarchyMinObjects bounded objects on, where it starts to pay (measured with raytrace_bench).
enum class Hierarchy { Auto, Always, Never };
constexpr size_t kHierarchyMinObjects = 8;

// The far distance is scaled up by 1 + 2γ₃ so that rounding never rejects a box the exact ray enters before
// tMax (Ize, "Robust BVH Ray Traversal", JCGT 2013). Scaling by a positive constant commutes with min, so it is
// applied once, to the smallest far distance.
template <class T> constexpr T kFarScale = T(1) + T(2) * (T(3) * std::numeric_limits<T>::epsilon()) /
                                                      (T(1) - T(3) * std::numeric_limits<T>::epsilon());

// The ray parameter where the ray o + t·d enters `box` within [tMin, tMax], or +∞ when it misses; invDir is
// 1/d. Slab test (Kay & Kajiya 1986). A NaN from 0·∞ (origin on a slab plane, ray parallel to it) either
// leaves the bounds unchanged or rejects a ray that lies in a face plane of the box; such a ray cannot reach
// the objects, which lie strictly inside their padded boxes (paddedBounds in bvh.cpp).
template <class T>
inline T rayBoxEntry(const Aabb<T>& box, const Vec3<T>& origin, const Vec3<T>& invDir, T tMin, T tMax) {
  for (int a = 0; a < 3; ++a) {
    const T t0 = (box.min[a] - origin[a]) * invDir[a];
    const T t1 = (box.max[a] - origin[a]) * invDir[a];
    // Branch-free (minss/maxss): which slab plane is near depends on the ray, and mispredicts would cost more
    // than the test.
    tMin = std::max(tMin, std::min(t0, t1));
    tMax = std::min(tMax, std::max(t0, t1));
  }
  return tMin <= tMax * kFarScale<T> ? tMin : std::numeric_limits<T>::infinity();
}

template <class T> class Bvh {
 public:
  // A node of the flattened tree. The two children of an inner node are stored side by side, the first at
  // `first`; a leaf holds objects_[first, first + count).
  struct Node {
    Aabb<T> box;
    uint32_t first = 0;
    uint32_t count = 0;  // 0 for an inner node

    bool leaf() const { return count != 0; }
  };

  // Builds over `objects`, all of which must have bounds(), in O(n log n).
  explicit Bvh(const std::vector<const Object<T>*>& objects);

  // The closest hit strictly inside `range`, or `best` when nothing is closer. Equal t resolve to the lower
  // object id, so the answer is the one a scan in file order gives (Scene::closestHit).
  std::optional<Hit<T>> closestHit(const Ray<T>& ray, Interval<T> range, std::optional<Hit<T>> best) const;
  // Whether any object has a hit strictly inside `range`.
  bool occluded(const Ray<T>& ray, Interval<T> range) const;

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<const Object<T>*>& objects() const { return objects_; }

  // The tree, one node per line, indented by depth: boxes, object ids in the leaves, and totals.
  void print(std::ostream& out) const;

 private:
  std::vector<Node> nodes_;               // nodes_[0] is the root; empty when there are no objects
  std::vector<const Object<T>*> objects_;  // in leaf order
};

}  // namespace rt
