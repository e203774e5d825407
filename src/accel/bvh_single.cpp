// The hierarchy's two queries for one ray: the incoherent rays (reflections, refractions, diffuse bounces)
// and every query of the diagnostics, on the 8-wide tree. One ray against a node's boxes fills one register
// (eight boxes with AVX2, else four at a time); nothing of a packet's bookkeeping (masks of rays, entry
// distances gathered over rays) is needed.
#include "raytrace/accel/bvh.hpp"

#include <array>
#include <cstring>
#include <limits>
#include <type_traits>

namespace rt {

namespace {

// The ray as the node test uses it, each value in every one of a register's L lanes.
template <class T, int L> struct Slabs {
  static constexpr int kWide = Bvh<T>::kWideWidth;
  typedef T Lanes __attribute__((vector_size(L * sizeof(T))));

  Lanes origin[3], invDir[3];

  explicit Slabs(const Ray<T>& ray) {
    for (int a = 0; a < 3; ++a) origin[a] = Lanes{} + ray.origin[a], invDir[a] = Lanes{} + T(1) / ray.dir[a];
  }

  // The children of the wide node the ray enters within [tMin, tMax], as bit k for child k, and in entry[k]
  // the distance at which it enters them: the packet kernels' slab test (bvh_kernels.cpp, the same
  // operations) for one ray, on L children at a time.
  uint32_t entries(const typename Bvh<T>::WideNode& node, T tMin, T tMax, T (&entry)[kWide]) const {
    uint32_t bits = 0;
    for (int first = 0; first < kWide; first += L) bits |= lanes(node, first, tMin, tMax, entry + first) << first;
    return bits;
  }

 private:
  // Children first to first + L − 1.
  uint32_t lanes(const typename Bvh<T>::WideNode& node, int first, T tMin, T tMax, T* entry) const {
    constexpr T inf = std::numeric_limits<T>::infinity();
    Lanes enter = Lanes{} + tMin, leave = Lanes{} + tMax;
    for (int a = 0; a < 3; ++a) {
      Lanes lo, hi;
      std::memcpy(&lo, node.lo[a] + first, sizeof lo);
      std::memcpy(&hi, node.hi[a] + first, sizeof hi);
      const Lanes t0 = (lo - origin[a]) * invDir[a], t1 = (hi - origin[a]) * invDir[a];
      // min and max written so that a NaN from 0·∞ in t0 or t1 never replaces enter or leave.
      const Lanes tNear = t1 < t0 ? t1 : t0, tFar = t0 < t1 ? t1 : t0;
      enter = enter < tNear ? tNear : enter;
      leave = tFar < leave ? tFar : leave;
    }
    std::memcpy(entry, &enter, sizeof enter);
    return laneBits((enter <= leave * kFarScale<T>) & (enter < inf));
  }
};

}  // namespace

template <class T>
template <class Slabs>
[[gnu::always_inline]] inline void Bvh<T>::closestHitWith(const Ray<T>& ray, Interval<T> range,
                                                          std::optional<Hit<T>>& best) const {
  if (wideNodes_.empty()) return;
  const Slabs slabs(ray);
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

template <class T>
template <class Slabs>
[[gnu::always_inline]] inline const Object<T>* Bvh<T>::occluderWith(const Ray<T>& ray, Interval<T> range) const {
  if (wideNodes_.empty()) return nullptr;
  const Slabs slabs(ray);
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

// The AVX2 instances test a wide node's eight boxes in one register. Their target attribute lets the compiler
// use AVX2 in all they inline; `flatten` inlines the AVX2 laneBits too, which the traversal's own body (compiled
// for the baseline) cannot take in.
template <class T> const std::vector<typename Bvh<T>::SingleRayQueries>& Bvh<T>::singleRayQueries() {
  static const std::vector<SingleRayQueries> supported = [] {
    std::vector<SingleRayQueries> q;
#if defined(__x86_64__)
    if constexpr (std::is_same_v<T, float>) {
      __builtin_cpu_init();
      if (__builtin_cpu_supports("avx2")) {
        q.push_back({[](const Bvh& bvh, const Ray<T>& ray, Interval<T> range, std::optional<Hit<T>>& best)
                         __attribute__((target("avx2"), flatten)) {
                           bvh.closestHitWith<Slabs<T, 8>>(ray, range, best);
                         },
                     [](const Bvh& bvh, const Ray<T>& ray, Interval<T> range) __attribute__((target("avx2"), flatten)) {
                       return bvh.occluderWith<Slabs<T, 8>>(ray, range);
                     }});
      }
    }
#endif
    q.push_back({[](const Bvh& bvh, const Ray<T>& ray, Interval<T> range, std::optional<Hit<T>>& best) {
                   bvh.closestHitWith<Slabs<T, 4>>(ray, range, best);
                 },
                 [](const Bvh& bvh, const Ray<T>& ray, Interval<T> range) {
                   return bvh.occluderWith<Slabs<T, 4>>(ray, range);
                 }});
    return q;
  }();
  return supported;
}

template <class T>
void Bvh<T>::closestHit(const Ray<T>& ray, Interval<T> range, std::optional<Hit<T>>& best) const {
  static const auto widest = singleRayQueries().front().closestHit;
  widest(*this, ray, range, best);
}

template <class T> const Object<T>* Bvh<T>::occluder(const Ray<T>& ray, Interval<T> range) const {
  static const auto widest = singleRayQueries().front().occluder;
  return widest(*this, ray, range);
}

template void Bvh<float>::closestHit(const Ray<float>&, Interval<float>, std::optional<Hit<float>>&) const;
template void Bvh<double>::closestHit(const Ray<double>&, Interval<double>, std::optional<Hit<double>>&) const;
template const Object<float>* Bvh<float>::occluder(const Ray<float>&, Interval<float>) const;
template const Object<double>* Bvh<double>::occluder(const Ray<double>&, Interval<double>) const;
template const std::vector<Bvh<float>::SingleRayQueries>& Bvh<float>::singleRayQueries();
template const std::vector<Bvh<double>::SingleRayQueries>& Bvh<double>::singleRayQueries();

}  // namespace rt
