// A pointed cone's side near its apex (docs/accuracy.md, "Choosing the arithmetic"): there the quadratic's
// coefficients are tiny differences of nearly equal terms, and float must give double's answer to the same
// rounded ray.
#include <catch2/catch.hpp>

#include <random>

#include "raytrace/shapes/cone.hpp"

namespace rt {

TEST_CASE("near a pointed cone's apex, float hits where double hits", "[stability][cone]") {
  // Radius 1 at y = 0 narrowing to a point at y = 2, seen from 8 units away, as edge_cone_apex.pov does.
  const Cone<float> narrow(Vec3<float>(0), 1.0f, Vec3<float>(0, 2, 0), 0.0f, Material{}, 1);
  const Cone<double> wide(glm::dvec3(0), 1.0, glm::dvec3(0, 2, 0), 0.0, Material{}, 1);
  const Vec3<float> eye(0.3f, 1.6f, 8.0f);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> near(-0.02f, 0.02f);
  int hits = 0, disagree = 0;
  float worst = 0;
  for (int i = 0; i < 20000; ++i) {
    // Aimed within 0.02 of the apex, where the cone's radius is at most 0.01.
    const Vec3<float> dir = glm::normalize(Vec3<float>(near(rng), 2 + near(rng), near(rng)) - eye);
    const auto f = narrow.intersect(Ray<float>{eye, dir}, Interval<float>{});
    const auto d = wide.intersect(Ray<double>{glm::dvec3(eye), glm::dvec3(dir)}, Interval<double>{});
    if (bool(f) != bool(d)) {
      ++disagree;
      continue;
    }
    if (!f) continue;
    ++hits;
    worst = std::max(worst, std::abs(f->t - float(d->t)));
  }
  CAPTURE(hits, disagree, worst);
  CHECK(hits > 2000);
  CHECK(disagree == 0);
  CHECK(worst < 1e-5f);  // a few ulps of t ≈ 8, where the textbook float coefficients were off by 2e-3
}

}  // namespace rt
