// The random numbers of Monte Carlo global illumination (docs/gi.md): counter-based, so that a sample's numbers
// depend only on where it is in the image (pixel, sub-sample, the path of gather samples that led to it, the
// seed), never on which thread or in which order it is computed. Also the stratified cosine-weighted hemisphere
// that the course gathers indirect light with (docs/reference/csc473.md §c.14).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/gtc/constants.hpp>

#include "raytrace/geometry/math.hpp"

namespace rt {

// SplitMix64's output function (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", 2014):
// a bijection of 64-bit words whose outputs for consecutive inputs pass BigCrush.
constexpr uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// A key extended by one more coordinate: the key of a child (a sample index, a branch) from its parent's.
constexpr uint64_t childKey(uint64_t key, uint64_t index) {
  return mix64(key + 0x9E3779B97F4A7C15ull * (index + 1));
}

// The key of sub-sample `sample` of pixel (x, y) under `seed`: the root of every random number of that eye ray.
constexpr uint64_t pixelKey(uint64_t seed, int x, int y, int sample) {
  return childKey(childKey(childKey(mix64(seed), uint64_t(uint32_t(x))), uint64_t(uint32_t(y))),
                  uint64_t(uint32_t(sample)));
}

// Two independent numbers uniform in [0, 1) from one key: the top and bottom 24 bits of its hash, exactly
// representable in float.
inline glm::vec2 uniformPair(uint64_t key) {
  const uint64_t bits = mix64(key);
  constexpr float kScale = 1.0f / float(1u << 24);
  return {float(bits >> 40) * kScale, float(bits & 0xFFFFFFu) * kScale};
}

// How n samples split into rows × cols strata of the unit square, one sample each: rows the largest divisor of
// n not above √n, so a square number gives a square grid (64 → 8 × 8) and a prime a single row of n.
struct Strata {
  int rows = 1, cols = 1;
};
Strata strataFor(int n);

// Sample i of a stratified set of rows × cols over the unit square: stratum (i / cols, i % cols), jittered by
// `jitter` ∈ [0, 1)².
inline glm::vec2 stratified(const Strata& s, int i, glm::vec2 jitter) {
  return {(float(i / s.cols) + jitter.x) / float(s.rows), (float(i % s.cols) + jitter.y) / float(s.cols)};
}

// The course's map of the unit square onto the cosine-weighted hemisphere about +z (§c.14): r = √u, φ = 2πv,
// (r cos φ, r sin φ, √(1 − u)). Its density is cos θ / π, so a mean of radiances estimates the cosine-weighted
// integral over π with no explicit cosine.
template <class T> Vec3<T> cosineHemisphere(glm::vec2 uv) {
  const T r = std::sqrt(T(uv.x));
  const T phi = T(2) * glm::pi<T>() * T(uv.y);
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(T(0), T(1) - T(uv.x)))};
}

// `local` (about +z) turned into the frame whose z is the unit vector n: Duff et al., "Building an Orthonormal
// Basis, Revisited" (JCGT 2017), branch-free and continuous except at n.z = 0's sign change.
template <class T> Vec3<T> aroundNormal(const Vec3<T>& local, const Vec3<T>& n) {
  const T sign = std::copysign(T(1), n.z);
  const T a = T(-1) / (sign + n.z);
  const T b = n.x * n.y * a;
  const Vec3<T> t(T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x);
  const Vec3<T> bt(b, sign + n.y * n.y * a, -n.y);
  return local.x * t + local.y * bt + local.z * n;
}

}  // namespace rt
