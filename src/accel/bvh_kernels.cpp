// The node test of the hierarchy's traversal: one SIMD kernel per register width, chosen at run time.
#include "raytrace/accel/bvh.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <type_traits>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace rt {

namespace {


// The node test for R rays at once (GCC/Clang vector extensions): lane r·kWidth + k tests ray first + r
// against child k, so one SIMD operation on `Lanes` does R·kWidth box-slab steps.
template <class T, int R>
[[gnu::always_inline]] inline void entriesOf(const typename Bvh<T>::Node& node, const typename Bvh<T>::Packet& packet,
                                             T tMin, uint32_t rays, uint32_t (&childRays)[Bvh<T>::kWidth],
                                             T (&childEntry)[Bvh<T>::kWidth]) {
  static_assert(R == 1 || R == 2, "the registers of the kernels below hold one or two rays");
  constexpr int W = Bvh<T>::kWidth;
  typedef T Quad __attribute__((vector_size(W * sizeof(T))));
  typedef T Lanes __attribute__((vector_size(R * W * sizeof(T))));
  using LaneMask = decltype(Lanes{} < Lanes{});  // integer lanes, all bits set where a comparison holds
  using Int = std::conditional_t<sizeof(T) == 4, int32_t, int64_t>;
  constexpr T inf = std::numeric_limits<T>::infinity();
  // The children's bounds, repeated for each of the R rays.
  Lanes lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    Quad q[2];
    std::memcpy(&q[0], node.lo[a], sizeof(Quad));
    std::memcpy(&q[1], node.hi[a], sizeof(Quad));
    for (int b = 0; b < 2; ++b) {
      Lanes& out = b ? hi[a] : lo[a];
      if constexpr (R == 1) out = q[b];
      if constexpr (R == 2) out = __builtin_shufflevector(q[b], q[b], 0, 1, 2, 3, 0, 1, 2, 3);
    }
  }
  LaneMask unitBit;  // 1 << r in the lanes of ray r
  for (int j = 0; j < R * W; ++j) unitBit[j] = Int(1) << (j / W);
  Lanes nearest = Lanes{} + inf;
  LaneMask entered{};
  for (uint32_t pending = rays; pending;) {
    const int first = __builtin_ctz(pending) & ~(R - 1);
    pending &= ~(((1u << R) - 1) << first);
    Lanes origin, invDir, near = Lanes{} + tMin, far;
    std::memcpy(&far, packet.tMax[first], sizeof far);
    for (int a = 0; a < 3; ++a) {
      std::memcpy(&origin, packet.origin[a][first], sizeof origin);
      std::memcpy(&invDir, packet.invDir[a][first], sizeof invDir);
      const Lanes t0 = (lo[a] - origin) * invDir, t1 = (hi[a] - origin) * invDir;
      // min and max written so that a NaN from 0·∞ in t0 or t1 never replaces near or far.
      const Lanes tNear = t1 < t0 ? t1 : t0, tFar = t0 < t1 ? t1 : t0;
      near = near < tNear ? tNear : near;
      far = tFar < far ? tFar : far;
    }
    // near = +∞ when the ray runs parallel to a slab outside it, toward +∞: a miss even if tMax is +∞.
    const LaneMask rayBit = (unitBit << first) & Int(rays);
    const LaneMask enters = (near <= far * kFarScale<T>) & (near < inf) & (rayBit != 0);
    nearest = (enters & (near < nearest)) ? near : nearest;
    entered |= enters & rayBit;
  }
  for (int k = 0; k < W; ++k) {
    childRays[k] = uint32_t(entered[k]);
    childEntry[k] = nearest[k];
    for (int r = 1; r < R; ++r) {
      childRays[k] |= uint32_t(entered[r * W + k]);
      childEntry[k] = std::min(childEntry[k], nearest[r * W + k]);
    }
  }
}

// One kernel per SIMD width, chosen at run time as Embree does: R = how many rays' kWidth lanes fit in a
// register. Without a target attribute the compiler assumes only the baseline (SSE2 on x86-64). The kernels
// do the same operations in the same order, so they give the same bits.
template <class T> constexpr int raysPerRegister(int bytes) {
  return std::max(1, bytes / int(Bvh<T>::kWidth * sizeof(T)));
}
template <class T>
void entriesBaseline(const typename Bvh<T>::Node& node, const typename Bvh<T>::Packet& packet, T tMin,
                     uint32_t rays, uint32_t (&childRays)[Bvh<T>::kWidth], T (&childEntry)[Bvh<T>::kWidth]) {
  entriesOf<T, raysPerRegister<T>(16)>(node, packet, tMin, rays, childRays, childEntry);
}
#if defined(__x86_64__)
template <class T>
[[gnu::target("avx2")]] void entriesAvx2(const typename Bvh<T>::Node& node, const typename Bvh<T>::Packet& packet,
                                         T tMin, uint32_t rays, uint32_t (&childRays)[Bvh<T>::kWidth],
                                         T (&childEntry)[Bvh<T>::kWidth]) {
  entriesOf<T, raysPerRegister<T>(32)>(node, packet, tMin, rays, childRays, childEntry);
}

