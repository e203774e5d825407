// The error bounds chooseArithmetic() relies on (docs/accuracy.md, "Choosing the arithmetic"), measured at
// their edges: each bound holds for every ray and is not loose by more than a small factor, and each tier
// changes exactly where its bound crosses the limit.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "raytrace/scene/arithmetic.hpp"
#include "raytrace/shapes/sphere.hpp"
#include "stability_support.hpp"

namespace rt {
namespace {

// The largest distance from the true surface of the float hit point o + t·d, over rays from D away whose
// impact parameter is spread up to the rim (0 … 0.99999 r), and whether every ray that hit or missed by
// mistake passed within `band` of the rim.
struct Measured {
  long double worst = 0;
  bool flipsInBand = true;
};
Measured measure(SphereMethod method, double D, double r, double band) {
  const Sphere<float> sphere(Vec3<float>(0), float(r), method, Material{}, 1);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> impact(0, 0.99999), turn(0, 2 * glm::pi<double>());
  Measured m;
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 eye = D * test::randomUnit(rng);
    glm::dvec3 e1, e2;
    test::frame(-eye / D, e1, e2);
    const double b = impact(rng) * r, a = turn(rng);
    const glm::dvec3 aim = b * (std::cos(a) * e1 + std::sin(a) * e2);
    const Vec3<float> o(eye), d(glm::normalize(aim - eye));
    const auto hit = sphere.intersect(Ray<float>{o, d}, Interval<float>{});
    const long double exact = test::referenceSphereT(o, d, Vec3<float>(0), float(r));
    if (bool(hit) != (exact > 0)) {
      const glm::dvec3 f = -glm::dvec3(o), dd = glm::normalize(glm::dvec3(d));
      const double miss = glm::length(f - glm::dot(f, dd) * dd);
      m.flipsInBand = m.flipsInBand && std::abs(miss - r) <= band;
      continue;
    }
    if (!hit) continue;
    const long double px = (long double)o.x + (long double)hit->t * d.x;
    const long double py = (long double)o.y + (long double)hit->t * d.y;
    const long double pz = (long double)o.z + (long double)hit->t * d.z;
    m.worst = std::max(m.worst, std::abs(std::sqrt(px * px + py * py + pz * pz) - (long double)r));
  }
  return m;
}

rt::SceneDesc oneSphere(double D, double r) {
  rt::SceneDesc s;
  s.camera.location = {0, 0, D};
  s.camera.lookAt = {0, 0, 0};
  ObjectDesc o;
  o.shape = SphereDesc{{0, 0, 0}, r};
  s.objects.push_back(o);
  return s;
}

}  // namespace

TEST_CASE("the textbook quadratic's error stays within 8uD²/r + 4uD", "[stability][tiers]") {
  for (const double R : {10.0, 100.0, 1000.0}) {
    const double r = 0.5, D = R * r, bound = textbookSphereError(D, r);
    const Measured m = measure(SphereMethod::Textbook, D, r, bound);
    CAPTURE(R, double(m.worst), bound);
    CHECK(m.worst <= bound);
    CHECK(m.worst >= bound / 20);  // the bound is the size of the real error, not a loose guess
    CHECK(m.flipsInBand);
  }
}

TEST_CASE("the robust test's error stays within 9uD", "[stability][tiers]") {
  for (const double R : {10.0, 1000.0, 10000.0}) {
    const double r = 0.5, D = R * r, bound = robustSphereError(D);
    const Measured m = measure(SphereMethod::Robust, D, r, bound);
    CAPTURE(R, double(m.worst), bound);
    CHECK(m.worst <= bound);
    CHECK(m.worst >= bound / 20);
    CHECK(m.flipsInBand);
  }
}

// One sphere at R = 20 (its hit error, 1e-4, well inside the offset): the textbook error grows with the image
// width, which sets where it reaches kVisiblePixels, and the course tier must stop there.
TEST_CASE("the course tier stops where a sphere's error reaches a quarter pixel", "[stability][tiers]") {
  const SceneDesc s = oneSphere(10, 0.5);
  const double perPixel = tierDomain(s, View{1, 1}).textbookPixels;  // scales with the width over height
  REQUIRE(perPixel > 0);
  const auto at = [&](double share) {
    const int width = int(kVisiblePixels / perPixel * share);
    const View v{width, width};
    CAPTURE(width, tierDomain(s, v).textbookPixels);
    return chooseArithmetic(s, {}, v);
  };
  CHECK(at(0.95).tier == Tier::Course);
  CHECK(at(1.05).tier == Tier::Float);
  CHECK(at(1.05).sphere == SphereMethod::Robust);
}

// A sphere over a floor and a light lowered toward the horizon: the fixed offset moves shadow edges by
// 0.001·tan φ, and the course tier stops once that reaches kVisiblePixels.
TEST_CASE("the course tier stops where the offset moves a shadow a quarter pixel", "[stability][tiers]") {
  const auto scene = [](double lightHeight) {
    SceneDesc s = oneSphere(10, 1);
    s.camera.location = {0, 3, 10};
    ObjectDesc floor;
    floor.shape = PlaneDesc{{0, 1, 0}, -1.5};
    floor.material.diffuse = Color(0.8f);
    s.objects.push_back(floor);
    s.lights.push_back(LightDesc{{30, lightHeight, 0}, Color(1)});
    return s;
  };
  double high = 40, low = 0.5;  // the shift grows as the light goes down
  REQUIRE(tierDomain(scene(high), {}).offsetShadowPixels < kVisiblePixels);
  REQUIRE(tierDomain(scene(low), {}).offsetShadowPixels > kVisiblePixels);
  for (int i = 0; i < 40; ++i) {
    const double mid = (high + low) / 2;
    (tierDomain(scene(mid), {}).offsetShadowPixels < kVisiblePixels ? high : low) = mid;
  }
  CHECK(chooseArithmetic(scene(high * 1.001)).tier == Tier::Course);
  CHECK(chooseArithmetic(scene(low * 0.999)).tier == Tier::Float);
}

TEST_CASE("the course tier needs twice the offset between spheres", "[stability][tiers]") {
  const auto pair = [](double gap) {
    SceneDesc s = oneSphere(10, 1);
    ObjectDesc o;
    o.shape = SphereDesc{{2 + gap, 0, 0}, 1};
    s.objects.push_back(o);
    return chooseArithmetic(s).tier;
  };
  CHECK(pair(2.1 * kCourseEpsilon) == Tier::Course);
  CHECK(pair(1.9 * kCourseEpsilon) == Tier::Float);
  CHECK(pair(0) == Tier::Float);
  CHECK(pair(-0.5) == Tier::Float);  // overlapping
}

}  // namespace rt
