#include <catch2/catch.hpp>

#include <cstring>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "raytrace/accel/bvh.hpp"
#include "raytrace/accel/scene.hpp"
#include "raytrace/app/hierarchy_report.hpp"
#include "hierarchy_checks.hpp"

namespace {

using rt::Hierarchy;
using rt::test::randomUnit;
using rt::test::requirePacketAsAlone;
using rt::test::requireSame;
using rt::test::robustArithmetic;

rt::ObjectDesc sphereDesc(glm::dvec3 center, double radius) {
  rt::ObjectDesc o;
  o.shape = rt::SphereDesc{center, radius};
  return o;
}

// Random spheres, some repeated exactly (ties), some nested, a share `ellipsoids` scaled into ellipsoids, and two
// planes. Without ellipsoids the hierarchy holds spheres only, and is built for SphereGroups.
rt::SceneDesc randomScene(std::mt19937& rng, int count, double ellipsoids = 0.2) {
  std::uniform_real_distribution<double> pos(-10, 10), radius(0.05, 2), unit(0, 1);
  rt::SceneDesc desc;
  for (int i = 0; i < count; ++i) {
    if (i > 0 && unit(rng) < 0.1) {
      desc.objects.push_back(desc.objects[size_t(i - 1)]);  // the same sphere again: every hit is a tie
      continue;
    }
    rt::ObjectDesc o = sphereDesc({pos(rng), pos(rng), pos(rng)}, radius(rng));
    if (unit(rng) < ellipsoids) {
      o.shape = rt::SphereDesc{{0, 0, 0}, 1};
      const glm::dvec3 scale(radius(rng), radius(rng), radius(rng)), offset(pos(rng), pos(rng), pos(rng));
      o.transforms = {{rt::TransformStep::Kind::Scale, scale}, {rt::TransformStep::Kind::Translate, offset}};
    }
    desc.objects.push_back(o);
  }
  rt::ObjectDesc floor;
  floor.shape = rt::PlaneDesc{{0, 1, 0}, -9};
  desc.objects.insert(desc.objects.begin() + count / 2, floor);
  rt::ObjectDesc wall;
  wall.shape = rt::PlaneDesc{{1, 0, 1}, 11};
  desc.objects.push_back(wall);
  return desc;
}

// The box of the unit sphere at `center`: an object the hierarchy tests through its own intersect(), so that a
// tree of them is built one object to a test (a tree of spheres only is built for SphereGroups).
rt::ObjectDesc cubeDesc(glm::dvec3 center) {
  rt::ObjectDesc o;
  o.shape = rt::BoxDesc{center - 1.0, center + 1.0};
  return o;
}

// What printbvh shows of the hierarchy of `desc` in double.
std::string printedTree(const rt::SceneDesc& desc) {
  const rt::Scene<double> scene(desc, robustArithmetic<double>(), Hierarchy::Always);
  std::ostringstream out;
  rt::printHierarchy(out, *scene.hierarchy());
  return out.str();
}

}  // namespace

