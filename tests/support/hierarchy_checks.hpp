// Test support: what the hierarchy's tests share: the robust arithmetic, random directions, and the check
// that a hierarchy answers a packet of rays as a scan in file order answers each ray alone.
#pragma once

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>

#include "raytrace/accel/scene.hpp"
#include "raytrace/app/hierarchy_report.hpp"

namespace rt::test {

// The robust tier in T: its hits lie inside the objects' padded boxes, so the hierarchy must find exactly what
// a scan finds.
template <class T> Arithmetic robustArithmetic() {
  return {std::is_same_v<T, float> ? Tier::Float : Tier::Double, SphereMethod::Robust};
}

template <class T> Vec3<T> randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Vec3<T>(glm::normalize(glm::dvec3(n(rng), n(rng), n(rng))));
}

template <class T> void requireSame(const std::optional<Hit<T>>& a, const std::optional<Hit<T>>& b) {
  REQUIRE(bool(a) == bool(b));
  if (!a) return;
  REQUIRE(a->t == b->t);
  REQUIRE(a->object->id() == b->object->id());
  REQUIRE(a->point == b->point);
  REQUIRE(a->normal == b->normal);
}

// The n rays traced by `tree` as one packet, closest hits (over the whole ray) and occlusion within ranges[i],
// against `flat` (no hierarchy) one ray at a time.
template <class T>
void requirePacketAsAlone(const Scene<T>& flat, const Scene<T>& tree, const Ray<T>* rays, const Interval<T>* ranges,
                          int n, const Object<T>** lastOccluder) {
  constexpr int kPacket = Bvh<T>::kPacket;
  std::optional<Hit<T>> hits[kPacket];
  tree.closestHits(rays, n, {}, hits);
  bool shadowed[kPacket];
  tree.occluded(rays, ranges, n, shadowed, lastOccluder);
  for (int i = 0; i < n; ++i) {
    CAPTURE(i);
    requireSame(hits[i], flat.closestHit(rays[i], {}));
    REQUIRE(shadowed[i] == flat.occluded(rays[i], ranges[i]));
  }
}

// The leaves of nodes, as (first object, count, kind of group): each in a node's box that holds them, every
// inner child's box holding its node's boxes.
template <class T, class Nodes> std::vector<std::array<uint32_t, 3>> leavesInNestedBoxes(const Bvh<T>& bvh,
                                                                                         const Nodes& nodes) {
  const auto contains = [](const Aabb<T>& outer, const Aabb<T>& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::lessThanEqual(inner.max, outer.max));
  };
  std::vector<std::array<uint32_t, 3>> leaves;
  for (const auto& node : nodes) {
    for (int k = 0; k < node.size(); ++k) {
      if (node.count[k]) {
        const auto [first, count] = bvh.leafObjects(node, k);
        for (uint32_t i = first; i < first + count; ++i) CHECK(contains(node.box(k), *bvh.objects()[i]->bounds()));
        leaves.push_back({first, count, node.count[k] & ~Bvh<T>::kLeafCount});
        continue;
      }
      const auto& child = nodes[node.first[k]];
      for (int c = 0; c < child.size(); ++c) CHECK(contains(node.box(k), child.box(c)));
    }
  }
  std::sort(leaves.begin(), leaves.end());
  return leaves;
}

// The 8-wide tree that single rays walk has the 4-wide tree's leaves, tested as the same groups, and holds
// every object of the hierarchy once.
template <class T> void checkWideTree(const Bvh<T>& bvh) {
  const auto leaves = leavesInNestedBoxes(bvh, bvh.nodes());
  REQUIRE(leavesInNestedBoxes(bvh, bvh.wideNodes()) == leaves);
  uint32_t next = 0;  // the leaves, in order of their first object, cover the objects without a gap
  for (const auto& leaf : leaves) {
    REQUIRE(leaf[0] == next);
    next += leaf[1];
  }
  CHECK(next == bvh.objects().size());
  CHECK(bvh.wideNodes().size() < bvh.nodes().size());
}

// The float hierarchy of `desc`, built on 1, 2 and 5 threads, is the same node for node (as printbvh shows it),
// and large enough (over 100,000 characters printed) for the build to split its top on the threads.
inline void checkSameTreeOnAnyThreads(const SceneDesc& desc) {
  const auto printed = [&](int threads) {
    const Scene<float> scene(desc, robustArithmetic<float>(), Hierarchy::Always, threads);
    std::ostringstream out;
    printHierarchy(out, *scene.hierarchy());
    return out.str();
  };
  const std::string one = printed(1);
  CHECK(one.size() > 100000);
  CHECK(printed(2) == one);
  CHECK(printed(5) == one);
}

}  // namespace rt::test