// Four rays in one AVX-512 register, written with intrinsics (GCC's vector extensions made this width three
// times slower than AVX2): the same steps as entriesOf, each min and max the instruction whose operand order
// gives entriesOf's choice (minps(a, b) = a < b ? a : b), so the same bits. For floats only. The min, max,
// broadcast and extract are the masked forms with every lane set: GCC 12's unmasked ones pass an undefined
// register through, which its -Wuninitialized reports.
[[gnu::target("avx512f,bmi2")]] void entriesAvx512(const Bvh<float>::Node& node, const Bvh<float>::Packet& packet,
                                                  float tMin, uint32_t rays, uint32_t (&childRays)[Bvh<float>::kWidth],
                                                  float (&childEntry)[Bvh<float>::kWidth]) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  constexpr __mmask16 all = 0xffff;
  const __m512 farScale = _mm512_set1_ps(kFarScale<float>), infinity = _mm512_set1_ps(inf);
  __m512 lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = _mm512_mask_broadcast_f32x4(infinity, all, _mm_loadu_ps(node.lo[a]));
    hi[a] = _mm512_mask_broadcast_f32x4(infinity, all, _mm_loadu_ps(node.hi[a]));
  }
  __m512 nearest = infinity;
  uint32_t entered[Bvh<float>::kWidth] = {};
  for (uint32_t pending = rays; pending;) {
    const int first = __builtin_ctz(pending) & ~3;
    pending &= ~(15u << first);
    // Lane 4r + k: ray first + r against child k; the lanes of rays outside `rays` are masked out.
    const __mmask16 live = __mmask16(_pdep_u32(rays >> first & 15, 0x1111) * 15);
    __m512 near = _mm512_set1_ps(tMin), far = _mm512_load_ps(packet.tMax[first]);
    for (int a = 0; a < 3; ++a) {
      const __m512 origin = _mm512_load_ps(packet.origin[a][first]), invDir = _mm512_load_ps(packet.invDir[a][first]);
      const __m512 t0 = _mm512_mul_ps(_mm512_sub_ps(lo[a], origin), invDir);
      const __m512 t1 = _mm512_mul_ps(_mm512_sub_ps(hi[a], origin), invDir);
      const __m512 tNear = _mm512_mask_min_ps(t1, all, t1, t0), tFar = _mm512_mask_max_ps(t1, all, t1, t0);
      near = _mm512_mask_max_ps(tNear, all, tNear, near);
      far = _mm512_mask_min_ps(tFar, all, tFar, far);
    }
    const __mmask16 enters = _mm512_mask_cmp_ps_mask(
        _mm512_mask_cmp_ps_mask(live, near, infinity, _CMP_LT_OQ), near, _mm512_mul_ps(far, farScale), _CMP_LE_OQ);
    nearest = _mm512_mask_min_ps(nearest, enters, near, nearest);
    for (int k = 0; k < Bvh<float>::kWidth; ++k) entered[k] |= _pext_u32(enters, 0x1111u << k) << first;
  }
  const __m128 none = _mm_set1_ps(inf);
  const __m128 quarters[4] = {
      _mm512_mask_extractf32x4_ps(none, 15, nearest, 0), _mm512_mask_extractf32x4_ps(none, 15, nearest, 1),
      _mm512_mask_extractf32x4_ps(none, 15, nearest, 2), _mm512_mask_extractf32x4_ps(none, 15, nearest, 3)};
  _mm_storeu_ps(childEntry, _mm_min_ps(_mm_min_ps(quarters[0], quarters[1]), _mm_min_ps(quarters[2], quarters[3])));
  std::copy_n(entered, Bvh<float>::kWidth, childRays);
}
#endif

}  // namespace

template <class T> const std::vector<typename Bvh<T>::Kernel>& Bvh<T>::kernels() {
  static const std::vector<Kernel> supported = [] {
    std::vector<Kernel> k;
#if defined(__x86_64__)
    __builtin_cpu_init();
    if constexpr (std::is_same_v<T, float>) {
      if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("bmi2")) k.push_back(&entriesAvx512);
    }
    if (__builtin_cpu_supports("avx2")) k.push_back(&entriesAvx2<T>);
#endif
    k.push_back(&entriesBaseline<T>);
    return k;
  }();
  return supported;
}

template const std::vector<Bvh<float>::Kernel>& Bvh<float>::kernels();
template const std::vector<Bvh<double>::Kernel>& Bvh<double>::kernels();

}  // namespace rt
