// A triangle group against up to 16 rays at once (TriangleGroup::manyRays): one ray per lane of an AVX-512
// register, as Embree tests a packet of 16 rays against one triangle at a time.
#include "raytrace/accel/triangle_group.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace rt {

namespace {

#if defined(__x86_64__)
// hits()' steps, written as hits() writes them, with the triangle's values broadcast and the rays' in the
// lanes; the build never fuses a product and a sum (-ffp-contract=off). The comparisons are intrinsics, which
// give masks.
[[gnu::target("avx512f")]] void manyRaysAvx512(const TriangleGroup<float>& group, const RayLanes<float>& lanes,
                                               uint32_t rays, uint32_t (&met)[LaneGroup<float>::kSize],
                                               float (&t)[LaneGroup<float>::kSize][RayLanes<float>::kSize]) {
  const __m512 d[3] = {_mm512_load_ps(lanes.dir[0]), _mm512_load_ps(lanes.dir[1]), _mm512_load_ps(lanes.dir[2])};
  const __m512 o[3] = {_mm512_load_ps(lanes.origin[0]), _mm512_load_ps(lanes.origin[1]),
                       _mm512_load_ps(lanes.origin[2])};
  const __m512 min = _mm512_load_ps(lanes.min), max = _mm512_load_ps(lanes.max);
  const __m512 zero = _mm512_setzero_ps(), one = _mm512_set1_ps(1.0f);
  for (int k = 0; k < LaneGroup<float>::kSize; ++k) {
    met[k] = 0;
    if (!(group.used >> k & 1)) continue;
    __m512 a[3], ab[3], ac[3];
    for (int axis = 0; axis < 3; ++axis) {
      a[axis] = _mm512_set1_ps(group.a[axis][k]);
      ab[axis] = _mm512_set1_ps(group.ab[axis][k]);
      ac[axis] = _mm512_set1_ps(group.ac[axis][k]);
    }
    const __m512 p[3] = {d[1] * ac[2] - ac[1] * d[2], d[2] * ac[0] - ac[2] * d[0], d[0] * ac[1] - ac[0] * d[1]};
    const __m512 det = ab[0] * p[0] + ab[1] * p[1] + ab[2] * p[2];
    const __m512 s[3] = {o[0] - a[0], o[1] - a[1], o[2] - a[2]};
    const __m512 u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    const __m512 q[3] = {s[1] * ab[2] - ab[1] * s[2], s[2] * ab[0] - ab[2] * s[0], s[0] * ab[1] - ab[0] * s[1]};
    const __m512 v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    const __m512 tk = (ac[0] * q[0] + ac[1] * q[1] + ac[2] * q[2]) / det;
    __mmask16 m = _mm512_mask_cmp_ps_mask(__mmask16(rays), det, zero, _CMP_NEQ_UQ);
    m = _mm512_mask_cmp_ps_mask(m, u, zero, _CMP_GE_OQ);
    m = _mm512_mask_cmp_ps_mask(m, u, one, _CMP_LE_OQ);
    m = _mm512_mask_cmp_ps_mask(m, v, zero, _CMP_GE_OQ);
    m = _mm512_mask_cmp_ps_mask(m, u + v, one, _CMP_LE_OQ);
    m = _mm512_mask_cmp_ps_mask(m, min, tk, _CMP_LT_OQ);
    m = _mm512_mask_cmp_ps_mask(m, tk, max, _CMP_LT_OQ);
    met[k] = m;
    _mm512_storeu_ps(t[k], tk);
  }
}
#endif

}  // namespace

template <> TriangleGroup<float>::ManyRays TriangleGroup<float>::manyRays() {
#if defined(__x86_64__)
  static const ManyRays chosen = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") ? &manyRaysAvx512 : ManyRays{};
  }();
  return chosen;
#else
  return nullptr;
#endif
}

template <> TriangleGroup<double>::ManyRays TriangleGroup<double>::manyRays() { return nullptr; }

}  // namespace rt