TEMPLATE_TEST_CASE("the hierarchy finds exactly the hit a scan in file order finds", "[bvh]", float, double) {
  using T = TestType;
  const rt::Arithmetic arithmetic = robustArithmetic<T>();
  for (unsigned seed = 1; seed <= 20; ++seed) {
    CAPTURE(seed);
    std::mt19937 rng(seed);
    const rt::SceneDesc desc = randomScene(rng, int(seed) * 10, seed % 2 ? 0.2 : 0.0);
    const rt::Scene<T> flat(desc, arithmetic, Hierarchy::Never);
    const rt::Scene<T> tree(desc, arithmetic, Hierarchy::Always);
    REQUIRE(!flat.hierarchy());
    REQUIRE(tree.hierarchy());
    std::uniform_real_distribution<double> pos(-15, 15), unit(0, 1);
    const rt::Object<T>* lastOccluder = nullptr;
    for (int i = 0; i < 2000; ++i) {
      CAPTURE(i);
      rt::Ray<T> ray{rt::Vec3<T>(pos(rng), pos(rng), pos(rng)), randomUnit<T>(rng)};
      if (i % 2 == 0) {
        // Aim just past the edge of a sphere, where a hit is decided by rounding: the grazing rays a loose
        // box test would cull.
        // The line from the origin through c + s·side passes at r' = s·D/√(D² + s²) from the centre c.
        const auto& object = desc.objects[size_t(i / 2) % desc.objects.size()];
        const auto* s = std::get_if<rt::SphereDesc>(&object.shape);
        const glm::dvec3 toCenter = s ? s->center - glm::dvec3(ray.origin) : glm::dvec3(0);
        const double miss = s ? s->radius * (1 + (unit(rng) - 0.5) * 1e-6) : 0;
        const double d = glm::length(toCenter);
        if (s && object.transforms.empty() && d > 2 * miss) {
          const glm::dvec3 side = glm::normalize(glm::cross(toCenter, glm::dvec3(1, 2, 3)));
          const glm::dvec3 target = s->center + side * (miss * d / std::sqrt(d * d - miss * miss));
          ray.dir = rt::Vec3<T>(glm::normalize(target - glm::dvec3(ray.origin)));
        }
      }
      if (i % 7 == 3) {
        // Parallel to an axis (with a signed zero elsewhere) from a point on the plane of a sphere's extreme
        // point: the 0·∞ cases of the slab test.
        const auto& object = desc.objects[size_t(i) % desc.objects.size()];
        if (const auto* s = std::get_if<rt::SphereDesc>(&object.shape)) {
          const int axis = i % 3;
          ray.origin[axis] = T(s->center[axis] + (i % 2 ? s->radius : -s->radius));
          ray.dir = rt::Vec3<T>(T(0));
          ray.dir[(axis + 1) % 3] = i % 4 == 3 ? T(-1) : T(1);
          ray.dir[(axis + 2) % 3] = T(-0.0);
        }
      }
      const rt::Interval<T> range{T(0), i % 3 == 0 ? T(std::abs(pos(rng))) : std::numeric_limits<T>::infinity()};
      requireSame(flat.closestHit(ray, range), tree.closestHit(ray, range));
      REQUIRE(flat.occluded(ray, range) == tree.occluded(ray, range));
      // The shadow cache carried from ray to ray changes nothing but the order of the tests.
      REQUIRE(flat.occluded(ray, range) == tree.occluded(ray, range, &lastOccluder));
    }
  }
}

TEMPLATE_TEST_CASE("every implementation of one ray's queries gives the same answers", "[bvh]", float, double) {
  using T = TestType;
  const auto& queries = rt::Bvh<T>::singleRayQueries();
  INFO(queries.size() << " implementations on this processor");
  int hits = 0;
  for (unsigned seed = 1; seed <= 10; ++seed) {
    CAPTURE(seed);
    std::mt19937 rng(seed);
    const rt::Scene<T> tree(randomScene(rng, int(seed) * 20, seed % 2 ? 0.2 : 0.0), robustArithmetic<T>(),
                            Hierarchy::Always);
    const rt::Bvh<T>& bvh = *tree.hierarchy();
    std::uniform_real_distribution<double> pos(-15, 15);
    for (int i = 0; i < 2000; ++i) {
      CAPTURE(i);
      rt::Ray<T> ray{rt::Vec3<T>(pos(rng), pos(rng), pos(rng)), randomUnit<T>(rng)};
      if (i % 5 == 0) ray.dir[i % 3] = T(0);  // parallel to a slab: infinite slab distances in the node test
      const rt::Interval<T> range{T(0), i % 3 == 0 ? T(std::abs(pos(rng))) : std::numeric_limits<T>::infinity()};
      std::optional<rt::Hit<T>> expected;
      queries.back().closestHit(bvh, ray, range, expected);
      const rt::Object<T>* expectedOccluder = queries.back().occluder(bvh, ray, range);
      hits += expected.has_value();
      for (const auto& query : queries) {
        std::optional<rt::Hit<T>> hit;
        query.closestHit(bvh, ray, range, hit);
        requireSame(hit, expected);
        REQUIRE(query.occluder(bvh, ray, range) == expectedOccluder);
      }
    }
  }
  CHECK(hits > 2000);  // of the 20,000 rays: the answers compared are not all misses
}

