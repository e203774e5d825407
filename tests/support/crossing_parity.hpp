// Test support for the shapes whose inside is the even-odd rule (prism, lathe, sor): along a ray from outside, every
// surface it crosses flips inside(), so between the k-th and (k+1)-th hit the ray is inside iff k is odd.
#pragma once

#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "raytrace/shapes/object.hpp"

namespace rt::test {

// `rays` seeded rays from a sphere around the box lo..hi, each aimed at a random point of the box; returns how many
// stretches between successive hits disagree with inside() at their middle. Stretches shorter than a millionth of the
// box are skipped: a grazing ray's two hits may be one point.
inline int parityMismatches(const Object<double>& object, const glm::dvec3& lo, const glm::dvec3& hi, unsigned seed,
                            int rays = 400) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> normal(0, 1);
  const glm::dvec3 center = (lo + hi) / 2.0;
  const double size = glm::length(hi - lo);
  int mismatches = 0;
  for (int r = 0; r < rays; ++r) {
    const glm::dvec3 origin = center + 2 * size * glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
    const glm::dvec3 target = lo + glm::dvec3(unit(rng), unit(rng), unit(rng)) * (hi - lo);
    const Ray<double> ray{origin, glm::normalize(target - origin)};
    std::vector<double> hits;
    for (double from = 0; hits.size() < 64;) {
      const auto hit = object.intersect(ray, Interval<double>{from, 1e30});
      if (!hit) break;
      hits.push_back(hit->t);
      from = hit->t + 1e-9 * size;
    }
    hits.push_back(4 * size);  // past the shape: outside again
    for (size_t k = 0; k + 1 < hits.size(); ++k) {
      if (hits[k + 1] - hits[k] < 1e-6 * size) continue;
      const bool inside = object.inside(ray.at((hits[k] + hits[k + 1]) / 2));
      if (inside != (k % 2 == 0)) {
        UNSCOPED_INFO("ray " << r << " stretch " << k << " of " << hits.size() - 1);
        ++mismatches;
      }
    }
  }
  return mismatches;
}

}  // namespace rt::test
