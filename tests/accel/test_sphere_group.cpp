#include <catch2/catch.hpp>

#include <cstring>
#include <limits>
#include <random>

#include "raytrace/accel/sphere_group.hpp"

namespace {

const rt::Material kMaterial;

template <class T> rt::Vec3<T> randomPoint(std::mt19937& rng, double extent) {
  std::uniform_real_distribution<double> pos(-extent, extent);
  return rt::Vec3<T>(pos(rng), pos(rng), pos(rng));
}

// A sphere of the sweep: radii from 1e-3 to 10, far from the origin or near it.
template <class T> rt::Sphere<T> randomSphere(std::mt19937& rng, rt::SphereMethod method, int id) {
  std::uniform_real_distribution<double> exponent(-3, 1);
  return rt::Sphere<T>(randomPoint<T>(rng, id % 3 ? 20 : 2), T(std::pow(10.0, exponent(rng))), method, kMaterial, id);
}

// A ray at the sphere: through its centre, grazing it (perpendicular distance exactly the radius, as far as
// the arithmetic goes), from a point of its surface outward or inward, from inside, or anywhere.
template <class T> rt::Ray<T> rayAt(std::mt19937& rng, const rt::Sphere<T>& s, int kind) {
  const rt::Vec3<T> c = s.center(), side = glm::normalize(randomPoint<T>(rng, 1));
  const rt::Vec3<T> origin = c + randomPoint<T>(rng, 30);
  switch (kind % 6) {
    case 0: return {origin, c - origin};
    case 1: {
      const rt::Vec3<T> dir = glm::normalize(c - origin);
      const rt::Vec3<T> across = glm::normalize(glm::cross(dir, side));
      return {origin + s.radius() * across, dir};
    }
    case 2: return {c + s.radius() * side, side + randomPoint<T>(rng, 0.5)};
    case 3: return {c + s.radius() * side, -side + randomPoint<T>(rng, 0.5)};
    case 4: return {c + T(0.5) * s.radius() * side, randomPoint<T>(rng, 1)};
    default: return {origin, randomPoint<T>(rng, 1)};
  }
}

}  // namespace

TEMPLATE_TEST_CASE("each lane of a sphere group gives Sphere::nearestRoot's and Sphere::meets' answers and bits",
                   "[bvh]", float, double) {
  using T = TestType;
  std::mt19937 rng(2025);
  for (const rt::SphereMethod method : {rt::SphereMethod::Textbook, rt::SphereMethod::Robust}) {
    const bool robust = method == rt::SphereMethod::Robust;
    CAPTURE(robust);
    int hits = 0, missesAfterRoots = 0;  // lanes hit; lanes whose roots are all outside the range
    for (int trial = 0; trial < 20000; ++trial) {
      CAPTURE(trial);
      const int used = 1 + trial % rt::SphereGroup<T>::kSize;
      std::vector<rt::Sphere<T>> spheres;
      rt::SphereGroup<T> group;
      for (int k = 0; k < used; ++k) {
        spheres.push_back(randomSphere<T>(rng, method, trial + k));
        group.set(k, spheres.back(), uint32_t(10 + k));
      }
      const rt::Sphere<T>& target = spheres[size_t(trial) % spheres.size()];
      const rt::Ray<T> ray = rayAt<T>(rng, target, trial / 4);
      rt::Interval<T> range{T(0), std::numeric_limits<T>::infinity()};
      // Some ranges end exactly at a root (excluded) or start there; some start at a shadow ray's offset.
      T t0, t1;
      if (trial % 4 && rt::Sphere<T>::roots(target.center(), target.radius(), robust, ray, t0, t1)) {
        if (trial % 4 == 1) range.max = t1;
        if (trial % 4 == 2) range.min = t0;
        if (trial % 4 == 3) range = {T(1e-4), t1};
      }
      typename rt::SphereGroup<T>::Lanes t;
      const uint32_t met = group.hits(ray, range, t), meets = group.meets(ray, range);
      CHECK(met >> used == 0);
      CHECK(meets >> used == 0);
      for (int k = 0; k < used; ++k) {
        CAPTURE(k);
        const rt::Sphere<T>& s = spheres[size_t(k)];
        T expected;
        const bool hit = rt::Sphere<T>::nearestRoot(s.center(), s.radius(), robust, ray, range, expected);
        REQUIRE(bool(met >> k & 1) == hit);
        REQUIRE(bool(meets >> k & 1) == rt::Sphere<T>::meets(s.center(), s.radius(), robust, ray, range));
        const T lane = t[k];  // a copy: clang gives no address of a vector element
        if (hit) REQUIRE(std::memcmp(&lane, &expected, sizeof(T)) == 0);
        hits += hit;
        missesAfterRoots += !hit && rt::Sphere<T>::roots(s.center(), s.radius(), robust, ray, t0, t1);
        CHECK(group.object[k] == uint32_t(10 + k));
        CHECK(group.id[k] == s.id());
      }
    }
    CHECK(hits > 8000);
    CHECK(missesAfterRoots > 2000);
  }
}
