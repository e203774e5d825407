// Hierarchies of triangles, whose leaves are tested in TriangleGroups: the same answers as a scan in file order,
// for one ray and for packets, and every triangle in exactly one leaf inside the leaf's box.
#include <catch2/catch.hpp>

#include <map>
#include <random>

#include "raytrace/accel/scene.hpp"
#include "hierarchy_checks.hpp"
#include "scene_builder.hpp"

namespace {

using rt::Hierarchy;
using namespace rt::test;

// A grid of n × n squares, two triangles each, sharing edges and vertices: rays through a grid point meet up to
// six triangles at the same t, which must go to the first in the file.
void addGrid(rt::SceneDesc& desc, glm::dvec3 corner, glm::dvec3 du, glm::dvec3 dv, int n) {
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const glm::dvec3 p = corner + double(i) * du + double(j) * dv;
      add(desc, rt::TriangleDesc{p, p + du, p + du + dv}, {});
      add(desc, rt::TriangleDesc{p, p + du + dv, p + dv}, {});
    }
  }
}

// Grids at several angles, a soup of random triangles, some repeated exactly (every hit a tie), and grid points
// to aim at; with `spheres`, that many spheres among them, so that leaves of triangles only (tested in groups)
// and leaves with spheres meet the same rays.
rt::SceneDesc triangleScene(std::mt19937& rng, int soup, int spheres, std::vector<glm::dvec3>& gridPoints) {
  std::uniform_real_distribution<double> pos(-10, 10), small(-1, 1), unit(0, 1);
  rt::SceneDesc desc;
  for (int g = 0; g < 3; ++g) {
    const glm::dvec3 corner(pos(rng), pos(rng), pos(rng)), du(small(rng), small(rng), small(rng));
    const glm::dvec3 dv = glm::cross(du, glm::dvec3(small(rng), small(rng), small(rng)));
    addGrid(desc, corner, du, dv, 6);
    for (int i = 0; i <= 6; ++i) gridPoints.push_back(corner + double(i) * du + double(6 - i) * dv);
  }
  for (int i = 0; i < soup; ++i) {
    if (i > 0 && unit(rng) < 0.1) {
      desc.objects.push_back(desc.objects.back());
      continue;
    }
    const glm::dvec3 a(pos(rng), pos(rng), pos(rng));
    add(desc, rt::TriangleDesc{a, a + glm::dvec3(small(rng), small(rng), small(rng)),
                               a + glm::dvec3(small(rng), small(rng), small(rng))}, {});
  }
  for (int i = 0; i < spheres; ++i) add(desc, rt::SphereDesc{{pos(rng), pos(rng), pos(rng)}, 0.2 + unit(rng)}, {});
  return desc;
}

}  // namespace

TEMPLATE_TEST_CASE("a hierarchy of triangles (and spheres) finds what a scan in file order finds, alone and in packets",
                   "[bvh]", float, double) {
  using T = TestType;
  constexpr int kPacket = rt::Bvh<T>::kPacket;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    CAPTURE(seed);
    std::mt19937 rng(seed);
    std::vector<glm::dvec3> gridPoints;
    const rt::SceneDesc desc = triangleScene(rng, int(seed) * 60, seed % 2 ? 40 : 0, gridPoints);
    const rt::Scene<T> flat(desc, robustArithmetic<T>(), Hierarchy::Never);
    const rt::Scene<T> tree(desc, robustArithmetic<T>(), Hierarchy::Always);
    REQUIRE(tree.hierarchy());
    std::uniform_real_distribution<double> pos(-15, 15), spread(-0.05, 0.05), unit(0, 1);
    const rt::Object<T>* lastOccluder = nullptr;
    int ties = 0;  // rays whose closest hit is shared by several triangles
    for (int p = 0; p < 300; ++p) {
      CAPTURE(p);
      const int n = 1 + p % kPacket;
      const rt::Vec3<T> origin(pos(rng), pos(rng), pos(rng));
      rt::Ray<T> rays[kPacket];
      rt::Interval<T> ranges[kPacket];
      for (int i = 0; i < n; ++i) {
        // Half the rays through a grid point (a tie of several triangles), the rest a coherent spread.
        const glm::dvec3 target = i % 2 ? gridPoints[rng() % gridPoints.size()]
                                        : glm::dvec3(origin) + glm::dvec3(randomUnit<T>(rng)) * 10.0 +
                                              glm::dvec3(spread(rng), spread(rng), spread(rng));
        rays[i] = {origin, rt::Vec3<T>(glm::normalize(target - glm::dvec3(origin)))};
        ranges[i] = {T(0), unit(rng) < 0.5 ? T(std::abs(pos(rng))) : std::numeric_limits<T>::infinity()};
      }
      requirePacketAsAlone(flat, tree, rays, ranges, n, &lastOccluder);
      for (int i = 0; i < n; ++i) {
        CAPTURE(i);
        const std::optional<rt::Hit<T>> expected = flat.closestHit(rays[i], {});
        requireSame(tree.closestHit(rays[i], {}), expected);
        REQUIRE(tree.occluded(rays[i], ranges[i]) == flat.occluded(rays[i], ranges[i]));
        int sharing = 0;
        for (const auto& object : flat.objects()) {
          const auto hit = expected ? object->intersect(rays[i], {}) : std::nullopt;
          sharing += hit && hit->t == expected->t;
        }
        ties += sharing > 1;
      }
    }
    CHECK(ties > 50);
  }
}

TEST_CASE("a hierarchy of triangles holds every triangle in exactly one leaf, inside the leaf's box", "[bvh]") {
  std::mt19937 rng(11);
  std::vector<glm::dvec3> gridPoints;
  const rt::SceneDesc desc = triangleScene(rng, 3000, 0, gridPoints);
  const rt::Scene<float> scene(desc, robustArithmetic<float>(), Hierarchy::Always);
  const rt::Bvh<float>& bvh = *scene.hierarchy();
  REQUIRE(bvh.objects().size() == desc.objects.size());
  std::map<int, int> leavesOf;  // id → how many leaves hold it
  const auto contains = [](const rt::Aabb<float>& outer, const rt::Aabb<float>& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::lessThanEqual(inner.max, outer.max));
  };
  uint32_t largest = 0;
  for (const auto& node : bvh.nodes()) {
    for (int k = 0; k < node.size(); ++k) {
      if (!node.count[k]) continue;
      const auto [first, count] = bvh.leafObjects(node, k);
      largest = std::max(largest, count);
      for (uint32_t i = first; i < first + count; ++i) {
        ++leavesOf[bvh.objects()[i]->id()];
        CHECK(contains(node.box(k), *bvh.objects()[i]->bounds()));
      }
    }
  }
  CHECK(leavesOf.size() == desc.objects.size());
  for (const auto& [id, leaves] : leavesOf) CHECK(leaves == 1);
  checkWideTree(bvh);
  // Leaves of up to two groups: larger than those tested one object at a time (4), as a group's four tests cost
  // about one.
  CHECK(largest > 4);
  CHECK(largest <= 8);
}

TEST_CASE("a hierarchy of triangles is the same, node for node, for any number of threads", "[bvh]") {
  std::mt19937 rng(5);
  std::vector<glm::dvec3> gridPoints;
  checkSameTreeOnAnyThreads(triangleScene(rng, 12000, 0, gridPoints));
}
