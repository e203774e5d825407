#include <cmath>
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/scene/arithmetic.hpp"
#include "raytrace/shapes/csg.hpp"
#include "raytrace/shapes/make_object.hpp"

using namespace rt;

namespace {

ObjectDesc sphere(glm::dvec3 center, double radius, Color pigment = Color(0)) {
  ObjectDesc o;
  o.shape = SphereDesc{center, radius};
  o.material.pigment = pigment;
  return o;
}

template <class T> std::unique_ptr<Object<T>> csg(CsgOp op, std::vector<ObjectDesc> children) {
  ObjectDesc group;
  group.shape = CsgDesc{op, std::move(children)};
  return makeObject<T>(group, SphereMethod::Robust, 1, false);
}

const Color kRed(1, 0, 0), kGreen(0, 1, 0);

}  // namespace

// The unit sphere A at the origin less the unit sphere B at (1, 0, 0).
TEMPLATE_TEST_CASE("a difference keeps the first solid's surface outside the others, and theirs inside it", "[csg]",
                   float, double) {
  using T = TestType;
  const auto lune = csg<T>(CsgOp::Difference, {sphere({0, 0, 0}, 1, kRed), sphere({1, 0, 0}, 1, kGreen)});

  // Along x = 0.3: A's near side at z = −√0.91, 1.18 from B's centre, is kept.
  const auto front = lune->intersect({{T(0.3), 0, -5}, {0, 0, 1}}, Interval<T>{});
  REQUIRE(front);
  CHECK(front->t == Approx(5 - std::sqrt(0.91)).epsilon(1e-6));
  CHECK(front->object->material().pigment == kRed);
  CHECK(front->normal.z == Approx(-std::sqrt(0.91)).epsilon(1e-6));

  // Along −x from (3, 0, 0): B's far side at x = 2 is outside A; its side at x = 0 lies inside A and is the
  // lune's wall, facing +x (B's outward normal turned inward), in B's material.
  const auto wall = lune->intersect({{3, 0, 0}, {-1, 0, 0}}, Interval<T>{});
  REQUIRE(wall);
  CHECK(wall->t == Approx(3).epsilon(1e-6));
  CHECK(wall->normal.x == Approx(1).epsilon(1e-6));
  CHECK(wall->object->material().pigment == kGreen);

  // Along x = 0.8 nothing of A lies outside B: z² < 0.36 and z² ≥ 0.96 have no common z.
  CHECK_FALSE(lune->intersect({{T(0.8), 0, -5}, {0, 0, 1}}, Interval<T>{}));

  CHECK(lune->inside({T(-0.5), 0, 0}));
  CHECK_FALSE(lune->inside({T(0.5), 0, 0}));
  CHECK_FALSE(lune->inside({T(-1.5), 0, 0}));
  const auto box = lune->bounds();
  REQUIRE(box);
  CHECK(box->max.x == Approx(1).epsilon(1e-6));  // the first child's box
}

// Unit spheres A at (−0.4, 0, 0) and B at (0.4, 0, 0).
TEMPLATE_TEST_CASE("an intersection keeps each surface inside all the others", "[csg]", float, double) {
  using T = TestType;
  const auto lens = csg<T>(CsgOp::Intersection, {sphere({-0.4, 0, 0}, 1, kRed), sphere({0.4, 0, 0}, 1, kGreen)});
  // Along x = 0.1: B's near side (z = −√0.91) is outside A; A's (z = −√0.75) is inside B.
  const auto hit = lens->intersect({{T(0.1), 0, -5}, {0, 0, 1}}, Interval<T>{});
  REQUIRE(hit);
  CHECK(hit->t == Approx(5 - std::sqrt(0.75)).epsilon(1e-6));
  CHECK(hit->object->material().pigment == kRed);
  CHECK(lens->inside({0, 0, 0}));
  CHECK_FALSE(lens->inside({T(-1.2), 0, 0}));
  const auto box = lens->bounds();
  REQUIRE(box);
  CHECK(box->min.x == Approx(-0.6).epsilon(1e-6));
  CHECK(box->max.x == Approx(0.6).epsilon(1e-6));
}