TEMPLATE_TEST_CASE("a packet of rays gets the answers each ray gets alone", "[bvh]", float, double) {
  using T = TestType;
  constexpr int kPacket = rt::Bvh<T>::kPacket;
  const rt::Arithmetic arithmetic = robustArithmetic<T>();
  for (unsigned seed = 1; seed <= 10; ++seed) {
    CAPTURE(seed);
    std::mt19937 rng(seed);
    const rt::SceneDesc desc = randomScene(rng, int(seed) * 20, seed % 2 ? 0.2 : 0.0);
    const rt::Scene<T> flat(desc, arithmetic, Hierarchy::Never);
    const rt::Scene<T> tree(desc, arithmetic, Hierarchy::Always);
    std::uniform_real_distribution<double> pos(-15, 15), spread(-0.05, 0.05), unit(0, 1);
    const rt::Object<T>* lastOccluder = nullptr;
    for (int p = 0; p < 200; ++p) {
      CAPTURE(p);
      // Odd packets are coherent (one origin, directions within a few degrees, as a pixel's eye rays), even
      // ones scattered; sizes run through 1..kPacket.
      const int n = 1 + p % kPacket;
      const rt::Vec3<T> origin(pos(rng), pos(rng), pos(rng));
      const rt::Vec3<T> axis = randomUnit<T>(rng);
      rt::Ray<T> rays[kPacket];
      rt::Interval<T> ranges[kPacket];
      for (int i = 0; i < n; ++i) {
        if (p % 2) {
          rays[i] = {origin, rt::Vec3<T>(glm::normalize(glm::dvec3(axis) + glm::dvec3(spread(rng), spread(rng), spread(rng))))};
        } else {
          rays[i] = {rt::Vec3<T>(pos(rng), pos(rng), pos(rng)), randomUnit<T>(rng)};
        }
        ranges[i] = {T(0), unit(rng) < 0.5 ? T(std::abs(pos(rng))) : std::numeric_limits<T>::infinity()};
      }
      requirePacketAsAlone(flat, tree, rays, ranges, n, &lastOccluder);
    }
  }
}

TEMPLATE_TEST_CASE("every SIMD kernel of the node test gives the baseline's bits", "[bvh]", float, double) {
  using Bvh = rt::Bvh<TestType>;
  using T = TestType;
  const auto& kernels = Bvh::kernels();
  INFO(kernels.size() << " kernels on this processor");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-4, 4), unit(0, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    CAPTURE(trial);
    typename Bvh::Node node;
    const int used = 1 + trial % Bvh::kWidth;  // the others keep the unused child's box, which no ray enters
    for (int k = 0; k < used; ++k) {
      for (int a = 0; a < 3; ++a) {
        const double x = pos(rng), y = pos(rng);
        node.lo[a][k] = T(std::min(x, y)), node.hi[a][k] = T(std::max(x, y));
      }
    }
    typename Bvh::Packet packet{};
    for (int i = 0; i < Bvh::kPacket; ++i) {
      // Some rays start on a slab plane or run parallel to one: the 0·∞ cases.
      rt::Vec3<T> origin(pos(rng), pos(rng), pos(rng)), dir = randomUnit<T>(rng);
      if (unit(rng) < 0.2) origin.x = node.lo[0][0];
      if (unit(rng) < 0.2) dir.y = T(0);
      packet.set(i, {origin, dir}, unit(rng) < 0.5 ? T(std::abs(pos(rng))) : std::numeric_limits<T>::infinity());
    }
    const uint32_t rays = uint32_t(rng()) & ((1u << Bvh::kPacket) - 1);
    uint32_t expectedRays[Bvh::kWidth], childRays[Bvh::kWidth];
    T expectedEntry[Bvh::kWidth], childEntry[Bvh::kWidth];
    kernels.back()(node, packet, T(0), rays, expectedRays, expectedEntry);
    for (const auto kernel : kernels) {
      kernel(node, packet, T(0), rays, childRays, childEntry);
      for (int k = 0; k < Bvh::kWidth; ++k) {
        CAPTURE(k);
        REQUIRE(childRays[k] == expectedRays[k]);
        REQUIRE(std::memcmp(&childEntry[k], &expectedEntry[k], sizeof(T)) == 0);
        if (k >= used) REQUIRE(childRays[k] == 0);
      }
    }
  }
}

TEST_CASE("equal t resolve to the object that comes first in the file", "[bvh]") {
  rt::SceneDesc desc;
  for (int i = 0; i < 50; ++i) desc.objects.push_back(sphereDesc({(i % 5) * 3.0, 0, -10}, 1));
  const rt::Scene<float> tree(desc, {rt::Tier::Float, rt::SphereMethod::Robust}, Hierarchy::Always);
  for (int k = 0; k < 5; ++k) {
    const rt::Ray<float> ray{{k * 3.0f, 0, 0}, {0, 0, -1}};
    const auto hit = tree.closestHit(ray, {});
    REQUIRE(hit);
    CHECK(hit->t == 9.0f);
    CHECK(hit->object->id() == k + 1);
  }
}

