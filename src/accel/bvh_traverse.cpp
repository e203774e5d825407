// The hierarchy's two queries, closest hit and any hit, for packets of rays.
#include "raytrace/accel/bvh.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace rt {

namespace {

// Leaves of triangles that at least this many of a packet's rays reach are tested against them all at once
// where the processor can (TriangleGroup::manyRays): thresholds of 2 to 8 measured on the bunny and a million
// triangles (docs/performance.md).
constexpr int kManyRays = 6;

// The packet a query fills in, one per thread. A kernel computes on whole registers, so it may read the lanes
// of rays that are not in the query: they hold what an earlier query left there, or zeros, and the results
// are masked out. Zeroing a fresh packet for every query would cost more than the rest of a short one.
// Queries never nest (objects do not query the scene), so one packet per thread is enough.
template <class T> typename Bvh<T>::Packet& scratchPacket() {
  thread_local typename Bvh<T>::Packet packet{};
  return packet;
}

}  // namespace

template <class T>
void Bvh<T>::entries(const Node& node, const Packet& packet, T tMin, uint32_t rays, uint32_t (&childRays)[kWidth],
                     T (&childEntry)[kWidth]) {
  static const Kernel widest = kernels().front();
  widest(node, packet, tMin, rays, childRays, childEntry);
}

template <class T>
void Bvh<T>::closestHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* best) const {
  if (nodes_.empty() || n == 0) return;
  if (n == 1) return closestHit(rays[0], range, best[0]);
  Packet& packet = scratchPacket<T>();
  const auto manyRays = triangleGroups_.empty() ? nullptr : TriangleGroup<T>::manyRays();
  // Hits at exactly best->t are still wanted: they win when their object comes first in the file.
  for (int i = 0; i < n; ++i) {
    packet.set(i, rays[i], best[i] ? nextUp(best[i]->t) : range.max);
    if (manyRays) packet.lanes.set(i, rays[i], {range.min, packet.tMax[i][0]});
  }
  std::optional<ClosestSoFar<T>> closest[kPacket];
  for (int i = 0; i < n; ++i) closest[i].emplace(best[i]);
  // Children still to visit, each with the rays that enter it, nearest on top: the child the packet enters
  // first is visited next, and the hits found there cut off the farther ones.
  struct Pending {
    T t;
    uint32_t first, count, rays;
  };
  std::array<Pending, kMaxDepth * kWidth> stack;
  int size = 0;
  Pending current{range.min, 0, 0, (1u << n) - 1};
  for (;;) {
    if (current.count && manyRays && (current.count & kTriangleLeaf) &&
        __builtin_popcount(current.rays) >= kManyRays) {
      closestInTriangles(manyRays, current.first, current.count, current.rays, packet, closest);
    } else if (current.count) {
      for (uint32_t mask = current.rays; mask; mask &= mask - 1) {
        const int i = __builtin_ctz(mask);
        T tMax = packet.tMax[i][0];
        if (closestInLeaf(current.first, current.count, rays[i], range.min, tMax, *closest[i], best[i])) {
          std::fill_n(packet.tMax[i], kWidth, tMax);
          packet.lanes.max[i] = tMax;
        }
      }
    } else {
      const Node& node = nodes_[current.first];
      uint32_t childRays[kWidth];
      T childEntry[kWidth];
      entries(node, packet, range.min, current.rays, childRays, childEntry);
      const int base = size;
      int nearest = -1;
      for (int k = 0; k < kWidth; ++k) {
        if (!childRays[k]) continue;
        int later = k;
        if (nearest < 0 || childEntry[k] < childEntry[nearest]) std::swap(later, nearest);
        if (later < 0) continue;
        int at = size++;
        while (at > base && stack[at - 1].t < childEntry[later]) stack[at] = stack[at - 1], --at;
        stack[at] = {childEntry[later], node.first[later], node.count[later], childRays[later]};
      }
      if (nearest >= 0) {
        current = {childEntry[nearest], node.first[nearest], node.count[nearest], childRays[nearest]};
        continue;
      }
    }
    // Next, the nearest pending child that some of its rays may enter before their closest hits.
    bool found = false;
    while (!found) {
      if (size == 0) {
        for (int i = 0; i < n; ++i) closest[i]->finish(rays[i], range.min, best[i]);
        return;
      }
      current = stack[--size];
      for (uint32_t mask = current.rays; mask && !found; mask &= mask - 1) {
        found = !(current.t > packet.tMax[__builtin_ctz(mask)][0] * kFarScale<T>);
      }
    }
  }
}

