// Bounding volume hierarchy over the bounded objects of a scene (csc473-course.md §c.13; the build is the
// binned SAH of Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", 2007).
#pragma once

#include <cstdint>
#include <cstring>
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

template <class T> class Bvh {
 public:
  static constexpr int kWidth = 4;  // children per node, tested together (the loops below vectorize)
  // Rays per packet: a packet's rays go down the tree together (Wald et al., "Interactive Rendering with
  // Coherent Ray Tracing", 2001), each tested against the nodes it enters. One ray's box test is a chain of
  // dependent SIMD operations; the tests of a packet's rays are independent, so they overlap in the core.
  static constexpr int kPacket = 16;

  // A node of the flattened 4-wide tree (Wald et al., "Getting Rid of Packets", 2008; Dammertz et al.,
  // "Shallow Bounding Volume Hierarchies", 2008): the boxes of its children in structure-of-arrays form, so
  // that one pass of SIMD arithmetic tests all of them. Child k < size is a leaf holding
  // objects_[first[k], first[k] + count[k]) when count[k] > 0, else the node nodes_[first[k]].
  struct Node {
    T lo[3][kWidth], hi[3][kWidth];  // [axis][child]
    uint32_t first[kWidth], count[kWidth];
    int size = 0;  // children in use; the boxes of the others are {+∞}

    Aabb<T> box(int k) const {
      return {{lo[0][k], lo[1][k], lo[2][k]}, {hi[0][k], hi[1][k], hi[2][k]}};
    }
  };

  // GCC/Clang vector extensions: one SIMD instruction per operation on all children.
  typedef T Lanes __attribute__((vector_size(kWidth * sizeof(T))));
  using LaneMask = decltype(Lanes{} < Lanes{});  // integer lanes, all bits set where a comparison holds

  // Where the ray o + t·d enters each child's box within [tMin, tMax] (`near`), and all bits set in `enters`
  // for the children it enters; invDir is 1/d. The slab test (Kay & Kajiya 1986) for all children at once. A
  // NaN from 0·∞ (origin on a slab plane, ray parallel to it) either leaves the bounds unchanged or rejects a
  // ray lying in a face plane of the box, which cannot reach the objects: they lie strictly inside their
  // padded boxes (paddedBounds in bvh.cpp). Unused child slots hold the box {+∞}, which every ray misses.
  // (Lanes are passed by reference: a 256-bit vector of doubles passed by value would depend on the AVX ABI.)
  static void entries(const Node& node, const Vec3<T>& origin, const Vec3<T>& invDir, T tMin, T tMax,
                      Lanes& near, LaneMask& enters) {
    near = Lanes{} + tMin;
    Lanes far = Lanes{} + tMax, lo, hi;
    for (int a = 0; a < 3; ++a) {
      std::memcpy(&lo, node.lo[a], sizeof lo);
      std::memcpy(&hi, node.hi[a], sizeof hi);
      const Lanes t0 = (lo - origin[a]) * invDir[a], t1 = (hi - origin[a]) * invDir[a];
      // min and max written so that a NaN from 0·∞ in t0 or t1 never replaces near or far.
      const Lanes tNear = t1 < t0 ? t1 : t0, tFar = t0 < t1 ? t1 : t0;
      near = near < tNear ? tNear : near;
      far = tFar < far ? tFar : far;
    }
    // An unused slot is entered at +∞, which only the near < ∞ test rejects when tMax is +∞ too.
    enters = (near <= far * kFarScale<T>) & (near < std::numeric_limits<T>::infinity());
  }

  // Builds over `objects`, all of which must have bounds(), in O(n log n): a binary tree by the binned
  // surface area heuristic, then collapsed to 4 children per node.
  explicit Bvh(const std::vector<const Object<T>*>& objects);

  // The two queries, for a packet of n ≤ kPacket rays (one ray is a packet of one); each ray gets the answer
  // it would get alone. best[i] becomes the closest hit of rays[i] strictly inside `range`, or stays when
  // nothing is closer; equal t resolve to the lower object id, so the answer is the one a scan in file order
  // gives (Scene::closestHits). blockers[i] becomes an object with a hit strictly inside ranges[i] (the
  // any-hit query), for the rays whose bit is set in `active`; the others are left as they are.
  void closestHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* best) const;
  void blockers(const Ray<T>* rays, const Interval<T>* ranges, uint32_t active, const Object<T>** blockers) const;

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<const Object<T>*>& objects() const { return objects_; }

  // The tree, one child per line, indented by depth: boxes, and object ids in the leaves.
  void print(std::ostream& out) const;

 private:
  std::vector<Node> nodes_;               // nodes_[0] is the root; empty when there are no objects
  std::vector<const Object<T>*> objects_;  // in leaf order
};

}  // namespace rt
