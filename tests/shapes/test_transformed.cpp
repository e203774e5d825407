#include <cmath>
#include <memory>

#include <catch2/catch.hpp>

#include "raytrace/shapes/box.hpp"
#include "raytrace/render/camera.hpp"
#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/accel/scene.hpp"
#include "raytrace/shapes/sphere.hpp"
#include "raytrace/shapes/transformed.hpp"

using namespace rt;

namespace {

const char* kCamera = "camera { location <0, 0, 12> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n";

// The matrix the parser builds for one unit sphere carrying `modifiers`.
glm::dmat4 worldFromObject(const std::string& modifiers) {
  const SceneDesc desc = parsePov(std::string(kCamera) + "sphere { <0, 0, 0>, 1 " + modifiers + " }", "t.pov");
  return desc.objects.at(0).worldFromObject();
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

template <class T> void checkNear(const Vec3<T>& a, const Vec3<T>& b, double tolerance) {
  CAPTURE(a.x, a.y, a.z, b.x, b.y, b.z);
  CHECK(glm::length(glm::dvec3(a - b)) < tolerance);
}

template <class T>
Transformed<T> transformedSphere(T radius, const glm::dmat4& m) {
  return Transformed<T>(std::make_unique<Sphere<T>>(Vec3<T>(0), radius, SphereMethod::Robust, Material{}, 1),
                        Mat4<T>(m), Material{}, 1);
}

}  // namespace

TEST_CASE("transforms compose in file order", "[transformed]") {
  checkNear(apply(worldFromObject("translate <1, 0, 0> scale 2"), glm::dvec3(0)), glm::dvec3(2, 0, 0), 1e-12);
  checkNear(apply(worldFromObject("scale 2 translate <1, 0, 0>"), glm::dvec3(0)), glm::dvec3(1, 0, 0), 1e-12);
  checkNear(apply(worldFromObject("scale <1, 2, 3>"), glm::dvec3(1)), glm::dvec3(1, 2, 3), 1e-12);
}

TEST_CASE("rotate <a, b, c> is the course's Rx·Ry·Rz, which turns about z first", "[transformed]") {
  // Ry(90) takes x to −z, then Rx(90) takes −z to y. POV-Ray's own order (x first) would give −z.
  checkNear(apply(worldFromObject("rotate <90, 90, 0>"), glm::dvec3(1, 0, 0)), glm::dvec3(0, 1, 0), 1e-12);
  // Rz(90) takes x to y, then Rx(90) takes y to z.
  checkNear(apply(worldFromObject("rotate <90, 0, 90>"), glm::dvec3(1, 0, 0)), glm::dvec3(0, 0, 1), 1e-12);
  // A positive angle turns counter-clockwise looking down the axis (right-handed).
  checkNear(apply(worldFromObject("rotate <0, 0, 90>"), glm::dvec3(1, 0, 0)), glm::dvec3(0, 1, 0), 1e-12);
}

// docs/reference/csc473.md §a.4/§c.10: valentine2's sphere #2 (radius 2, scale <1,2,1> rotate <0,0,−25>
// translate <1.2,0,0>) seen through pixel [399, 280] of 640×480, as printed by the course's p4/test1.
TEMPLATE_TEST_CASE("the course's transformed-ray check", "[transformed]", float, double) {
  using T = TestType;
  const SceneDesc desc = parsePov(std::string(kCamera) +
                                      "sphere { <0, 0, 0>, 2 scale <1, 2, 1> rotate <0, 0, -25> "
                                      "translate <1.2, 0, 0> }",
                                  "valentine.pov");
  const glm::dmat4 m = desc.objects.at(0).worldFromObject();
  const Ray<T> ray = Camera<T>(desc.camera, 640, 480).pixelRay(399, 280);
  checkNear(ray.dir, Vec3<T>(T(0.1628), T(0.0830), T(-0.9832)), 1e-4);
  const glm::dmat4 objectFromWorld = glm::inverse(m);
  checkNear(apply(objectFromWorld, glm::dvec3(ray.origin)), glm::dvec3(-1.0876, -0.2536, 12), 1e-4);
  checkNear(glm::dvec3(objectFromWorld * glm::dvec4(glm::dvec3(ray.dir), 0)), glm::dvec3(0.1125, 0.0720, -0.9832),
            1e-4);

  const Transformed<T> sphere = transformedSphere(T(2), m);
  const auto hit = sphere.intersect(ray, Interval<T>{});
  REQUIRE(hit);
  CHECK(hit->t == Approx(10.2326).margin(1e-4));
  checkNear(hit->point, Vec3<T>(T(1.6662), T(0.8488), T(1.9397)), 1e-4);
  checkNear(hit->normal, Vec3<T>(T(0.0818), T(0.0982), T(0.9918)), 1e-4);
  // The hit is the inner sphere's, so a CSG child under a transform keeps its own material; it carries the
  // transformed object's id and name.
  REQUIRE(hit->object != nullptr);
  CHECK(hit->object != &sphere);
  CHECK(hit->object->id() == sphere.id());
  CHECK(std::string(hit->object->name()) == "Sphere");
}

TEMPLATE_TEST_CASE("a scaled sphere's t is the world t", "[transformed]", float, double) {
  using T = TestType;
  const Transformed<T> scaled = transformedSphere(T(1), worldFromObject("scale 2"));
  const Sphere<T> plain(Vec3<T>(0), T(2), SphereMethod::Robust, Material{}, 2);
  const Ray<T> ray{Vec3<T>(T(0.5), T(0.25), 10), Vec3<T>(0, 0, -1)};
  const auto a = scaled.intersect(ray, Interval<T>{});
  const auto b = plain.intersect(ray, Interval<T>{});
  REQUIRE(a);
  REQUIRE(b);
  CHECK(a->t == Approx(b->t).epsilon(1e-6));
  checkNear(a->point, b->point, 1e-5);
  checkNear(a->normal, b->normal, 1e-6);
}

TEMPLATE_TEST_CASE("a non-uniform scale maps normals by the inverse transpose", "[transformed]", float, double) {
  using T = TestType;
  // The ellipsoid x²/4 + y² + z² = 1: at p = (√2, √½, 0) the normal is ∝ (x/4, y, 0) ∝ (1, 2, 0)…
  const Transformed<T> ellipsoid = transformedSphere(T(1), worldFromObject("scale <2, 1, 1>"));
  const Vec3<T> p(std::sqrt(T(2)), std::sqrt(T(0.5)), 0);
  const Vec3<T> n = glm::normalize(Vec3<T>(1, 2, 0));
  // …so a ray coming in along −n from 5 units out meets the surface at p, at t = 5.
  const auto hit = ellipsoid.intersect(Ray<T>{p + T(5) * n, -n}, Interval<T>{});
  REQUIRE(hit);
  CHECK(hit->t == Approx(5).epsilon(1e-5));
  checkNear(hit->point, p, 1e-5);
  checkNear(hit->normal, n, 1e-5);
  // The naive M·n would tilt it the other way.
  CHECK(glm::length(glm::normalize(Vec3<T>(2, 2, 0)) - hit->normal) > T(0.1));
}

TEMPLATE_TEST_CASE("a transformed box: bounds of the turned corners, outward normal from inside", "[transformed]",
                   float, double) {
  using T = TestType;
  const glm::dmat4 m = worldFromObject("rotate <0, 0, 45> translate <0, 0, -5>");
  const Transformed<T> box(std::make_unique<Box<T>>(Vec3<T>(-1), Vec3<T>(1), Material{}, 1), Mat4<T>(m), Material{},
                           1);
  const auto bounds = box.bounds();
  REQUIRE(bounds);
  const T s = std::sqrt(T(2));
  checkNear(bounds->min, Vec3<T>(-s, -s, -6), 1e-5);
  checkNear(bounds->max, Vec3<T>(s, s, -4), 1e-5);
  // From the centre along the turned x axis: out through the face x = 1 of the object, at t = 1.
  const auto exit = box.intersect(Ray<T>{Vec3<T>(0, 0, -5), glm::normalize(Vec3<T>(1, 1, 0))}, Interval<T>{});
  REQUIRE(exit);
  CHECK(exit->t == Approx(1).epsilon(1e-5));
  checkNear(exit->normal, glm::normalize(Vec3<T>(1, 1, 0)), 1e-5);
}

TEST_CASE("the scene builds boxes, cones and cylinders, transformed or not", "[transformed][scene]") {
  const SceneDesc desc = parsePov(std::string(kCamera) +
                                      "box { <1, 1, 1>, <-1, -1, -1> translate <0, 0, -10> }\n"
                                      "cone { <0, 0, 0>, 1, <0, 0, 2>, 0 scale 2 translate <0, 0, -5> }\n"
                                      "cylinder { <0, -1, 0>, <0, 1, 0>, 0.5 translate <3, 0, 0> }\n",
                                  "shapes.pov");
  const Arithmetic arithmetic{Tier::Double, SphereMethod::Robust};
  const Scene<double> scene(desc, arithmetic);
  REQUIRE(scene.objects().size() == 3);
  // Down −z from the eye: the cone's apex at z = −1 (2·2 − 5), in front of the box's face at z = −9.
  const auto apex = scene.closestHit(Ray<double>{{0, 0, 12}, {0, 0, -1}}, Interval<double>{});
  REQUIRE(apex);
  CHECK(apex->t == Approx(13));
  CHECK(apex->object->id() == 2);
  const auto side = scene.closestHit(Ray<double>{{10, 0, 0}, {-1, 0, 0}}, Interval<double>{});
  REQUIRE(side);
  CHECK(side->t == Approx(6.5));
  CHECK(side->object->id() == 3);
  CHECK(side->normal == glm::dvec3(1, 0, 0));
}

TEST_CASE("every object is named as its description's shape, plain, transformed or folded", "[transformed][scene]") {
  const SceneDesc desc = parsePov(std::string(kCamera) +
                                      "sphere { <0, 0, 0>, 1 }\n"
                                      "sphere { <0, 0, 0>, 1 scale 2 }\n"
                                      "sphere { <0, 0, 0>, 1 scale <2, 1, 1> }\n"
                                      "plane { <0, 1, 0>, -1 }\n"
                                      "triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> rotate <0, 0, 30> }\n"
                                      "box { <1, 1, 1>, <-1, -1, -1> }\n"
                                      "cone { <0, 0, 0>, 1, <0, 0, 2>, 0 translate <0, 0, -5> }\n"
                                      "cylinder { <0, -1, 0>, <0, 1, 0>, 0.5 }\n",
                                  "names.pov");
  // The course tier keeps every transform; the others fold the uniformly scaled sphere into a plain one.
  const Scene<double> folding(desc, Arithmetic{Tier::Double, SphereMethod::Robust});
  const Scene<float> course(desc, Arithmetic{Tier::Course, SphereMethod::Textbook, OffsetPolicy::Course});
  REQUIRE(folding.objects().size() == desc.objects.size());
  REQUIRE(course.objects().size() == desc.objects.size());
  for (size_t i = 0; i < desc.objects.size(); ++i) {
    CHECK(std::string(folding.objects()[i]->name()) == shapeName(desc.objects[i].shape));
    CHECK(std::string(course.objects()[i]->name()) == shapeName(desc.objects[i].shape));
  }
}

TEST_CASE("a sphere moved by a similarity becomes a plain sphere; other transforms are kept", "[transformed][scene]") {
  const SceneDesc desc = parsePov(std::string(kCamera) +
                                      "sphere { <1, 0, 0>, 2 rotate <0, 90, 0> scale 0.5 translate <1, 2, 3> }\n"
                                      "sphere { <0, 0, 0>, 1 scale <2, 1, 1> }\n",
                                  "spheres.pov");
  const Scene<double> scene(desc, Arithmetic{Tier::Double, SphereMethod::Robust});
  // Ry(90) takes the centre (1, 0, 0) to (0, 0, −1); halved and moved: (1, 2, 2.5), radius 1.
  const auto* folded = dynamic_cast<const Sphere<double>*>(scene.objects().at(0).get());
  REQUIRE(folded);
  const auto bounds = folded->bounds();
  checkNear(bounds->min, glm::dvec3(0, 1, 1.5), 1e-12);
  checkNear(bounds->max, glm::dvec3(2, 3, 3.5), 1e-12);
  const auto hit = scene.closestHit(Ray<double>{{1, 2, 12}, {0, 0, -1}}, Interval<double>{});
  REQUIRE(hit);
  CHECK(hit->t == Approx(8.5));
  CHECK(hit->object->id() == 1);
  CHECK(dynamic_cast<const Transformed<double>*>(scene.objects().at(1).get()));
}

// The course tier (scene/arithmetic.hpp) keeps the similarity transform, in the float matrix the reference composes
// from the file's steps, and reports the hit as the reference does: the point o + t·d, the normal of the
// sphere at M⁻¹ of that point, carried out by (M⁻¹)ᵀ.
TEST_CASE("the course tier intersects the transformed ray and takes the normal at M⁻¹·(o + t·d)",
          "[transformed][scene]") {
  const SceneDesc desc = parsePov(std::string(kCamera) +
                                      "sphere { <1, 0, 0>, 2 rotate <0, 90, 0> scale 0.5 translate <1, 2, 3> }\n",
                                  "spheres.pov");
  const Scene<float> scene(desc, Arithmetic{Tier::Course, SphereMethod::Textbook, OffsetPolicy::Course});
  REQUIRE(dynamic_cast<const Transformed<float>*>(scene.objects().at(0).get()));
  const Ray<float> ray{{1.1f, 2.2f, 12}, {0, 0, -1}};
  const auto hit = scene.closestHit(ray, Interval<float>{});
  REQUIRE(hit);
  // The world sphere is centred at (1, 2, 2.5) with radius 1; the ray passes √0.05 from its axis.
  CHECK(hit->t == Approx(9.5 - std::sqrt(0.95)).margin(1e-5));
  CHECK(hit->point == ray.at(hit->t));
  const glm::mat4 objectFromWorld = glm::inverse(composeTransforms<float>(desc.objects.at(0).transforms));
  const glm::vec3 local(objectFromWorld * glm::vec4(hit->point, 1));
  const glm::vec3 objectNormal = glm::normalize(local - glm::vec3(1, 0, 0));
  CHECK(hit->normal == glm::normalize(glm::transpose(glm::mat3(objectFromWorld)) * objectNormal));
}

// A scene built in code gives its transforms as steps, as the parser does.
TEST_CASE("the course tier moves an object of a scene built in code by its steps", "[transformed][scene]") {
  SceneDesc desc;
  ObjectDesc o;
  o.shape = SphereDesc{{0, 0, 0}, 1};
  o.transforms = {{TransformStep::Kind::Translate, {0, 0, -5}}};
  desc.objects.push_back(o);
  const Scene<float> scene(desc, Arithmetic{Tier::Course, SphereMethod::Textbook, OffsetPolicy::Course});
  const auto hit = scene.closestHit(Ray<float>{{0, 0, 0}, {0, 0, -1}}, Interval<float>{});
  REQUIRE(hit);
  CHECK(hit->t == 4.0f);
  CHECK(hit->point == glm::vec3(0, 0, -4));
  CHECK(hit->normal == glm::vec3(0, 0, 1));
}