TEMPLATE_TEST_CASE("a union keeps inner walls and a merge removes them", "[csg]", float, double) {
  using T = TestType;
  const std::vector<ObjectDesc> pair{sphere({-0.4, 0, 0}, 1, kRed), sphere({0.4, 0, 0}, 1, kGreen)};
  const Ray<T> fromCentre{{0, 0, 0}, {1, 0, 0}};
  const auto join = csg<T>(CsgOp::Union, pair);
  const auto fused = csg<T>(CsgOp::Merge, pair);
  // From the origin along +x: A's far side at x = 0.6 is a wall inside B; B's at x = 1.4 is the outside.
  const auto wall = join->intersect(fromCentre, Interval<T>{});
  REQUIRE(wall);
  CHECK(wall->t == Approx(0.6).epsilon(1e-6));
  CHECK(wall->object->material().pigment == kRed);
  const auto outside = fused->intersect(fromCentre, Interval<T>{});
  REQUIRE(outside);
  CHECK(outside->t == Approx(1.4).epsilon(1e-6));
  CHECK(outside->object->material().pigment == kGreen);
  // From outside both agree: A's left side at x = −1.4.
  const Ray<T> fromLeft{{-5, 0, 0}, {1, 0, 0}};
  CHECK(join->intersect(fromLeft, Interval<T>{})->t == Approx(3.6).epsilon(1e-6));
  CHECK(fused->intersect(fromLeft, Interval<T>{})->t == Approx(3.6).epsilon(1e-6));
  CHECK(join->inside({T(1.2), 0, 0}));
  CHECK_FALSE(join->inside({T(1.5), 0, 0}));
}

TEMPLATE_TEST_CASE("a moved CSG child keeps its own material and the group's transform moves all", "[csg]", float,
                   double) {
  using T = TestType;
  ObjectDesc moved = sphere({0, 0, 0}, 1, kGreen);
  moved.transforms.push_back({TransformStep::Kind::Translate, {1, 0, 0}});
  ObjectDesc group;
  group.shape = CsgDesc{CsgOp::Difference, {sphere({0, 0, 0}, 1, kRed), moved}};
  group.transforms.push_back({TransformStep::Kind::Translate, {0, 0, -2}});
  const auto lune = makeObject<T>(group, SphereMethod::Robust, 7, false);
  const auto wall = lune->intersect({{3, 0, -2}, {-1, 0, 0}}, Interval<T>{});
  REQUIRE(wall);
  CHECK(wall->t == Approx(3).epsilon(1e-6));
  CHECK(wall->object->material().pigment == kGreen);
  CHECK(wall->object->id() == 7);
  CHECK(lune->inside({T(-0.5), 0, -2}));
  CHECK_FALSE(lune->inside({T(-0.5), 0, 0}));
}

TEST_CASE("a CSG scene is computed in double until float's error on it is bounded", "[csg]") {
  SceneDesc scene;
  scene.camera.location = {0, 0, 5};
  scene.objects.push_back(sphere({0, 0, 0}, 1));
  CHECK(chooseArithmetic(scene).tier != Tier::Double);
  ObjectDesc group;
  group.shape = CsgDesc{CsgOp::Union, {sphere({0, 0, 0}, 1)}};
  scene.objects.push_back(group);
  CHECK(chooseArithmetic(scene).tier == Tier::Double);
}

TEST_CASE("a CSG child without a pigment or finish takes its group's", "[csg]") {
  const SceneDesc desc = parsePov(
      "camera { location <0, 0, 5> up <0, 1, 0> right <1, 0, 0> look_at <0, 0, 0> }\n"
      "difference {\n"
      "  sphere { <0, 0, 0>, 1 pigment { color rgb <1, 0, 0> } }\n"
      "  union { sphere { <1, 0, 0>, 1 } cylinder { <0, 0, 0>, <0, 1, 0>, 0.5 } }\n"
      "  pigment { color rgb <0, 1, 0> } finish { ambient 0.2 diffuse 0.5 }\n"
      "}\n",
      "csg.pov");
  REQUIRE(desc.objects.size() == 1);
  const auto& group = std::get<CsgDesc>(desc.objects[0].shape);
  CHECK(std::string(shapeName(desc.objects[0].shape)) == "Difference");
  REQUIRE(group.children.size() == 2);
  CHECK(group.children[0].material.pigment == kRed);
  CHECK(group.children[0].finish.diffuse == 0);
  const auto& inner = std::get<CsgDesc>(group.children[1].shape);
  for (const ObjectDesc& o : inner.children) {
    CHECK(o.material.pigment == kGreen);
    CHECK(o.finish.diffuse == 0.5);
    CHECK(o.material.diffuse == Color(0, 0.5f, 0));
  }
}

TEST_CASE("an empty CSG group is refused where it starts", "[csg]") {
  CHECK_THROWS_WITH(parsePov("camera { location <0, 0, 5> look_at <0, 0, 0> }\nunion { pigment { rgb <1, 0, 0> } }",
                             "empty.pov"),
                    "empty.pov:2:9: error: expected an object inside 'union'");
}
