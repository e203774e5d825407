// A POV-Ray area light's grid and its sampling, against the shares real POV-Ray 3.7 lit a white plane with
// (read back from its pictures: a linear light's points shadowed one by one by the edge of a wall).
#include <catch2/catch.hpp>

#include <cmath>

#include "raytrace/scene/area_light.hpp"

namespace rt {
namespace {

AreaLight linear(int size, int adaptive = -1) {
  AreaDesc d;
  d.axis1 = {2, 0, 0};
  d.axis2 = {0, 0, 0};
  d.size1 = size;
  d.adaptive = adaptive;
  return AreaLight(d);
}

// The share of a light whose first `blocked` points (along axis1) are hidden, and how many points were asked.
float shareWithBlocked(const AreaLight& light, int blocked, int* asked = nullptr) {
  std::vector<Color> grid;
  std::vector<char> known;
  int count = 0;
  const Color c = light.share(
      [&](int i, int) {
        ++count;
        return i < blocked ? Color(0) : Color(1);
      },
      grid, known);
  if (asked) *asked = count;
  return c.r;
}

TEST_CASE("area light: a grid of n points spans each axis end to end; one point sits on the centre", "[light]") {
  const AreaLight l = linear(5);
  const glm::dvec3 c(0, 10, 0), a1(2, 0, 0), a2(0, 0, 0);
  CHECK(l.point(0, 0, c, a1, a2, {}) == glm::dvec3(-1, 10, 0));
  CHECK(l.point(1, 0, c, a1, a2, {}) == glm::dvec3(-0.5, 10, 0));
  CHECK(l.point(4, 0, c, a1, a2, {}) == glm::dvec3(1, 10, 0));
  CHECK(linear(1).point(0, 0, c, a1, a2, {}) == c);
}

TEST_CASE("area light: jitter moves a point within half a cell; circular pulls the square onto the circle",
          "[light]") {
  AreaDesc d;
  d.axis1 = {2, 0, 0};
  d.axis2 = {0, 0, 2};
  d.size1 = d.size2 = 3;
  d.jitter = true;
  const AreaLight jittered(d);
  const glm::dvec3 c(0), a1 = d.axis1, a2 = d.axis2;
  // A cell is half the axis (1 unit): an offset of 0.75 moves the point a quarter of it.
  CHECK(jittered.point(1, 1, c, a1, a2, {0.75f, 0.25f}) == glm::dvec3(0.25, 0, -0.25));
  d.jitter = false;
  d.circular = true;
  const AreaLight round(d);
  // A corner at distance √2 comes in to 1 along its diagonal; the middles of the sides stay.
  const glm::dvec3 corner = round.point(2, 2, c, a1, a2, {});
  CHECK(corner.x == Approx(std::sqrt(0.5)));
  CHECK(corner.z == Approx(std::sqrt(0.5)));
  CHECK(round.point(2, 1, c, a1, a2, {}) == glm::dvec3(1, 0, 0));
}

TEST_CASE("area light: orient turns the axes across the direction to the point, their lengths kept", "[light]") {
  AreaDesc d;
  d.axis1 = {2, 0, 0};
  d.axis2 = {0, 0, 2};
  d.orient = d.circular = true;
  const AreaLight l(d);
  glm::dvec3 a1, a2;
  l.axesToward({0, 0, 0}, {0, 0, 5}, a1, a2);  // along axis2: the axes turn to lie across z
  CHECK(glm::dot(a1, glm::dvec3(0, 0, 1)) == Approx(0).margin(1e-12));
  CHECK(glm::dot(a2, glm::dvec3(0, 0, 1)) == Approx(0).margin(1e-12));
  CHECK(glm::length(a1) == Approx(2));
  CHECK(glm::length(a2) == Approx(2));
  CHECK(glm::dot(a1, a2) == Approx(0).margin(1e-12));
}

TEST_CASE("area light: the share of a partly hidden linear light, as POV-Ray weighs its points", "[light]") {
  // POV-Ray 3.7, linear lights of 3 to 6 points without `adaptive`: the lit fraction with the first k hidden.
  CHECK(shareWithBlocked(linear(3), 1) == 0.75f);
  CHECK(shareWithBlocked(linear(4), 1) == 0.75f);
  CHECK(shareWithBlocked(linear(4), 2) == 0.5f);
  CHECK(shareWithBlocked(linear(5), 1) == 0.875f);
  CHECK(shareWithBlocked(linear(5), 2) == 0.625f);
  CHECK(shareWithBlocked(linear(6), 1) == 0.875f);
  CHECK(shareWithBlocked(linear(6), 2) == 0.625f);
  CHECK(shareWithBlocked(linear(6), 3) == 0.5f);
  // `adaptive 0` as well: the corners differ, so the blocks split down to single cells.
  CHECK(shareWithBlocked(linear(4, 0), 2) == 0.5f);
  CHECK(shareWithBlocked(linear(5, 0), 2) == 0.625f);
}

TEST_CASE("area light: adaptive sampling asks the corners, and splits an even grid as many times as asked",
          "[light]") {
  AreaDesc d;
  d.axis1 = {1, 0, 0};
  d.axis2 = {0, 1, 0};
  d.size1 = d.size2 = 5;
  int asked = 0;
  d.adaptive = 0;
  CHECK(shareWithBlocked(AreaLight(d), 0, &asked) == 1.0f);
  CHECK(asked == 4);  // the manual: "adaptive 0 ... a minimum of 4 rays"
  d.adaptive = 1;
  shareWithBlocked(AreaLight(d), 0, &asked);
  CHECK(asked == 9);
  d.adaptive = 2;
  shareWithBlocked(AreaLight(d), 0, &asked);
  CHECK(asked == 25);
  d.adaptive = -1;  // no `adaptive`: every point
  shareWithBlocked(AreaLight(d), 0, &asked);
  CHECK(asked == 25);
}

}  // namespace
}  // namespace rt
