// The offset policies of spawned rays (spawn.hpp), on hand-made hits with exact answers. Their re-hit
// measurements are in test_stability_spawn.cpp.
#include <catch2/catch.hpp>

#include "raytrace/geometry/spawn.hpp"

using namespace rt;

namespace {

Hit<double> hitAt(glm::dvec3 point, glm::dvec3 normal) {
  Hit<double> hit;
  hit.t = 1;
  hit.point = point;
  hit.normal = normal;
  return hit;
}

}  // namespace

// The course reference's shadow ray: from P + 0.001·N on the side toward the light (the viewer's, for a lit
// point), aimed from there at the light, the segment measured from there.
TEST_CASE("spawn: a course shadow ray starts 0.001 along the normal and is aimed from there", "[spawn]") {
  const glm::dvec3 p(1, 2, 3), light(5, 2, 6);  // light − P = (4, 0, 3)
  for (const glm::dvec3 normal : {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)}) {  // seen from outside or inside
    CAPTURE(normal.z);
    const auto [ray, segment] = spawnRayTo(hitAt(p, normal), light, OffsetPolicy::Course);
    const glm::dvec3 origin(1, 2, 3 + 0.001);
    CHECK(ray.origin == origin);
    CHECK(ray.dir == glm::normalize(light - origin));
    CHECK(ray.dir != glm::normalize(light - p));  // not the direction from P
    CHECK(segment.min == 0);
    CHECK(segment.max == glm::length(light - origin) * (1 - kShadowEpsilon<double>));
  }
}

TEST_CASE("spawn: course secondary rays start 0.001 along the normal on the side they leave by", "[spawn]") {
  const Hit<double> hit = hitAt({1, 2, 3}, {0, 0, 1});
  const glm::dvec3 reflected(0.6, 0, 0.8), refracted(0.6, 0, -0.8);
  const Ray<double> out = spawnRay(hit, reflected, OffsetPolicy::Course);
  CHECK(out.origin == glm::dvec3(1, 2, 3 + 0.001));
  CHECK(out.dir == reflected);
  const Ray<double> in = spawnRay(hit, refracted, OffsetPolicy::Course);
  CHECK(in.origin == glm::dvec3(1, 2, 3 - 0.001));
  CHECK(in.dir == refracted);
}

// The scale-aware policies keep the direction from the hit point: a ray parallel to it, from an origin a few
// ulps off the surface (why: spawnRayTo).
TEST_CASE("spawn: a relative shadow ray keeps the direction from the hit point", "[spawn]") {
  const glm::dvec3 p(1, 2, 3), light(5, 2, 6);
  const auto [ray, segment] = spawnRayTo(hitAt(p, {0, 0, 1}), light, OffsetPolicy::Relative);
  const glm::dvec3 origin = p + kRayEpsilon<double> * 3.0 * glm::dvec3(0, 0, 1);
  CHECK(ray.origin == origin);
  CHECK(ray.dir == glm::normalize(light - p));
  CHECK(segment.max == glm::length(light - origin) * (1 - kShadowEpsilon<double>));
}
