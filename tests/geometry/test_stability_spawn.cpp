// T3 and T4 of docs/reference/stability.md §2: rays spawned at a hit by the offset policy (spawn.hpp) must never find
// their own surface again. pbrt-v4's bar (shapes_test.cpp, Reintersect): exactly 0 re-hits.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <random>

#include "raytrace/shapes/cylinder.hpp"
#include "raytrace/shapes/plane.hpp"
#include "raytrace/geometry/spawn.hpp"
#include "raytrace/shapes/sphere.hpp"
#include "stability_support.hpp"

namespace rt {
namespace {

enum class ShapeKind { Sphere, Plane, Cylinder };

// A shape of size r (sphere radius; cylinder radius and half-height; for planes the spread of the hits)
// whose hits lie about |pos| from the world origin, and a way to find hits on it from either side.
template <class T> struct Target {
  ShapeKind kind;
  std::unique_ptr<Object<T>> object;
  glm::dvec3 centre;  // sphere or cylinder centre, or the plane's point nearest the hits
  glm::dvec3 normal;  // plane only
  double r;

  Target(ShapeKind k, double radius, double pos, std::mt19937_64& rng) : kind(k), r(radius) {
    centre = pos * test::randomUnit(rng);
    if (kind == ShapeKind::Sphere) {
      object = std::make_unique<Sphere<T>>(Vec3<T>(centre), T(r), SphereMethod::Robust, Material{}, 1);
    } else if (kind == ShapeKind::Cylinder) {
      const glm::dvec3 axis = r * test::randomUnit(rng);
      object = std::make_unique<Cylinder<T>>(Vec3<T>(centre - axis), Vec3<T>(centre + axis), T(r), Material{}, 1);
    } else {
      normal = test::randomUnit(rng);
      const Vec3<T> n(normal);  // the plane as the renderer holds it: rounded unit normal, rounded distance
      object = std::make_unique<Plane<T>>(n, glm::dot(n, Vec3<T>(centre)), Material{}, 1);
    }
  }

  // A point at distance about s from the hit in direction w (on the hit's outer side), moved out further
  // until, rounded to T, it lies on w's side of the tangent plane both exactly and as spawnRayTo() sees it
  // (and, for spheres, strictly outside): the target of a shadow segment. Sphere and cylinder are convex.
  Vec3<T> outside(const Hit<T>& hit, const glm::dvec3& w, double s) const {
    using H = test::WiderT<T>;
    const T side = glm::dot(Vec3<T>(w), hit.normal) > T(0) ? T(1) : T(-1);
    for (;; s *= 2) {
      const Vec3<T> light(glm::dvec3(hit.point) + s * w);
      const test::WideVec<H> fromHit = test::WideVec<H>(light) - test::WideVec<H>(hit.point);
      const test::WideVec<H> fromCentre = test::WideVec<H>(light) - test::WideVec<H>(Vec3<T>(centre));
      const bool above = fromHit.dot(test::WideVec<H>(hit.normal)) * H(side) > H(0) &&
                         glm::dot(glm::normalize(light - hit.point), hit.normal) * side > T(0);
      const bool out = kind != ShapeKind::Sphere || fromCentre.dot(fromCentre) > H(r) * H(r);
      if (above && out) return light;
    }
  }

  // A hit from a ray that starts outside or inside (sphere, cylinder) or on either side (plane) of the surface.
  std::optional<Hit<T>> randomHit(std::mt19937_64& rng) const {
    std::uniform_real_distribution<double> u(0, 1);
    const bool solid = kind != ShapeKind::Plane;
    const glm::dvec3 from = solid ? centre + (u(rng) < 0.5 ? 4.0 : 0.5) * r * test::randomUnit(rng)
                                   : centre + r * (test::randomUnit(rng) + (u(rng) < 0.5 ? 2.0 : -2.0) * normal);
    glm::dvec3 to = centre + 0.9 * r * std::cbrt(u(rng)) * test::randomUnit(rng);
    if (!solid) to -= glm::dot(to - centre, normal) * normal;
    return object->intersect(Ray<T>{Vec3<T>(from), Vec3<T>(glm::normalize(to - from))}, Interval<T>{});
  }
};

// The spacing of T's values at |pos|.
template <class T> double ulp(double pos) {
  const T p = T(pos);
  return double(std::nextafter(p, std::numeric_limits<T>::infinity()) - p);
}

struct Rehits {
  int hits = 0;      // surface points tried
  int leaving = 0;   // rays leaving by the outer side of a solid or either side of a plane that hit it again
  int entering = 0;  // rays into a solid that did not reach its far side first (re-hit near side or escaped);
                     // tried only if offsets (up to 256 ulps) fit inside it
  int segments = 0;  // shadow segments to a point outside that the surface itself occluded
};

// For each of `hits` surface points: one ray leaving, one entering (solids), one segment to a point outside.
// Below 8 ulps of the position a shape is not representable as a shape at all: callers skip those cells
// (docs/reference/stability.md T3).
template <class T>
Rehits rehits(ShapeKind kind, double r, double pos, OffsetPolicy policy, int hits, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Rehits out;
  for (int i = 0; i < hits; ++i) {
    const Target<T> target(kind, r, pos, rng);
    const auto hit = target.randomHit(rng);
    if (!hit) continue;
    ++out.hits;
    const glm::dvec3 n(hit->normal);
    glm::dvec3 w = test::randomUnit(rng);
    if (glm::dot(w, n) < 0) w = -w;
    if (kind == ShapeKind::Plane && u(rng) < 0.5) w = -w;  // a plane has two outer sides

    if (target.object->intersect(spawnRay(*hit, Vec3<T>(w), policy), Interval<T>{})) ++out.leaving;

    if (kind != ShapeKind::Plane && r >= 256 * ulp<T>(pos)) {
      const Vec3<T> in(-w);
      const auto exit = target.object->intersect(spawnRay(*hit, in, policy), Interval<T>{});
      if (!exit || !(glm::dot(exit->normal, in) > T(0))) ++out.entering;
    }

    const Vec3<T> light = target.outside(*hit, w, r * std::pow(10.0, 3 * u(rng) - 2));
    const auto [ray, range] = spawnRayTo(*hit, light, policy);
    if (target.object->intersect(ray, range)) ++out.segments;
  }
  return out;
}

// Re-hits of rays leaving unit spheres or planes at `elevation` degrees above the surface (T4).
template <class T>
int grazingRehits(ShapeKind kind, double pos, double elevation, OffsetPolicy policy, int hits, uint64_t seed) {
  std::mt19937_64 rng(seed);
  int count = 0;
  for (int i = 0; i < hits; ++i) {
    const Target<T> target(kind, 1.0, pos, rng);
    const auto hit = target.randomHit(rng);
    if (!hit) continue;
    const glm::dvec3 n = glm::dvec3(hit->normal);
    const Vec3<T> w(test::atElevation(n, glm::radians(elevation), rng));
    if (target.object->intersect(spawnRay(*hit, w, policy), Interval<T>{})) ++count;
  }
  return count;
}

}  // namespace

// T3: the production policy, Relative, gives exactly zero re-hits on every representable cell, in float and
// double, for rays leaving, rays entering and shadow segments, on spheres, planes and capped cylinders
// (side and cap hits alike, about a third of the cylinder's hits are on its caps). Wächter–Binder, the
// chart's other scale-aware policy, meets the same bar on spheres and planes. Not on capped cylinders: its
// steps are ulps of each coordinate, so the offset is not parallel to n where the coordinates differ in
// magnitude, and near a rim an entering ray's origin slips out through the cap (float, |p| = 1e4, r = 1:
// 322 of 30000 entering rays).
TEMPLATE_TEST_CASE("scale-aware offsets never re-hit their own surface", "[stability][spawn]", float, double) {
  const OffsetPolicy policy = GENERATE(OffsetPolicy::Relative, OffsetPolicy::WaechterBinder);
  const ShapeKind kind = GENERATE(ShapeKind::Sphere, ShapeKind::Plane, ShapeKind::Cylinder);
  const double r = GENERATE(1e-3, 1.0, 1e3);
  const double pos = GENERATE(0.0, 1e2, 1e4, 1e6);
  const uint64_t seed = 0x5EED0100;
  if (r < 8 * ulp<TestType>(pos)) return;
  if (policy == OffsetPolicy::WaechterBinder && kind == ShapeKind::Cylinder) return;
  CAPTURE(int(policy), int(kind), r, pos, seed);
  const Rehits e = rehits<TestType>(kind, r, pos, policy, 20000, seed);
  CHECK(e.hits == 20000);
  CHECK(e.leaving == 0);
  CHECK(e.entering == 0);
  CHECK(e.segments == 0);
}

// The fixed epsilons are scale-blind (docs/reference/stability.md F4): at |p| = 1e6 in float both lose rays to their
// own surface, which is what the measurement above would catch in the production policy.
TEST_CASE("fixed epsilons re-hit their own surface far from the origin in float", "[stability][spawn]") {
  const OffsetPolicy policy = GENERATE(OffsetPolicy::Course, OffsetPolicy::FixedNormal);
  const uint64_t seed = 0x5EED0102;
  CAPTURE(int(policy), seed);
  const Rehits e = rehits<float>(ShapeKind::Sphere, 1.0, 1e6, policy, 3000, seed);
  CHECK(e.leaving + e.entering > 300);
}

// T4: rays leaving at grazing elevations. A normal offset does not care about the angle; a t-epsilon along
// the ray (the earlier course reference's P + 0.001·d) does (docs/reference/stability.md F5).
TEMPLATE_TEST_CASE("relative offsets survive grazing spawned rays", "[stability][spawn]", float, double) {
  const ShapeKind kind = GENERATE(ShapeKind::Sphere, ShapeKind::Plane);
  const double pos = GENERATE(1e2, 1e4);
  const double elevation = GENERATE(90.0, 10.0, 1.0, 0.1, 0.01);
  const uint64_t seed = 0x5EED0103;
  CAPTURE(int(kind), pos, elevation, seed);
  CHECK(grazingRehits<TestType>(kind, pos, elevation, OffsetPolicy::Relative, 2000, seed) == 0);
}

// The course's 0.001 along the normal, inside the course tier's domain (coordinates up to 1e3, scene/arithmetic.hpp).
TEST_CASE("the course's normal offset survives grazing spawned rays in its domain", "[stability][spawn]") {
  const ShapeKind kind = GENERATE(ShapeKind::Sphere, ShapeKind::Plane);
  const double pos = GENERATE(1e2, 1e3);
  const double elevation = GENERATE(90.0, 1.0, 0.01);
  const uint64_t seed = 0x5EED0104;
  CAPTURE(int(kind), pos, elevation, seed);
  CHECK(grazingRehits<float>(kind, pos, elevation, OffsetPolicy::Course, 2000, seed) == 0);
}

}  // namespace rt
