// Bounding volume hierarchy over the bounded objects of a scene (docs/reference/csc473.md §c.13; the build is the
// binned SAH of Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", 2007).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <algorithm>
#include <utility>
#include <vector>

#include "raytrace/accel/leaf.hpp"
#include "raytrace/accel/sphere_group.hpp"
#include "raytrace/accel/triangle_group.hpp"
#include "raytrace/shapes/object.hpp"

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
  static constexpr int kWidth = 4;  // children per node, tested together in the lanes of a SIMD register
  // Rays per packet: a packet's rays go down the tree together (Wald et al., "Interactive Rendering with
  // Coherent Ray Tracing", 2001), each tested against the nodes it enters. The tests of a packet's rays are
  // independent: they share wide registers and overlap in the core.
  static constexpr int kPacket = 16;
  // Deeper subtrees become leaves, so that a traversal stack of kMaxDepth·kWidth entries is enough.
  static constexpr int kMaxDepth = 64;
  // How many groups (TriangleGroup, SphereGroup: four lanes each) a leaf of `count` objects takes.
  static uint32_t groupsOf(uint32_t count) { return (count + TriangleGroup<T>::kSize - 1) / TriangleGroup<T>::kSize; }
  // A leaf's count in a Node: how many objects, and whether they are tested in groups, of which kind.
  static constexpr uint32_t kTriangleLeaf = uint32_t(1) << 31, kSphereLeaf = uint32_t(1) << 30;
  static constexpr uint32_t kLeafCount = kSphereLeaf - 1;

  // A node of the flattened W-wide tree (Wald et al., "Getting Rid of Packets", 2008; Dammertz et al.,
  // "Shallow Bounding Volume Hierarchies", 2008). Child k < size() is the node nodes_[first[k]] (wideNodes_ in
  // the wide tree; never the root, 0) when count[k] = 0, else a leaf of count[k] & kLeafCount objects:
  // objects_[first[k], ...) tested one by one, or, with kTriangleLeaf or kSphereLeaf set in count[k], the
  // groups triangleGroups_[first[k], ...) or sphereGroups_[first[k], ...) (leafObjects() tells which objects).
  // An unused child has first = count = 0 and a box at +∞ on every axis, which no ray enters: the slab test
  // puts the entry at +∞ or the exit at −∞. So the node tests need no count of children, and a 4-wide node of
  // floats is 128 bytes, two cache lines (Embree's 4-wide nodes are the same size).
  template <int W> struct alignas(64) NodeOf {
    T lo[3][W], hi[3][W];  // [axis][child]
    uint32_t first[W]{}, count[W]{};

    NodeOf() {
      std::fill_n(&lo[0][0], 3 * W, std::numeric_limits<T>::infinity());
      std::fill_n(&hi[0][0], 3 * W, std::numeric_limits<T>::infinity());
    }
    // The children in use, which come first.
    int size() const {
      int n = 0;
      while (n < W && (first[n] || count[n])) ++n;
      return n;
    }
    Aabb<T> box(int k) const {
      return {{lo[0][k], lo[1][k], lo[2][k]}, {hi[0][k], hi[1][k], hi[2][k]}};
    }
  };
  using Node = NodeOf<kWidth>;
  // The same tree with up to 8 children a node, which the queries of one ray walk (bvh_single.cpp): the same
  // leaves in fewer steps down, a node's eight boxes tested at once with AVX2. Packets keep the 4-wide tree, which
  // their rays share a register of (8 children a node cost them 15–20 %, docs/performance.md); Embree builds
  // 8-wide trees on processors with AVX.
  static constexpr int kWideWidth = 8;
  using WideNode = NodeOf<kWideWidth>;

  // A packet laid out for the node test (bvh_kernels.cpp): each of ray i's values repeated kWidth times, once per
  // child, so that a SIMD register holds the values of one or more whole rays. tMax[i] is where ray i stops,
  // invDir[a][i] is 1/d.
  struct Packet {
    alignas(64) T origin[3][kPacket][kWidth];
    alignas(64) T invDir[3][kPacket][kWidth];
    alignas(64) T tMax[kPacket][kWidth];
    RayLanes<T> lanes;  // the rays and their ranges, for tests of a group against many rays at once

    void set(int i, const Ray<T>& ray, T max) {
      for (int a = 0; a < 3; ++a) std::fill_n(origin[a][i], kWidth, ray.origin[a]);
      for (int a = 0; a < 3; ++a) std::fill_n(invDir[a][i], kWidth, T(1) / ray.dir[a]);
      std::fill_n(tMax[i], kWidth, max);
    }
  };

  // Which children of `node` the rays whose bits are set in `rays` enter within [tMin, tMax[i]]: bit i of
  // childRays[k] is set when ray i enters child k, and childEntry[k] is the nearest of their entry distances
  // (+∞ when none enters). The slab test (Kay & Kajiya 1986), for all children at once and for as many rays
  // at once as the widest SIMD registers of the processor hold. A NaN from 0·∞ (origin on a slab plane, ray
  // parallel to it) either leaves the bounds unchanged or rejects a ray lying in a face plane of the box,
  // which cannot reach the objects: they lie strictly inside their padded boxes (paddedBounds in bvh_build.cpp).
  static void entries(const Node& node, const Packet& packet, T tMin, uint32_t rays, uint32_t (&childRays)[kWidth],
                      T (&childEntry)[kWidth]);
  // The implementations of entries() this processor can run, widest SIMD first; entries() uses the first.
  using Kernel = void (*)(const Node&, const Packet&, T, uint32_t, uint32_t (&)[kWidth], T (&)[kWidth]);
  static const std::vector<Kernel>& kernels();

  // Builds over `objects`, all of which must have bounds(), in O(n log n): a binary tree by the binned
  // surface area heuristic, then collapsed to 4 children per node. The tree is the same for any number of
  // `threads`.
  explicit Bvh(const std::vector<const Object<T>*>& objects, int threads = 1);

  // The two queries, for a packet of n ≤ kPacket rays (one ray is a packet of one); each ray gets the answer
  // it would get alone. best[i] becomes the closest hit of rays[i] strictly inside `range`, or stays when
  // nothing is closer; equal t resolve to the lower object id, so the answer is the one a scan in file order
  // gives (Scene::closestHits). found[i] becomes an object with a hit strictly inside ranges[i] (the
  // any-hit query), for the rays whose bit is set in `active`; the others are left as they are.
  void closestHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* best) const;
  void occluders(const Ray<T>* rays, const Interval<T>* ranges, uint32_t active, const Object<T>** found) const;

  // The tree, for those who walk it: nodes()[0] is the root (none when there are no objects).
  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<WideNode>& wideNodes() const { return wideNodes_; }
  const std::vector<const Object<T>*>& objects() const { return objects_; }
  // The objects of the leaf that is child k of `node` (count[k] > 0): objects()[first, first + count), as
  // (first, count).
  template <int W> std::pair<uint32_t, uint32_t> leafObjects(const NodeOf<W>& node, int k) const {
    const uint32_t count = node.count[k] & kLeafCount, first = node.first[k];
    if (node.count[k] & kTriangleLeaf) return {triangleGroups_[first].object[0], count};
    if (node.count[k] & kSphereLeaf) return {sphereGroups_[first].object[0], count};
    return {first, count};
  }

  // The queries for one ray, which packets of one take too (bvh_single.cpp): the ray's node test fills one
  // register, without a packet's bookkeeping. occluder() returns an object with a hit strictly inside `range`.
  void closestHit(const Ray<T>& ray, Interval<T> range, std::optional<Hit<T>>& best) const;
  const Object<T>* occluder(const Ray<T>& ray, Interval<T> range) const;
  // The implementations of those two queries this processor can run, widest node test first (a wide node's
  // boxes in one AVX2 register, or four at a time); closestHit() and occluder() use the first. All give the
  // same answers.
  struct SingleRayQueries {
    void (*closestHit)(const Bvh&, const Ray<T>&, Interval<T>, std::optional<Hit<T>>&);
    const Object<T>* (*occluder)(const Bvh&, const Ray<T>&, Interval<T>);
  };
  static const std::vector<SingleRayQueries>& singleRayQueries();

 private:
  // The queries of one ray with the node test `Slabs` (bvh_single.cpp).
  template <class Slabs> void closestHitWith(const Ray<T>& ray, Interval<T> range, std::optional<Hit<T>>& best) const;
  template <class Slabs> const Object<T>* occluderWith(const Ray<T>& ray, Interval<T> range) const;
  // The leaf (first, count) of a node's child tested for the ray's closest hit inside [tMin, tMax), as a
  // traversal does: tMax comes down to just above each closer hit found. True when it came down.
  [[gnu::always_inline]] bool closestInLeaf(uint32_t first, uint32_t count, const Ray<T>& ray, T tMin, T& tMax,
                                             ClosestSoFar<T>& closest, std::optional<Hit<T>>& best) const {
    const T before = tMax;
    const auto testGroups = [&](const auto& groups) {
      for (uint32_t j = first; j < first + groupsOf(count & kLeafCount); ++j) {
        if (closest.test(groups[j], objects_.data(), ray, {tMin, tMax})) tMax = nextUp(closest.t());
      }
    };
    if (count & kSphereLeaf) {
      testGroups(sphereGroups_);
    } else if (count & kTriangleLeaf) {
      testGroups(triangleGroups_);
    } else {
      for (uint32_t o = first; o < first + count; ++o) {
        if (closest.test(primitives_[o], *objects_[o], ray, {tMin, tMax}, best)) tMax = nextUp(closest.t());
      }
    }
    return tMax != before;
  }
  // The first object in leaf order of a grouped leaf (first, count) that the ray meets strictly inside
  // `range`; null when none does.
  [[gnu::always_inline]] const Object<T>* occluderInGroups(uint32_t first, uint32_t count, const Ray<T>& ray,
                                                           Interval<T> range) const {
    const uint32_t end = first + groupsOf(count & kLeafCount);
    if (count & kSphereLeaf) {
      for (uint32_t j = first; j < end; ++j) {
        const SphereGroup<T>& g = sphereGroups_[j];
        if (const uint32_t met = g.meets(ray, range)) return objects_[g.object[__builtin_ctz(met)]];
      }
      return nullptr;
    }
    typename TriangleGroup<T>::Lanes t;
    for (uint32_t j = first; j < end; ++j) {
      const TriangleGroup<T>& g = triangleGroups_[j];
      if (const uint32_t met = g.hits(ray, range, t)) return objects_[g.object[__builtin_ctz(met)]];
    }
    return nullptr;
  }
  // closestInLeaf for the rays `rays` of a packet at once, in a leaf of triangle groups, with the test of many
  // rays (`manyRays`, not null); the rays whose closest hit came closer get their tMax in `packet` lowered.
  // The groups after a hit are tested up to the ray's earlier tMax, not the lowered one: the hits that admits
  // in addition are farther than the closest, which ClosestSoFar::take then turns down.
  void closestInTriangles(typename TriangleGroup<T>::ManyRays manyRays, uint32_t first, uint32_t count, uint32_t rays,
                          Packet& packet, std::optional<ClosestSoFar<T>>* closest) const {
    uint32_t met[TriangleGroup<T>::kSize], closer = 0;
    alignas(64) T t[TriangleGroup<T>::kSize][RayLanes<T>::kSize];
    for (uint32_t j = first; j < first + groupsOf(count & kLeafCount); ++j) {
      const TriangleGroup<T>& g = triangleGroups_[j];
      manyRays(g, packet.lanes, rays, met, t);
      for (uint32_t mask = met[0] | met[1] | met[2] | met[3]; mask; mask &= mask - 1) {
        const int i = __builtin_ctz(mask);
        uint32_t lanesMet = 0;
        typename TriangleGroup<T>::Lanes lanesT;
        for (int k = 0; k < TriangleGroup<T>::kSize; ++k) lanesMet |= (met[k] >> i & 1) << k, lanesT[k] = t[k][i];
        if (closest[i]->take(g, lanesMet, lanesT, objects_.data())) closer |= 1u << i;
      }
    }
    for (; closer; closer &= closer - 1) {
      const int i = __builtin_ctz(closer);
      packet.lanes.max[i] = nextUp(closest[i]->t());
      std::fill_n(packet.tMax[i], kWidth, packet.lanes.max[i]);
    }
  }
  // occluderInGroups for the rays `rays` of a packet at once, in a leaf of triangle groups, with the test of
  // many rays (`manyRays`, not null): found[i] for every ray i that meets one. Returns those rays.
  uint32_t occludersInTriangles(typename TriangleGroup<T>::ManyRays manyRays, uint32_t first, uint32_t count,
                                const RayLanes<T>& lanes, uint32_t rays, const Object<T>** found) const {
    uint32_t met[TriangleGroup<T>::kSize], done = 0;
    alignas(64) T t[TriangleGroup<T>::kSize][RayLanes<T>::kSize];
    for (uint32_t j = first; j < first + groupsOf(count & kLeafCount) && done != rays; ++j) {
      const TriangleGroup<T>& g = triangleGroups_[j];
      manyRays(g, lanes, rays & ~done, met, t);
      for (int k = 0; k < TriangleGroup<T>::kSize; ++k) {
        for (uint32_t mask = met[k] & ~done; mask; mask &= mask - 1) found[__builtin_ctz(mask)] = objects_[g.object[k]];
        done |= met[k];
      }
    }
    return done;
  }
  // Turns the leaves that hold triangles only or spheres of one formula only into groups.
  void groupLeaves();

  std::vector<Node> nodes_;                  // nodes_[0] is the root; empty when there are no objects
  std::vector<WideNode> wideNodes_;          // the same tree, 8-wide; its leaves are those of nodes_
  std::vector<const Object<T>*> objects_;    // in leaf order
  std::vector<Primitive<T>> primitives_;     // objects_ as the traversals test them
  std::vector<TriangleGroup<T>> triangleGroups_;  // the grouped leaves' (Node), in the order of nodes_
  std::vector<SphereGroup<T>> sphereGroups_;
};

}  // namespace rt
