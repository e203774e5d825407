// What the groups of a leaf (TriangleGroup, SphereGroup) share: up to four of its objects lane by lane, which
// lanes hold one, and the lanes a test met as bits.
#pragma once

#include <cstdint>

#if defined(__SSE__)
#include <immintrin.h>
#endif

namespace rt {

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
  template <class Mask> uint32_t bits(const Mask& met) const {
#if defined(__SSE__)
    if constexpr (sizeof(T) == 4) return uint32_t(_mm_movemask_ps(reinterpret_cast<const __m128&>(met))) & used;
#endif
    uint32_t out = 0;
    for (int k = 0; k < kSize; ++k) out |= uint32_t(met[k] & 1) << k;
    return out & used;
  }
};

}  // namespace rt