template <class T>
void Bvh<T>::occluders(const Ray<T>* rays, const Interval<T>* ranges, uint32_t active,
                       const Object<T>** found) const {
  if (nodes_.empty() || !active) return;
  if (!(active & (active - 1))) {
    const int i = __builtin_ctz(active);
    if (const Object<T>* o = occluder(rays[i], ranges[i])) found[i] = o;
    return;
  }
  Packet& packet = scratchPacket<T>();
  const auto manyRays = triangleGroups_.empty() ? nullptr : TriangleGroup<T>::manyRays();
  // Every ray has its own tMin; the smallest, tested against all, only admits more boxes, whose objects are
  // then tested with each ray's own range.
  T tMin = std::numeric_limits<T>::infinity();
  for (uint32_t mask = active; mask; mask &= mask - 1) {
    const int i = __builtin_ctz(mask);
    packet.set(i, rays[i], ranges[i].max);
    if (manyRays) packet.lanes.set(i, rays[i], ranges[i]);
    tMin = std::min(tMin, ranges[i].min);
  }
  struct Pending {
    uint32_t node, rays;
  };
  std::array<Pending, kMaxDepth * kWidth> stack;
  int size = 0;
  stack[size++] = {0, active};
  while (size > 0) {
    const Pending p = stack[--size];
    const uint32_t live = p.rays & active;  // those not occluded yet
    if (!live) continue;
    const Node& node = nodes_[p.node];
    uint32_t childRays[kWidth];
    T childEntry[kWidth];
    entries(node, packet, tMin, live, childRays, childEntry);
    for (int k = 0; k < kWidth; ++k) {
      if (!childRays[k]) continue;
      if (!node.count[k]) {
        stack[size++] = {node.first[k], childRays[k]};
        continue;
      }
      if (manyRays && (node.count[k] & kTriangleLeaf) && __builtin_popcount(childRays[k] & active) >= kManyRays) {
        active &= ~occludersInTriangles(manyRays, node.first[k], node.count[k], packet.lanes, childRays[k] & active,
                                        found);
        if (!active) return;
        continue;
      }
      if (node.count[k] & (kTriangleLeaf | kSphereLeaf)) {
        for (uint32_t mask = childRays[k] & active; mask; mask &= mask - 1) {
          const int i = __builtin_ctz(mask);
          if (const Object<T>* o = occluderInGroups(node.first[k], node.count[k], rays[i], ranges[i])) {
            found[i] = o, active &= ~(1u << i);
          }
        }
        if (!active) return;
        continue;
      }
      for (uint32_t o = node.first[k]; o < node.first[k] + node.count[k]; ++o) {
        const Primitive<T>& p = primitives_[o];
        if (p.kind == Primitive<T>::Kind::Other) {
          active &= ~objects_[o]->noteOccluder(rays, ranges, childRays[k] & active, found);
        } else {
          for (uint32_t mask = childRays[k] & active; mask; mask &= mask - 1) {
            const int i = __builtin_ctz(mask);
            if (p.meets(rays[i], ranges[i])) found[i] = objects_[o], active &= ~(1u << i);
          }
        }
        if (!active) return;
      }
    }
  }
}

template void Bvh<float>::entries(const Node&, const Packet&, float, uint32_t, uint32_t (&)[kWidth],
                                  float (&)[kWidth]);
template void Bvh<double>::entries(const Node&, const Packet&, double, uint32_t, uint32_t (&)[kWidth],
                                   double (&)[kWidth]);
template void Bvh<float>::closestHits(const Ray<float>*, int, Interval<float>, std::optional<Hit<float>>*) const;
template void Bvh<double>::closestHits(const Ray<double>*, int, Interval<double>, std::optional<Hit<double>>*) const;
template void Bvh<float>::occluders(const Ray<float>*, const Interval<float>*, uint32_t,
                                    const Object<float>**) const;
template void Bvh<double>::occluders(const Ray<double>*, const Interval<double>*, uint32_t,
                                     const Object<double>**) const;

}  // namespace rt