TEST_CASE("the tree holds every bounded object once, inside nested boxes", "[bvh]") {
  std::mt19937 rng(7);
  const rt::SceneDesc desc = randomScene(rng, 300);
  const rt::Scene<double> scene(desc, {rt::Tier::Double, rt::SphereMethod::Robust}, Hierarchy::Always);
  const rt::Bvh<double>& bvh = *scene.hierarchy();
  REQUIRE(bvh.objects().size() == desc.objects.size() - 2);  // the two planes stay outside
  std::set<int> ids;
  for (const auto* o : bvh.objects()) ids.insert(o->id());
  CHECK(ids.size() == bvh.objects().size());
  const auto contains = [](const rt::Aabb<double>& outer, const rt::Aabb<double>& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::lessThanEqual(inner.max, outer.max));
  };
  for (const auto& node : bvh.nodes()) {
    for (int k = 0; k < node.size(); ++k) {
      if (node.count[k]) {
        const auto [first, count] = bvh.leafObjects(node, k);
        for (uint32_t i = first; i < first + count; ++i) CHECK(contains(node.box(k), *bvh.objects()[i]->bounds()));
        continue;
      }
      const auto& child = bvh.nodes()[node.first[k]];
      for (int c = 0; c < child.size(); ++c) CHECK(contains(node.box(k), child.box(c)));
    }
  }
}

TEST_CASE("the 8-wide tree of single rays has the 4-wide tree's leaves", "[bvh]") {
  std::mt19937 rng(8);
  // With ellipsoids, leaves tested one object at a time; spheres only, leaves of sphere groups.
  for (const double ellipsoids : {0.2, 0.0}) {
    const rt::SceneDesc desc = randomScene(rng, 3000, ellipsoids);
    rt::test::checkWideTree(*rt::Scene<float>(desc, rt::test::robustArithmetic<float>(), Hierarchy::Always)
                                 .hierarchy());
  }
}

// Large enough that the top of the tree is split first and the subtrees under it are built on the threads; a
// tenth of the spheres coincide, so that some subtrees stop early.
TEST_CASE("the tree is the same, node for node, for any number of threads", "[bvh]") {
  std::mt19937 rng(20000);
  rt::SceneDesc desc = randomScene(rng, 20000);
  for (int i = 0; i < 2000; ++i) desc.objects.push_back(sphereDesc({4, 4, 4}, 0.5));
  rt::test::checkSameTreeOnAnyThreads(desc);
}

// Spheres near float's largest value: their boxes are finite, but the sum of two corners, and so their centres,
// overflow to ∞ (found by fuzz_cs3451; the bins' arithmetic then gave NaN, and an out-of-range bin index).
TEST_CASE("objects near the top of the float range still make a tree that finds them", "[bvh]") {
  rt::SceneDesc desc;
  for (int i = 0; i < 12; ++i) desc.objects.push_back(sphereDesc({(i % 2 ? 3.3e38 : -3.3e38), i * 10.0, 0}, 1));
  for (int i = 0; i < 12; ++i) desc.objects.push_back(sphereDesc({i * 3.0, 0, 0}, 1));
  const rt::Scene<float> scene(desc, {rt::Tier::Float, rt::SphereMethod::Robust}, Hierarchy::Always);
  REQUIRE(scene.hierarchy()->objects().size() == 24);
  std::set<int> ids;
  for (const auto* o : scene.hierarchy()->objects()) ids.insert(o->id());
  CHECK(ids.size() == 24);
  const auto hit = scene.closestHit({{9, 0, 10}, {0, 0, -1}}, {});
  REQUIRE(hit);
  CHECK(hit->object->id() == 16);
}

