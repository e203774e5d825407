#include <cmath>
#include <memory>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/scene/arithmetic.hpp"
#include "raytrace/shapes/box.hpp"
#include "raytrace/shapes/csg.hpp"
#include "raytrace/shapes/make_object.hpp"
#include "shape_oracle.hpp"

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

// POV-Ray inverts a union as the intersection of its inverted children, and a difference inverts its later
// children: no inner wall of such a union is seen (POV-Ray's pictures of both: qtvr/qtvrpanorama.pov's bored box).
TEMPLATE_TEST_CASE("an inverted union and a union cut away show no inner walls", "[csg]", float, double) {
  using T = TestType;
  ObjectDesc pair;
  pair.shape = CsgDesc{CsgOp::Union, {sphere({-0.4, 0, 0}, 1, kRed), sphere({0.4, 0, 0}, 1, kGreen)}};
  // From the origin along +x, A's far side at x = 0.6 is a wall inside B; B's at x = 1.4 is the outside.
  const Ray<T> fromCentre{{0, 0, 0}, {1, 0, 0}};
  ObjectDesc notPair = pair;
  notPair.inverse = true;
  const auto hole = makeObject<T>(notPair, SphereMethod::Robust, 1, false);
  const auto outside = hole->intersect(fromCentre, Interval<T>{});
  REQUIRE(outside);
  CHECK(outside->t == Approx(1.4).epsilon(1e-6));
  CHECK(outside->object->material().pigment == kGreen);
  CHECK(outside->normal.x == Approx(-1));  // into B, out of the inverted solid's inside
  CHECK_FALSE(hole->inside({T(1.2), 0, 0}));
  CHECK(hole->inside({T(1.5), 0, 0}));
  // A box from x = 0 to 3 less the pair: along +x from the origin, the cut's far side at 1.4 is the hit.
  ObjectDesc box;
  box.shape = BoxDesc{{0, -2, -2}, {3, 2, 2}};
  const auto cut = csg<T>(CsgOp::Difference, {box, pair});
  const auto far = cut->intersect(fromCentre, Interval<T>{});
  REQUIRE(far);
  CHECK(far->t == Approx(1.4).epsilon(1e-6));
  CHECK(far->object->material().pigment == kGreen);
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
  CHECK(group.children[0].finish->diffuse == 0);
  const auto& inner = std::get<CsgDesc>(group.children[1].shape);
  for (const ObjectDesc& o : inner.children) {
    CHECK(o.material.pigment == kGreen);
    CHECK(o.finish->diffuse == 0.5);
    CHECK(o.material.diffuse == Color(0, 0.5f, 0));
  }
}

TEST_CASE("an empty CSG group is refused where it starts", "[csg]") {
  CHECK_THROWS_WITH(parsePov("camera { location <0, 0, 5> look_at <0, 0, 0> }\nunion { pigment { rgb <1, 0, 0> } }",
                             "empty.pov"),
                    "empty.pov:2:9: error: expected an object inside 'union'");
}

