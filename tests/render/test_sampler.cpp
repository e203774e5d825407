#include <cmath>
#include <functional>
#include <set>
#include <vector>

#include <catch2/catch.hpp>

#include "raytrace/render/sampler.hpp"

using namespace rt;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The chi-square value that a statistic with `dof` degrees of freedom exceeds with probability 1e-4, by the
// Wilson-Hilferty approximation (z = 3.719 is the standard normal's 1e-4 upper quantile).
double chiSquareCritical(int dof) {
  const double k = dof, z = 3.719;
  const double c = 1 - 2 / (9 * k) + z * std::sqrt(2 / (9 * k));
  return k * c * c * c;
}

// Pearson's chi-square of directions, relative to the frame (t, b, n), in kTheta × kPhi bins of (θ, φ) against
// the cosine density cos θ / π: a bin [θ0, θ1] × [φ0, φ1] holds (sin²θ1 − sin²θ0)(φ1 − φ0) / (2π) of them.
// Every bin expects at least 5 (the test's rule of thumb) at the sizes used below.
constexpr int kTheta = 10, kPhi = 20;
double chiSquare(const std::function<glm::dvec3(int)>& direction, int count) {
  std::vector<double> observed(kTheta * kPhi, 0);
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 d = direction(i);
    const double theta = std::acos(std::min(1.0, std::max(-1.0, d.z)));
    const double phi = std::atan2(d.y, d.x) + kPi;
    const int a = std::min(kTheta - 1, int(theta / (kPi / 2) * kTheta));
    const int b = std::min(kPhi - 1, int(phi / (2 * kPi) * kPhi));
    REQUIRE(d.z >= 0);
    observed[size_t(a * kPhi + b)] += 1;
  }
  double chi = 0;
  for (int a = 0; a < kTheta; ++a) {
    const double s0 = std::sin(a * kPi / 2 / kTheta), s1 = std::sin((a + 1) * kPi / 2 / kTheta);
    const double expected = count * (s1 * s1 - s0 * s0) / kPhi;
    REQUIRE(expected >= 5);
    for (int b = 0; b < kPhi; ++b) {
      const double o = observed[size_t(a * kPhi + b)];
      chi += (o - expected) * (o - expected) / expected;
    }
  }
  return chi;
}

constexpr int kDirections = 200000;

}  // namespace

TEST_CASE("Cosine-weighted hemisphere samples follow cos θ / π (chi-square goodness of fit)", "[sampler]") {
  const double critical = chiSquareCritical(kTheta * kPhi - 1);
  SECTION("independent samples") {
    const double chi = chiSquare(
        [](int i) { return glm::dvec3(cosineHemisphere<double>(uniformPair(childKey(mix64(1), uint64_t(i))))); },
        kDirections);
    CAPTURE(chi, critical);
    CHECK(chi < critical);
  }
  SECTION("stratified sets of 64, as the renderer gathers them") {
    const Strata strata = strataFor(64);
    const double chi = chiSquare(
        [&](int i) {
          const uint64_t set = childKey(mix64(2), uint64_t(i / 64));
          return glm::dvec3(cosineHemisphere<double>(stratified(strata, i % 64, uniformPair(childKey(set, uint64_t(i % 64))))));
        },
        kDirections);
    CAPTURE(chi, critical);
    CHECK(chi < critical);
  }
  SECTION("the test can fail: uniformly distributed directions are rejected") {
    // Uniform on the hemisphere: cos θ = u, the density 1 / (2π).
    const double chi = chiSquare(
        [](int i) {
          const glm::vec2 uv = uniformPair(childKey(mix64(3), uint64_t(i)));
          const double z = uv.x, r = std::sqrt(1 - z * z), phi = 2 * kPi * uv.y;
          return glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
        },
        kDirections);
    CAPTURE(chi, critical);
    CHECK(chi > 10 * critical);
  }
}