TEST_CASE("a hierarchy is built only where it pays", "[bvh]") {
  rt::SceneDesc desc;
  for (int i = 0; i < 3; ++i) desc.objects.push_back(sphereDesc({i * 3.0, 0, 0}, 1));
  const rt::Arithmetic arithmetic{rt::Tier::Float, rt::SphereMethod::Robust};
  CHECK(!rt::Scene<float>(desc, arithmetic).hierarchy());
  while (desc.objects.size() < rt::kHierarchyMinObjects) desc.objects.push_back(sphereDesc({0, 5, 0}, 1));
  CHECK(rt::Scene<float>(desc, arithmetic).hierarchy());
  CHECK(!rt::Scene<float>(desc, arithmetic, Hierarchy::Never).hierarchy());
}

TEST_CASE("coincident objects still split into small leaves", "[bvh]") {
  // Leaves of up to 4 objects tested one by one, or of up to 8 spheres (two SphereGroups) in a tree of spheres.
  for (const bool grouped : {false, true}) {
    CAPTURE(grouped);
    rt::SceneDesc desc;
    for (int i = 0; i < 1000; ++i) desc.objects.push_back(grouped ? sphereDesc({1, 2, 3}, 1) : cubeDesc({1, 2, 3}));
    const rt::Scene<float> scene(desc, {rt::Tier::Float, rt::SphereMethod::Robust}, Hierarchy::Always);
    for (const auto& node : scene.hierarchy()->nodes()) {
      for (int k = 0; k < node.size(); ++k) {
        if (node.count[k]) CHECK(scene.hierarchy()->leafObjects(node, k).second <= (grouped ? 8u : 4u));
      }
    }
    const auto hit = scene.closestHit({{1, 2, 10}, {0, 0, -1}}, {});
    REQUIRE(hit);
    CHECK(hit->object->id() == 1);
  }
}

TEST_CASE("an empty hierarchy answers nothing", "[bvh]") {
  const rt::Bvh<float> empty({});
  const rt::Ray<float> ray{{0, 0, 0}, {0, 0, -1}};
  std::optional<rt::Hit<float>> hit;
  empty.closestHits(&ray, 1, {}, &hit);
  CHECK(!hit);
  const rt::Interval<float> range;
  const rt::Object<float>* occluder = nullptr;
  empty.occluders(&ray, &range, 1u, &occluder);
  CHECK(!occluder);
  empty.closestHit(ray, {}, hit);
  CHECK(!hit);
  CHECK(!empty.occluder(ray, range));
  std::ostringstream out;
  rt::printHierarchy(out, empty);
  CHECK(out.str() == "BVH: 0 objects, 0 nodes of up to 4 children, 0 leaves, largest leaf 0\n");
}

TEST_CASE("printbvh shows each node's box and the object ids in the leaves", "[bvh]") {
  rt::SceneDesc desc;
  desc.objects.push_back(cubeDesc({0, 0, 0}));
  desc.objects.push_back(cubeDesc({10, 0, 0}));
  CHECK(printedTree(desc) ==
        "BVH: 2 objects, 1 nodes of up to 4 children, 2 leaves, largest leaf 1\n"
        "Node 0: {-1.0020 -1.0020 -1.0020} - {11.0020 1.0020 1.0020}\n"
        "  Leaf: {-1.0020 -1.0020 -1.0020} - {1.0020 1.0020 1.0020} objects 1\n"
        "  Leaf: {8.9980 -1.0020 -1.0020} - {11.0020 1.0020 1.0020} objects 2\n");
}

// Clusters with gaps of many empty bins between them. The build sweeps only the bins that got objects; the
// tree must be the one a sweep over every bin boundary gives (checked against that build, which this printout
// comes from): each gap is split where the surface area heuristic is lowest, and no cluster is cut.
TEST_CASE("splits fall in the gaps between clusters, as a sweep over every bin boundary puts them", "[bvh]") {
  rt::SceneDesc desc;
  for (const double x : {0, 3, 4, 10, 30, 31, 33, 60, 61}) desc.objects.push_back(cubeDesc({x, 0, 0}));
  CHECK(printedTree(desc) ==
        "BVH: 9 objects, 3 nodes of up to 4 children, 6 leaves, largest leaf 2\n"
        "Node 0: {-1.0020 -1.0020 -1.0020} - {62.0020 1.0020 1.0020}\n"
        "  Leaf: {58.9980 -1.0020 -1.0020} - {62.0020 1.0020 1.0020} objects 8 9\n"
        "  Leaf: {8.9980 -1.0020 -1.0020} - {11.0020 1.0020 1.0020} objects 4\n"
        "  Node 1: {-1.0020 -1.0020 -1.0020} - {5.0020 1.0020 1.0020}\n"
        "    Leaf: {-1.0020 -1.0020 -1.0020} - {1.0020 1.0020 1.0020} objects 1\n"
        "    Leaf: {1.9980 -1.0020 -1.0020} - {5.0020 1.0020 1.0020} objects 2 3\n"
        "  Node 2: {28.9980 -1.0020 -1.0020} - {34.0020 1.0020 1.0020}\n"
        "    Leaf: {28.9980 -1.0020 -1.0020} - {32.0020 1.0020 1.0020} objects 5 6\n"
        "    Leaf: {31.9980 -1.0020 -1.0020} - {34.0020 1.0020 1.0020} objects 7\n");
}

