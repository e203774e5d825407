// T8 of docs/reference/stability.md §2: refraction directions across all angles of incidence: total internal reflection
// exactly past the critical angle, unit results on the far side, Snell's law kept.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "raytrace/render/shading.hpp"

namespace rt {

// θ from 0° to 89.9° in 0.1° steps, η ∈ {1.5, 2.42} entering and leaving, and 1/1.5 (a denser outside).
TEMPLATE_TEST_CASE("refraction directions are unit, on the far side, and TIR only past the critical angle",
                   "[stability][shading]", float, double) {
  using T = TestType;
  const float ior = GENERATE(1.5f, 2.42f, 1 / 1.5f);
  const bool leaving = GENERATE(false, true);
  const Vec3<T> n(0, 0, 1);  // outward
  const double ratio = leaving ? double(ior) : 1 / double(ior);  // η of Snell's law n₁/n₂
  CAPTURE(ior, leaving);
  for (int step = 0; step < 900; ++step) {
    const double theta = glm::radians(step / 10.0);
    CAPTURE(step);
    // Coming from outside the ray travels against n, from inside along it.
    const Vec3<T> d(std::sin(theta), 0, leaving ? std::cos(theta) : -std::cos(theta));
    const auto w = refractDirection(d, n, ior);
    const double sinOut = ratio * std::sin(theta);  // Snell: sin of the refracted angle
    if (std::abs(sinOut - 1) < 2e-3) continue;  // within a step of the critical angle
    REQUIRE(bool(w) == (sinOut < 1));
    if (!w) continue;
    CHECK(std::abs(double(glm::length(*w)) - 1) <= 4 * std::numeric_limits<T>::epsilon());
    CHECK((leaving ? w->z > T(0) : w->z < T(0)));  // it crossed the surface
    CHECK(std::abs(double(w->x) - sinOut) <= 1e-5);
  }
}

}  // namespace rt
