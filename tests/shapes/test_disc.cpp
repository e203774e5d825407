#include <cmath>
#include <memory>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/shapes/disc.hpp"

using namespace rt;

namespace {

const Material kMaterial{};

template <class T> std::unique_ptr<Object<T>> disc(glm::dvec3 center, glm::dvec3 normal, double radius, double hole) {
  return DiscDesc{center, normal, radius, hole}.make<T>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
}

std::string povFailure(const std::string& body) {
  try {
    povray::parsePovRay("#version 3.7;\n" + body, "scene.pov", povray::PovRayOptions{{}, 320, 240, false});
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

std::string courseFailure(const std::string& body) {
  try {
    parsePov("camera { location <0,0,5> look_at <0,0,0> }\n" + body, "s.pov");
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEMPLATE_TEST_CASE("a disc is hit on its ring, not in its hole nor past its rim", "[disc]", float, double) {
  using T = TestType;
  const auto d = disc<T>({0, 1, 0}, {0, 3, 0}, 2, 0.5);
  const auto hit = d->intersect({{1, 6, 0}, {0, -1, 0}}, Interval<T>{});
  REQUIRE(hit);
  CHECK(hit->t == Approx(5));
  CHECK(hit->point.y == T(1));
  CHECK(hit->normal == Vec3<T>(0, 1, 0));
  CHECK_FALSE(d->intersect({{T(0.3), 6, 0}, {0, -1, 0}}, Interval<T>{}));  // in the hole
  CHECK_FALSE(d->intersect({{T(2.1), 6, 0}, {0, -1, 0}}, Interval<T>{}));  // past the rim
  CHECK_FALSE(d->intersect({{1, 6, 0}, {1, 0, 0}}, Interval<T>{}));        // parallel to it
  // The manual's inside: the plane's, whatever the radius.
  CHECK(d->inside({0, 0, 0}));
  CHECK(d->inside({50, 0, 0}));
  CHECK_FALSE(d->inside({1, 2, 0}));
}

TEST_CASE("a disc's box is its circle's, and every hit of a random sweep lies on its ring", "[disc]") {
  const glm::dvec3 center(0.5, -1, 2), normal = glm::normalize(glm::dvec3(1, 2, -2));
  const auto d = disc<double>(center, normal, 1.5, 0.25);
  const auto box = d->bounds();
  REQUIRE(box);
  for (int i = 0; i < 3; ++i) {
    CHECK(box->max[i] - center[i] == Approx(1.5 * std::sqrt(1 - normal[i] * normal[i])).epsilon(1e-9));
    CHECK(center[i] - box->min[i] == Approx(1.5 * std::sqrt(1 - normal[i] * normal[i])).epsilon(1e-9));
  }
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-3, 3);
  int hits = 0;
  for (int r = 0; r < 2000; ++r) {
    const glm::dvec3 origin = center + glm::dvec3(u(rng), u(rng), u(rng)) * 2.0;
    const glm::dvec3 target = center + glm::dvec3(u(rng), u(rng), u(rng)) * 0.6;
    const Ray<double> ray{origin, glm::normalize(target - origin)};
    const auto hit = d->intersect(ray, Interval<double>{});
    // The crossing of the plane, and whether it lies on the ring, computed apart.
    const double t = glm::dot(normal, center - origin) / glm::dot(normal, ray.dir);
    const double r2 = glm::dot(ray.at(t) - center, ray.at(t) - center);
    const bool onRing = t > 0 && r2 < 1.5 * 1.5 - 1e-9 && r2 > 0.25 * 0.25 + 1e-9;
    if (onRing) {
      REQUIRE(hit);
      CHECK(hit->t == Approx(t).epsilon(1e-12));
      CHECK(glm::dot(hit->point - center, normal) == Approx(0).margin(1e-12));
      CHECK(box->min.x <= hit->point.x);
      CHECK(hit->point.x <= box->max.x);
      ++hits;
    } else if (t <= 0 || r2 > 1.5 * 1.5 + 1e-9 || r2 < 0.25 * 0.25 - 1e-9) {
      CHECK_FALSE(hit);
    }
  }
  CHECK(hits > 100);
}

TEST_CASE("a disc is read with and without its hole in both languages", "[disc]") {
  const SceneDesc pov = povray::parsePovRay("#version 3.7;\ndisc { <1, 2, 3>, y, 2 }\ndisc { 0, z, 2, 1 }\n", "s.pov",
                                            povray::PovRayOptions{{}, 320, 240, false});
  REQUIRE(pov.objects.size() == 2);
  CHECK(std::get<DiscDesc>(pov.objects[0].shape).hole == 0);
  CHECK(std::get<DiscDesc>(pov.objects[1].shape).hole == 1);
  const SceneDesc course = parsePov(
      "camera { location <0,0,5> look_at <0,0,0> }\ndisc { <0, 0, 0>, <0, 1, 0>, 2, 0.5 pigment { color rgb <1, 0, 0> } }\n",
      "s.pov");
  REQUIRE(course.objects.size() == 1);
  CHECK(std::get<DiscDesc>(course.objects[0].shape).hole == 0.5);
}

TEST_CASE("a disc without a normal, or with a hole as wide as it, is refused where that is written", "[disc]") {
  CHECK(povFailure("disc { 0, <0, 0, 0>, 1 }\n") == "scene.pov:2:11: error: the disc normal is zero");
  CHECK(povFailure("disc { 0, y, 1, 1 }\n") ==
        "scene.pov:2:17: error: the disc hole radius must be smaller than its radius, found 1");
  CHECK(povFailure("disc { 0, y, 0 }\n") == "scene.pov:2:14: error: the disc radius must be greater than 0, found 0");
  CHECK(courseFailure("disc { <0, 0, 0>, <0, 1, 0>, 1, -1 }") ==
        "s.pov:2:33: error: the disc hole radius must not be negative, found -1");
}
