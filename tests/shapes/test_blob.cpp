#include <cmath>
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/shapes/blob.hpp"
#include "shape_oracle.hpp"

using namespace rt;

namespace {

const Material kMaterial{};

std::unique_ptr<Object<double>> blob(double threshold, std::vector<BlobComponent> components) {
  BlobDesc d;
  d.threshold = threshold;
  d.components = std::move(components);
  return d.make<double>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
}

BlobComponent ball(glm::dvec3 c, double r, double s) { return {c, c, r, s, false, {}}; }

std::optional<Hit<double>> shoot(const Object<double>& o, glm::dvec3 origin, glm::dvec3 dir) {
  return o.intersect(Ray<double>{origin, dir}, Interval<double>{});
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

// One component's surface is where s·(1 − d²/R²)² = t: d = R·√(1 − √(t/s)).
TEST_CASE("a blob of one sphere is the sphere where its density equals the threshold", "[blob]") {
  const auto b = blob(0.25, {ball({0, 0, 0}, 2, 1)});
  const double r = 2 * std::sqrt(0.5);
  const auto hit = shoot(*b, {0, 0, -5}, {0, 0, 1});
  REQUIRE(hit);
  CHECK(hit->t == Approx(5 - r).epsilon(1e-12));
  CHECK(hit->normal.z == Approx(-1).epsilon(1e-12));
  const auto out = b->intersect(Ray<double>{{0, 0, -5}, {0, 0, 1}}, Interval<double>{hit->t, 100});
  REQUIRE(out);
  CHECK(out->t == Approx(5 + r).epsilon(1e-12));
  CHECK(b->inside({0, 0, 0}));
  CHECK_FALSE(b->inside({0, 1.5, 0}));
  CHECK_FALSE(shoot(*b, {0, 1.5, -5}, {0, 0, 1}));
}

TEST_CASE("a cylinder component is a capsule: its side about the axis, its caps about the ends", "[blob]") {
  const auto b = blob(0.25, {BlobComponent{{0, -1, 0}, {0, 1, 0}, 1, 1, true, {}}});
  const double r = std::sqrt(0.5);
  const auto side = shoot(*b, {-5, 0.3, 0}, {1, 0, 0});
  REQUIRE(side);
  CHECK(side->t == Approx(5 - r).epsilon(1e-12));
  CHECK(side->normal.x == Approx(-1).epsilon(1e-12));
  // Half a unit past the end the cap's ball of radius r meets the line x at ±√(r² − 0.25) = ±0.5.
  const auto cap = shoot(*b, {-5, 1.5, 0}, {1, 0, 0});
  REQUIRE(cap);
  CHECK(cap->t == Approx(4.5).epsilon(1e-12));
  const auto top = shoot(*b, {0, 5, 0}, {0, -1, 0});
  REQUIRE(top);
  CHECK(top->t == Approx(4 - r).epsilon(1e-12));
}

TEST_CASE("a component's transforms stretch its field: a scaled sphere is an ellipsoid", "[blob]") {
  BlobComponent c = ball({0, 0, 0}, 1, 1);
  c.transforms = {{TransformStep::Kind::Scale, {3, 1, 1}}};
  const auto b = blob(0.25, {c});
  const double r = std::sqrt(0.5);
  const auto hit = shoot(*b, {-5, 0, 0}, {1, 0, 0});
  REQUIRE(hit);
  CHECK(hit->t == Approx(5 - 3 * r).epsilon(1e-12));
  const auto box = b->bounds();
  REQUIRE(box);
  CHECK(box->max.x == Approx(3));
}

TEST_CASE("blob sweeps: crossings against inside(), with attracting and repelling components", "[blob]") {
  const auto b = blob(0.6, {ball({0.75, 0, 0}, 1, 1), ball({-0.375, 0.65, 0}, 1, 1), ball({-0.375, -0.65, 0}, 1, 1),
                            ball({0, 0, 0.5}, 0.6, -1), BlobComponent{{-1, 0, -1}, {1, 0.5, 1}, 0.5, 1, true, {}}});
  test::paritySweep<double>(*b, glm::dvec3(-1.6), glm::dvec3(1.6), 1e-6, 30);
  const auto sturm = [] {
    BlobDesc d;
    d.threshold = 0.5;
    d.components = {ball({0, 0, 0}, 1, 1), ball({0.8, 0, 0}, 1, 2)};
    d.sturm = true;
    return d.make<double>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
  }();
  test::paritySweep<double>(*sturm, glm::dvec3(-1.5), glm::dvec3(2), 1e-6, 31);
}

TEST_CASE("a blob is read with its threshold, strengths, old components and component transforms", "[blob]") {
  const SceneDesc s = povScene(
      "blob { threshold 0.6 sphere { <1, 0, 0>, 1, strength 2 scale 2 } cylinder { 0, y, 0.5, -1 }\n"
      "  component 1, 2, <0, 0, 3> sturm hierarchy off pigment { rgb 1 } }\n");
  const auto& b = std::get<BlobDesc>(s.objects.at(0).shape);
  CHECK(b.threshold == 0.6);
  REQUIRE(b.components.size() == 3);
  CHECK(b.components[0].strength == 2);
  CHECK(b.components[0].transforms.size() == 1);
  CHECK(b.components[1].cylinder);
  CHECK(b.components[1].strength == -1);
  CHECK(b.components[2].a == glm::dvec3(0, 0, 3));
  CHECK(b.components[2].radius == 2);
  CHECK(b.sturm);
}

TEST_CASE("bad blobs are refused where they go wrong", "[blob]") {
  CHECK(povFailure("blob { threshold 0 sphere { 0, 1, 1 } }\n") ==
        "scene.pov:2:18: error: the blob threshold must be greater than 0, found 0");
  CHECK(povFailure("blob { threshold 0.5 }\n") ==
        "scene.pov:2:8: error: expected a sphere or cylinder component inside 'blob'");
  CHECK(povFailure("blob { sphere { 0, 1, 1 pigment { rgb 1 } } }\n") ==
        "scene.pov:2:25: error: 'pigment in a blob's sphere' is not supported yet");
  CHECK(povFailure("blob { cylinder { 0, y, 1 } }\n") == "scene.pov:2:8: error: 'cylinder' needs the blob component strength");
  try {
    parsePov("camera { location <0,0,5> look_at <0,0,0> }\nblob { threshold 1 }\n", "s.pov");
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(std::string(e.what()) == "s.pov:2:8: error: 'blob' is read only in POV-Ray 3.7 scenes");
  }
}
