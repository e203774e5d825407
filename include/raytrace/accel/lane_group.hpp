// What the groups of a leaf (TriangleGroup, SphereGroup) share: up to four of its objects lane by lane, which
// lanes hold one, and the lanes a test met as bits.
#pragma once

#include <cstdint>

#if defined(__SSE__)
#include <immintrin.h>
#endif

namespace rt {

// The lanes of a comparison's result `met` (all bits set where it holds) as bits, lane k as bit k: one
// movemask instruction where the processor has it for that width.
template <class Mask> uint32_t laneBits(const Mask& met) {
  uint32_t bits = 0;
  for (int k = 0; k < int(sizeof met / sizeof met[0]); ++k) bits |= uint32_t(met[k] & 1) << k;
  return bits;
}
#if defined(__SSE__)
typedef int32_t LaneMask4 __attribute__((vector_size(16)));
inline uint32_t laneBits(const LaneMask4& met) {
  return uint32_t(_mm_movemask_ps(reinterpret_cast<const __m128&>(met)));
}
// Eight lanes, for code built for AVX2 (the single-ray node test's AVX2 instance, bvh_single.cpp).
typedef int32_t LaneMask8 __attribute__((vector_size(32)));
[[gnu::target("avx2")]] inline uint32_t laneBits(const LaneMask8& met) {
  return uint32_t(_mm256_movemask_ps(reinterpret_cast<const __m256&>(met)));
}
#endif

template <class T> struct LaneGroup {
  static constexpr int kSize = 4;
  typedef T Lanes __attribute__((vector_size(kSize * sizeof(T))));

  uint32_t object[kSize]{};  // lane k's index into the hierarchy's objects
  int id[kSize]{};           // lane k's object id: equal t go to the lower
  uint32_t used = 0;         // bit k set when lane k holds an object

  // Lane k becomes the hierarchy's object `index`, whose id is `objectId`.
  void hold(int k, uint32_t index, int objectId) {
    object[k] = index;
    id[k] = objectId;
    used |= 1u << k;
  }
  // The lanes in use where the comparison result `met` holds, as bit k for lane k.
  template <class Mask> uint32_t bits(const Mask& met) const { return laneBits(met) & used; }
};

}  // namespace rt
