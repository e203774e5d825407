// The hierarchy's two queries for one ray: the incoherent rays (reflections, refractions, diffuse bounces)
// and every query of the diagnostics, on the 8-wide tree. One ray against four of a node's boxes fills one
// register; nothing of a packet's bookkeeping (masks of rays, entry distances gathered over rays) is needed.
#include "raytrace/accel/bvh.hpp"

#include <array>
#include <cstring>
#include <limits>

#if defined(__SSE__)
#include <immintrin.h>
#endif

namespace rt {

namespace {

// The ray as the node test uses it, each value in every lane of a register of four.
template <class T> struct Slabs {
  static constexpr int W = Bvh<T>::kWidth, kWide = Bvh<T>::kWideWidth;
  typedef T Quad __attribute__((vector_size(W * sizeof(T))));

  Quad origin[3], invDir[3];

  explicit Slabs(const Ray<T>& ray) {
    for (int a = 0; a < 3; ++a) origin[a] = Quad{} + ray.origin[a], invDir[a] = Quad{} + T(1) / ray.dir[a];
  }

  // The children of the wide node the ray enters within [tMin, tMax], as bit k for child k, and in entry[k]
  // the distance at which it enters them: the packet kernels' slab test (bvh_kernels.cpp, the same
  // operations) for one ray, on four children at a time.
  uint32_t entries(const typename Bvh<T>::WideNode& node, T tMin, T tMax, T (&entry)[kWide]) const {
    uint32_t bits = 0;
    for (int first = 0; first < kWide; first += W) bits |= quad(node, first, tMin, tMax, entry + first) << first;
    return bits;
  }

 private:
  // Children first to first + W − 1.
  uint32_t quad(const typename Bvh<T>::WideNode& node, int first, T tMin, T tMax, T* entry) const {
    constexpr T inf = std::numeric_limits<T>::infinity();
    Quad enter = Quad{} + tMin, leave = Quad{} + tMax;
    for (int a = 0; a < 3; ++a) {
      Quad lo, hi;
      std::memcpy(&lo, node.lo[a] + first, sizeof lo);
      std::memcpy(&hi, node.hi[a] + first, sizeof hi);
      const Quad t0 = (lo - origin[a]) * invDir[a], t1 = (hi - origin[a]) * invDir[a];
      // min and max written so that a NaN from 0·∞ in t0 or t1 never replaces enter or leave.
      const Quad tNear = t1 < t0 ? t1 : t0, tFar = t0 < t1 ? t1 : t0;
      enter = enter < tNear ? tNear : enter;
      leave = tFar < leave ? tFar : leave;
    }
    const auto enters = (enter <= leave * kFarScale<T>) & (enter < inf);
    std::memcpy(entry, &enter, sizeof enter);
#if defined(__SSE__)
    if constexpr (sizeof(T) == 4) return uint32_t(_mm_movemask_ps(reinterpret_cast<const __m128&>(enters)));
#endif
    uint32_t bits = 0;
    for (int k = 0; k < W; ++k) bits |= uint32_t(enters[k] & 1) << k;
    return bits;
  }
};

}  // namespace

template <class T>
void Bvh<T>::closestHit(const Ray<T>& ray, Interval<T> range, std::optional<Hit<T>>& best) const {
  if (wideNodes_.empty()) return;
  const Slabs<T> slabs(ray);
  ClosestSoFar<T> closest(best);
  // Hits at exactly best->t are still wanted: they win when their object comes first in the file.
  T tMax = best ? nextUp(best->t) : range.max;
  // Children still to visit, nearest on top: the nearest child is visited next, and the hits found there cut
  // off the farther ones.
  struct Pending {
    T t;
    uint32_t first, count;
  };
  std::array<Pending, kMaxDepth * kWideWidth> stack;
  int size = 0;
  Pending current{range.min, 0, 0};
  for (;;) {
    if (current.count) {
      closestInLeaf(current.first, current.count, ray, range.min, tMax, closest, best);
    } else {
      const WideNode& node = wideNodes_[current.first];
      T entry[kWideWidth];
      uint32_t enters = slabs.entries(node, range.min, tMax, entry);
      if (enters && !(enters & (enters - 1))) {  // one child, the most common case below the top
        const int k = __builtin_ctz(enters);
        current = {entry[k], node.first[k], node.count[k]};
        continue;
      }
      const int base = size;
      int nearest = -1;
      for (; enters; enters &= enters - 1) {
        const int k = __builtin_ctz(enters);
        int later = k;
        if (nearest < 0 || entry[k] < entry[nearest]) std::swap(later, nearest);
        if (later < 0) continue;
        int at = size++;
        while (at > base && stack[at - 1].t < entry[later]) stack[at] = stack[at - 1], --at;
        stack[at] = {entry[later], node.first[later], node.count[later]};
      }
      if (nearest >= 0) {
        current = {entry[nearest], node.first[nearest], node.count[nearest]};
        continue;
      }
    }
    // Next, the nearest pending child the ray may enter before its closest hit.
    do {
      if (size == 0) return closest.finish(ray, range.min, best);
      current = stack[--size];
    } while (current.t > tMax * kFarScale<T>);
  }
}

template <class T> const Object<T>* Bvh<T>::occluder(const Ray<T>& ray, Interval<T> range) const {
  if (wideNodes_.empty()) return nullptr;
  const Slabs<T> slabs(ray);
  std::array<uint32_t, kMaxDepth * kWideWidth> stack;
  int size = 0;
  stack[size++] = 0;
  while (size > 0) {
    const WideNode& node = wideNodes_[stack[--size]];
    T entry[kWideWidth];
    for (uint32_t enters = slabs.entries(node, range.min, range.max, entry); enters; enters &= enters - 1) {
      const int k = __builtin_ctz(enters);
      if (!node.count[k]) {
        stack[size++] = node.first[k];
        continue;
      }
      if (node.count[k] & (kTriangleLeaf | kSphereLeaf)) {
        if (const Object<T>* o = occluderInGroups(node.first[k], node.count[k], ray, range)) return o;
        continue;
      }
      for (uint32_t o = node.first[k]; o < node.first[k] + node.count[k]; ++o) {
        const Primitive<T>& p = primitives_[o];
        const bool met = p.kind == Primitive<T>::Kind::Other ? objects_[o]->occludes(&ray, &range, 1) != 0
                                                               : p.meets(ray, range);
        if (met) return objects_[o];
      }
    }
  }
  return nullptr;
}

template void Bvh<float>::closestHit(const Ray<float>&, Interval<float>, std::optional<Hit<float>>&) const;
template void Bvh<double>::closestHit(const Ray<double>&, Interval<double>, std::optional<Hit<double>>&) const;
template const Object<float>* Bvh<float>::occluder(const Ray<float>&, Interval<float>) const;
template const Object<double>* Bvh<double>::occluder(const Ray<double>&, Interval<double>) const;

}  // namespace rt