TEMPLATE_TEST_CASE("scene: an object with no_shadow is hit but casts no shadow, with or without a hierarchy, "
                   "through transparent surfaces too", "",
                   float, double) {
  rt::SceneDesc desc;
  for (int i = 0; i < 12; ++i) desc.objects.push_back(sphereDesc({3.0 * i, 0, 0}, 1));
  desc.objects[0].noShadow = true;
  const rt::Ray<TestType> ray{{0, 0, -5}, {0, 0, 1}};
  const rt::Interval<TestType> range{TestType(0), TestType(10)};
  for (const Hierarchy h : {Hierarchy::Never, Hierarchy::Always}) {
    const rt::Scene<TestType> scene(desc, robustArithmetic<TestType>(), h);
    CHECK(scene.closestHit(ray, range));
    CHECK_FALSE(scene.occluded(ray, range));
    bool shadowed = true;
    const rt::Object<TestType>* last = nullptr;
    scene.occluded(&ray, &range, 1, &shadowed, &last);
    CHECK_FALSE(shadowed);
    // Nor does a shadow ray followed through transparent surfaces see it.
    CHECK_FALSE(scene.closestHit(ray, range, rt::Sight::Shadow));
    // The sphere at x = 3 still casts one.
    const rt::Ray<TestType> other{{3, 0, -5}, {0, 0, 1}};
    CHECK(scene.occluded(other, range));
    CHECK(scene.closestHit(other, range, rt::Sight::Shadow));
  }
}

TEMPLATE_TEST_CASE("scene: no_image, no_reflection and no_radiosity hide an object from image, reflected or "
                   "gathered rays alone", "",
                   float, double) {
  rt::SceneDesc desc;
  for (int i = 0; i < 12; ++i) desc.objects.push_back(sphereDesc({0, 0, 3.0 * i}, 1));
  desc.objects[0].noImage = true;
  desc.objects[1].noReflection = true;
  desc.objects[2].noRadiosity = true;
  const rt::Ray<TestType> ray{{0, 0, -5}, {0, 0, 1}};
  for (const Hierarchy h : {Hierarchy::Never, Hierarchy::Always}) {
    const rt::Scene<TestType> scene(desc, robustArithmetic<TestType>(), h);
    const auto nearest = [&](rt::Sight sight) {
      const auto hit = scene.closestHit(ray, {}, sight);
      REQUIRE(hit);
      return hit->object->id();
    };
    CHECK(nearest(rt::Sight::All) == 1);
    CHECK(nearest(rt::Sight::Image) == 2);
    CHECK(nearest(rt::Sight::Reflected) == 1);
    CHECK(nearest(rt::Sight::Gathered) == 1);
    std::optional<rt::Hit<TestType>> hit;
    scene.closestHits(&ray, 1, {}, &hit, rt::Sight::Image);
    REQUIRE(hit);
    CHECK(hit->object->id() == 2);
    // Both still cast shadows.
    CHECK(scene.occluded(ray, {TestType(0), TestType(10)}));
    const rt::Ray<TestType> behind{{0, 0, 1.5}, {0, 0, 1}};
    const auto second = scene.closestHit(behind, {}, rt::Sight::Reflected);
    REQUIRE(second);
    CHECK(second->object->id() == 3);
    const auto gathered = scene.closestHit(behind, {}, rt::Sight::Gathered);
    REQUIRE(gathered);
    CHECK(gathered->object->id() == 2);
    const auto past = scene.closestHit({{0, 0, 4.5}, {0, 0, 1}}, {}, rt::Sight::Gathered);
    REQUIRE(past);
    CHECK(past->object->id() == 4);
  }
}