namespace {

ObjectDesc inverted(ObjectDesc o) {
  o.inverse = true;
  return o;
}

ObjectDesc clipped(ObjectDesc o, std::vector<ObjectDesc> by) {
  for (ObjectDesc& c : by) o.clip.push_back({std::move(c), o.transforms.size()});
  return o;
}

ObjectDesc plane(glm::dvec3 normal, double distance) {
  ObjectDesc o;
  o.shape = PlaneDesc{normal, distance};
  return o;
}

SceneDesc povScene(const std::string& body) {
  return povray::parsePovRay("#version 3.7;\n" + body, "scene.pov", povray::PovRayOptions{{}, 320, 240, false});
}

std::string povFailure(const std::string& body) {
  try {
    povScene(body);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

// inverse: the complement. The truth table at points in and out of A and B: A ∩ ¬B is A less B everywhere, and
// so is every hit of random rays, normal included.
TEST_CASE("an intersection with an inverted child is the difference", "[csg]") {
  const ObjectDesc a = sphere({0, 0, 0}, 1, kRed), b = sphere({0.8, 0, 0}, 0.7, kGreen);
  const auto both = csg<double>(CsgOp::Intersection, {a, inverted(b)});
  const auto less = csg<double>(CsgOp::Difference, {a, b});
  const auto notB = makeObject<double>(inverted(b), SphereMethod::Robust, 1, false);
  CHECK(notB->inside({5, 0, 0}));
  CHECK_FALSE(notB->inside({0.8, 0, 0}));
  CHECK_FALSE(notB->bounds());  // the complement is unbounded
  const auto hitB = notB->intersect({{5, 0, 0}, {-1, 0, 0}}, Interval<double>{});
  REQUIRE(hitB);
  CHECK(hitB->normal.x == Approx(-1));  // out of the new inside, which is outside B
  for (const glm::dvec3 p : {glm::dvec3(-0.5, 0, 0), glm::dvec3(0.5, 0, 0), glm::dvec3(1.3, 0, 0), glm::dvec3(3, 0, 0)}) {
    CAPTURE(p.x);
    CHECK(both->inside(p) == less->inside(p));
  }
  std::mt19937 rng(40);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int r = 0; r < 2000; ++r) {
    const glm::dvec3 origin = glm::dvec3(u(rng), u(rng), u(rng)) * 2.0, target(u(rng) / 2, u(rng) / 2, u(rng) / 2);
    const Ray<double> ray{origin, glm::normalize(target - origin)};
    const auto x = both->intersect(ray, Interval<double>{}), y = less->intersect(ray, Interval<double>{});
    REQUIRE(bool(x) == bool(y));
    if (!x) continue;
    CHECK(x->t == y->t);
    CHECK(glm::length(x->normal - y->normal) < 1e-12);
    CHECK(both->inside(ray.at(r % 5 * 0.7)) == less->inside(ray.at(r % 5 * 0.7)));
  }
  test::paritySweep<double>(*both, glm::dvec3(-1), glm::dvec3(1.5), 1e-6, 41);
}

// clipped_by: the surface inside the clip and nothing new; a ray through the cut sees the inside of what is left.
TEMPLATE_TEST_CASE("a clipped sphere keeps the surface inside its clip and closes nothing", "[csg]", float, double) {
  using T = TestType;
  const auto bowl = makeObject<T>(clipped(sphere({0, 0, 0}, 1), {plane({0, 1, 0}, 0)}), SphereMethod::Robust, 1, false);
  const auto down = bowl->intersect({{0, 5, 0}, {0, -1, 0}}, Interval<T>{});
  REQUIRE(down);
  CHECK(down->t == Approx(6));  // the far side: the top is gone and no lid closes it
  CHECK(down->normal.y == Approx(-1));
  const auto side = bowl->intersect({{-5, T(-0.5), 0}, {1, 0, 0}}, Interval<T>{});
  REQUIRE(side);
  CHECK(side->t == Approx(5 - std::sqrt(0.75)).epsilon(1e-6));
  CHECK_FALSE(bowl->intersect({{-5, T(0.5), 0}, {1, 0, 0}}, Interval<T>{}));
  CHECK(bowl->inside({0, T(-0.5), 0}));
  CHECK_FALSE(bowl->inside({0, T(0.5), 0}));
  const auto box = bowl->bounds();
  REQUIRE(box);
  CHECK(box->max.y == Approx(1));  // the plane is unbounded: the sphere's box
  // Two clips: what lies inside both.
  const auto quarter = makeObject<T>(clipped(sphere({0, 0, 0}, 1), {plane({0, 1, 0}, 0), sphere({1, 0, 0}, 1)}),
                                     SphereMethod::Robust, 1, false);
  CHECK(quarter->intersect({{T(0.7), -5, 0}, {0, 1, 0}}, Interval<T>{}));
  CHECK_FALSE(quarter->intersect({{T(-0.5), -5, 0}, {0, 1, 0}}, Interval<T>{}));
  const auto qbox = quarter->bounds();
  REQUIRE(qbox);
  CHECK(qbox->min.x == Approx(0));
}

// As POV-Ray's pictures have it: a clipped object's inside is its clips' and its own, and a difference takes the
// complement of its own solid but keeps the clips. So a difference with a clipped child keeps nothing outside
// the clip, and is open there (no parity of crossings to check).
TEST_CASE("a difference with a clipped child keeps only what lies inside the clip", "[csg]") {
  // A box less a ball clipped to y < 0: the box's top and its sides above y = 0 are gone, and from above one sees
  // the ball's lower wall, or the box's floor.
  ObjectDesc box;
  box.shape = BoxDesc{{-2, -2, -2}, {2, 0.5, 2}};
  const auto cut = csg<double>(CsgOp::Difference, {box, clipped(sphere({0, 0.5, 0}, 1), {plane({0, 1, 0}, 0)})});
  const auto wall = cut->intersect({{0, 5, 0}, {0, -1, 0}}, Interval<double>{});
  REQUIRE(wall);
  CHECK(wall->t == Approx(5.5));
  CHECK(wall->normal.y == Approx(1));  // turned into the ball, out of what remains
  const auto floor = cut->intersect({{1.5, 5, 0}, {0, -1, 0}}, Interval<double>{});
  REQUIRE(floor);
  CHECK(floor->t == Approx(7));
  CHECK_FALSE(cut->inside({0, 0.25, 0}));
  CHECK_FALSE(cut->inside({1.5, 0.25, 0}));
  CHECK_FALSE(cut->inside({0, -0.25, 0}));
  CHECK(cut->inside({1.5, -1, 0}));
}

TEST_CASE("clipped_by and inverse are read with POV-Ray's transforms and bounded_by rules", "[csg]") {
  const auto world = [](const ObjectDesc& o) { return makeObject<double>(o, SphereMethod::Robust, 1, false); };
  // Transforms after clipped_by move the clip too; those before it move the object alone.
  const SceneDesc after = povScene("sphere { 0, 1 clipped_by { plane { y, 0 } } translate 2*y }\n");
  const auto moved = world(after.objects.at(0));
  const auto hit = moved->intersect({{0, 10, 0}, {0, -1, 0}}, Interval<double>{});
  REQUIRE(hit);
  CHECK(hit->t == Approx(9));
  const SceneDesc before = povScene("sphere { 0, 1 translate 2*y clipped_by { plane { y, 0 } } }\n");
  CHECK_FALSE(world(before.objects.at(0))->intersect({{0, 10, 0}, {0, -1, 0}}, Interval<double>{}));
  // clipped_by { bounded_by } clips by the bound; a bounded_by alone clips only an unbounded shape.
  const SceneDesc shared = povScene("sphere { 0, 1 bounded_by { plane { y, 0 } } clipped_by { bounded_by } }\n");
  CHECK(shared.objects.at(0).clip.size() == 1);
  CHECK(povScene("sphere { 0, 1 bounded_by { plane { y, 0 } } }\n").objects.at(0).clip.empty());
  const SceneDesc floor = povScene("plane { y, 0 bounded_by { sphere { 0, 1 } } }\n");
  const auto disc = world(floor.objects.at(0));
  CHECK(disc->intersect({{0.5, 5, 0}, {0, -1, 0}}, Interval<double>{}));
  CHECK_FALSE(disc->intersect({{1.5, 5, 0}, {0, -1, 0}}, Interval<double>{}));
  // inverse toggles, and keeps an inverted union whole.
  CHECK(povScene("sphere { 0, 1 inverse }\n").objects.at(0).inverse);
  CHECK_FALSE(povScene("#declare S = sphere { 0, 1 inverse }\nobject { S inverse }\n").objects.at(0).inverse);
  const SceneDesc group = povScene("union { sphere { 0, 1 } sphere { x, 1 } inverse }\n");
  REQUIRE(group.objects.size() == 1);
  CHECK(std::holds_alternative<CsgDesc>(group.objects[0].shape));
  // A clip decides by inside tests, as CSG does: computed in double.
  SceneDesc scene = povScene("camera { location <0, 0, -5> look_at 0 }\nsphere { 0, 1 }\n");
  CHECK(chooseArithmetic(scene).tier != Tier::Double);
  scene.objects[0] = after.objects[0];
  CHECK(chooseArithmetic(scene).tier == Tier::Double);
  CHECK(povFailure("sphere { 0, 1 clipped_by { pigment { rgb 1 } } }\n") ==
        "scene.pov:2:28: error: 'pigment in clipped_by' is not supported yet");
}