TEST_CASE("Directions turned around a normal keep their angle to it and their distribution", "[sampler]") {
  const glm::dvec3 normals[] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, glm::normalize(glm::dvec3(1, -2, 0.5)),
                                glm::normalize(glm::dvec3(1e-9, 0, -1))};
  for (const glm::dvec3& n : normals) {
    CAPTURE(n.x, n.y, n.z);
    // The frame's images of x, y and z are orthonormal and z goes to n.
    const glm::dvec3 t = aroundNormal(glm::dvec3(1, 0, 0), n), b = aroundNormal(glm::dvec3(0, 1, 0), n);
    CHECK_THAT(glm::dot(t, b), Catch::Matchers::WithinAbs(0, 1e-12));
    CHECK_THAT(glm::dot(t, n), Catch::Matchers::WithinAbs(0, 1e-12));
    CHECK_THAT(glm::length(t), Catch::Matchers::WithinAbs(1, 1e-12));
    CHECK_THAT(glm::length(b), Catch::Matchers::WithinAbs(1, 1e-12));
    CHECK_THAT(glm::dot(glm::cross(t, b), n), Catch::Matchers::WithinAbs(1, 1e-12));
    // Pulled back into the frame, the turned samples pass the same test.
    const double chi = chiSquare(
        [&](int i) {
          const glm::dvec3 d = aroundNormal(cosineHemisphere<double>(uniformPair(childKey(mix64(4), uint64_t(i)))), n);
          return glm::dvec3(glm::dot(d, t), glm::dot(d, b), glm::dot(d, n));
        },
        kDirections / 4);
    CHECK(chi < chiSquareCritical(kTheta * kPhi - 1));
  }
}

TEST_CASE("Sample counts split into strata of one sample each", "[sampler]") {
  CHECK(strataFor(64).rows == 8);
  CHECK(strataFor(64).cols == 8);
  CHECK(strataFor(16).rows == 4);
  CHECK(strataFor(12).rows == 3);
  CHECK(strataFor(12).cols == 4);
  CHECK(strataFor(7).rows == 1);
  CHECK(strataFor(7).cols == 7);
  CHECK(strataFor(1).rows == 1);
  for (int n : {1, 2, 7, 12, 16, 18, 64, 100, 256}) {
    const Strata s = strataFor(n);
    CAPTURE(n);
    REQUIRE(s.rows * s.cols == n);
    // Each stratum receives exactly one of the n samples, whatever the jitter.
    for (uint64_t set = 0; set < 20; ++set) {
      std::set<int> hit;
      for (int i = 0; i < n; ++i) {
        const glm::vec2 p = stratified(s, i, uniformPair(childKey(set, uint64_t(i))));
        REQUIRE(p.x >= 0);
        REQUIRE(p.x < 1);
        REQUIRE(p.y >= 0);
        REQUIRE(p.y < 1);
        hit.insert(int(p.x * float(s.rows)) * s.cols + int(p.y * float(s.cols)));
      }
      CHECK(hit.size() == size_t(n));
    }
  }
}

TEST_CASE("Random numbers are a function of their key alone, and neighbouring keys are unrelated", "[sampler]") {
  CHECK(pixelKey(0, 3, 4, 0) == pixelKey(0, 3, 4, 0));
  CHECK(pixelKey(0, 3, 4, 0) != pixelKey(1, 3, 4, 0));
  CHECK(pixelKey(0, 3, 4, 0) != pixelKey(0, 4, 3, 0));
  CHECK(pixelKey(0, 3, 4, 0) != pixelKey(0, 3, 4, 1));
  // Keys of consecutive pixels and samples: the mean of their numbers is ½ within 5 standard errors, and their
  // first numbers are uncorrelated with the next pixel's.
  double sum = 0, product = 0;
  const int count = 100000;
  for (int i = 0; i < count; ++i) {
    const glm::vec2 a = uniformPair(childKey(pixelKey(0, i % 317, i / 317, 0), 0));
    const glm::vec2 b = uniformPair(childKey(pixelKey(0, i % 317 + 1, i / 317, 0), 0));
    sum += a.x + a.y;
    product += (a.x - 0.5) * (b.x - 0.5);
  }
  const double sd = std::sqrt(1.0 / 12);
  CHECK(std::abs(sum / (2 * count) - 0.5) < 5 * sd / std::sqrt(2.0 * count));
  CHECK(std::abs(product / count) < 5 * sd * sd / std::sqrt(double(count)));
}
