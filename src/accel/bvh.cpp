#include "raytrace/accel/bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <limits>
#include <string>

#include "raytrace/util/parallel.hpp"
#include "raytrace/app/report.hpp"

namespace rt {

namespace {

constexpr int kBins = 16;         // Wald 2007: 16 bins lose almost nothing against a full sweep
constexpr int kMaxDepth = 64;     // deeper subtrees become leaves, so the traversal stack below is enough
constexpr uint32_t kMaxLeaf = 4;  // a leaf this small may stay a leaf when no split pays
// SAH cost of one node visit (two box tests) relative to one object test; measured with raytrace_bench.
constexpr double kTraversalCost = 1.0;

template <class T> Vec3<T> centroid(const Aabb<T>& b) { return (b.min + b.max) * T(0.5); }

template <class T> double area(const Aabb<T>& b) {
  const glm::dvec3 e = glm::dvec3(b.max) - glm::dvec3(b.min);
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

// The object's box, grown so that no hit its intersect() reports can fall outside it. A computed t is off by
// at most 1e-3 of the object's size (chooseArithmetic's budget, stability.md §1.1), and the corners
// themselves are rounded; both margins are tiny next to the box.
template <class T> Aabb<T> paddedBounds(const Object<T>& object) {
  Aabb<T> b = *object.bounds();
  const Vec3<T> extent = b.max - b.min;
  const T pad = T(1e-3) * std::max(extent.x, std::max(extent.y, extent.z)) +
                T(64) * std::numeric_limits<T>::epsilon() * std::max(maxAbs(b.min), maxAbs(b.max));
  b.min -= Vec3<T>(pad);
  b.max += Vec3<T>(pad);
  return b;
}

// The next representable value above t: the smallest limit that still admits a hit at exactly t. A hit's t is
// positive, where this is one step of the bit pattern; std::nextafter covers the rest.
template <class T> T nextUp(T t) {
  using Bits = std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>;
  constexpr T inf = std::numeric_limits<T>::infinity();
  if (!(t > T(0) && t < inf)) return std::nextafter(t, inf);
  Bits bits;
  std::memcpy(&bits, &t, sizeof t);
  ++bits;
  std::memcpy(&t, &bits, sizeof t);
  return t;
}

// The binary tree the 4-wide one is collapsed from. The two children of an inner node are stored side by
// side, the first at `first`; a leaf holds order[first, first + count).
template <class T> struct BinaryNode {
  Aabb<T> box;
  uint32_t first = 0;
  uint32_t count = 0;  // 0 for an inner node
};

// Binned SAH build (Wald 2007) over the objects' boxes and centroids; `order` holds the object indices,
// reordered into leaf order as nodes split.
template <class T> class BinaryBuilder {
 public:
  struct Task {
    uint32_t node;
    int depth;
  };

  BinaryBuilder(const std::vector<Aabb<T>>& boxes, const std::vector<Vec3<T>>& centroids, std::vector<uint32_t>& order)
      : boxes_(boxes), centroids_(centroids), order_(order) {}

  // Gives the task's node its box and, when a split pays, two children appended to `nodes`, as tasks in `out`.
  // Touches only the node's own range of `order`, so nodes of disjoint ranges may be split at the same time.
  // The task is taken by value, as `out` may be the vector it comes from.
  void split(std::vector<BinaryNode<T>>& nodes, Task task, std::vector<Task>& out) const {
    const uint32_t first = nodes[task.node].first, count = nodes[task.node].count;
    Aabb<T> box, centres;
    for (uint32_t i = first; i < first + count; ++i) {
      box.expand(boxes_[order_[i]]);
      centres.expand(centroids_[order_[i]]);
    }
    nodes[task.node].box = box;
    if (count == 1 || task.depth >= kMaxDepth) return;

    // Bin the centroids along their longest extent and sweep the bin boundaries for the lowest surface area
    // heuristic cost, kTraversalCost + (A_left·N_left + A_right·N_right) / A_node, against N for a leaf.
    const Vec3<T> extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const T binScale = T(kBins) / extent[axis];
    // Near the top of T's range a centroid or the extent overflows to ∞, and the bin's position becomes ∞·0,
    // a NaN: it is clamped into the bins before it is made an int, which a NaN or ∞ would make undefined.
    const auto binOf = [&](uint32_t object) {
      const T x = (centroids_[object][axis] - centres.min[axis]) * binScale;
      return x > T(0) ? int(std::min(x, T(kBins - 1))) : 0;
    };
    double bestCost = std::numeric_limits<double>::infinity();
    int bestSplit = 0;
    if (extent[axis] > T(0)) {
      std::array<Aabb<T>, kBins> binBox;
      std::array<uint32_t, kBins> binCount{};
      for (uint32_t i = first; i < first + count; ++i) {
        const int b = binOf(order_[i]);
        binBox[b].expand(boxes_[order_[i]]);
        ++binCount[b];
      }
      // The sweeps look only at the bins that got objects. Most nodes are small and fill a few bins, and a
      // boundary between empty bins splits the objects as the first boundary after the last full bin before
      // it does, at the same cost: the split chosen is the one a sweep over all bins would choose.
      std::array<int, kBins> full;
      int size = 0;
      for (int b = 0; b < kBins; ++b) {
        if (binCount[b]) full[size++] = b;
      }
      // rightCost[j] is A·N of full bins j..size − 1, the right side of a split before full bin j.
      std::array<double, kBins> rightCost;
      Aabb<T> right;
      uint32_t rightCount = 0;
      for (int j = size - 1; j > 0; --j) {
        right.expand(binBox[full[j]]);
        rightCount += binCount[full[j]];
        rightCost[j] = area(right) * rightCount;
      }
      Aabb<T> left;
      uint32_t leftCount = 0;
      const double nodeArea = area(box);
      for (int j = 1; j < size; ++j) {
        left.expand(binBox[full[j - 1]]);
        leftCount += binCount[full[j - 1]];
        const double cost = kTraversalCost + (area(left) * leftCount + rightCost[j]) / nodeArea;
        if (cost < bestCost) bestCost = cost, bestSplit = full[j - 1] + 1;
      }
    }
    if (count <= kMaxLeaf && !(bestCost < double(count))) return;

    uint32_t middle;
    if (bestSplit > 0) {
      const auto split = std::partition(order_.begin() + first, order_.begin() + first + count,
                                        [&](uint32_t o) { return binOf(o) < bestSplit; });
      middle = uint32_t(split - order_.begin());
    } else {
      middle = first + count / 2;  // all centroids coincide: any halving is as good as another
    }
    const uint32_t left = uint32_t(nodes.size());
    nodes.push_back(BinaryNode<T>{{}, first, middle - first});
    nodes.push_back(BinaryNode<T>{{}, middle, first + count - middle});
    nodes[task.node].first = left;
    nodes[task.node].count = 0;
    out.push_back({left, task.depth + 1});
    out.push_back({left + 1, task.depth + 1});
  }

  // The whole subtree under each task, depth first.
  void finish(std::vector<BinaryNode<T>>& nodes, std::vector<Task> tasks) const {
    while (!tasks.empty()) {
      const Task task = tasks.back();
      tasks.pop_back();
      split(nodes, task, tasks);
    }
  }

 private:
  const std::vector<Aabb<T>>& boxes_;
  const std::vector<Vec3<T>>& centroids_;
  std::vector<uint32_t>& order_;
};

// Subtrees built apart on the threads: at least this many, so that the tree is the same for any thread count.
constexpr size_t kSubtrees = 16;
// Below this many objects one thread builds the tree faster than several can start.
constexpr size_t kMinParallelBuild = 4096;

// The nodes of `roots` split on the threads, each into an array of its own whose node 0 is a copy of its root,
// then appended to `nodes` in order. With `whole`, each root's whole subtree is built, and nothing is returned;
// otherwise each root is split once, and the tasks of the children are returned, to be split in turn.
template <class T>
std::vector<typename BinaryBuilder<T>::Task> splitApart(const BinaryBuilder<T>& builder,
                                                         std::vector<BinaryNode<T>>& nodes,
                                                         const std::vector<typename BinaryBuilder<T>::Task>& roots,
                                                         bool whole, int threads) {
  using Task = typename BinaryBuilder<T>::Task;
  std::vector<std::vector<BinaryNode<T>>> subtrees(roots.size());
  parallelFor(int(roots.size()), threads, [&](int k) {
    std::vector<BinaryNode<T>>& sub = subtrees[size_t(k)];
    sub.push_back(nodes[roots[size_t(k)].node]);
    const Task root{0, roots[size_t(k)].depth};
    if (whole) {
      builder.finish(sub, {root});
    } else {
      std::vector<Task> children;  // sub[1] and sub[2], if any, known from sub's size below
      builder.split(sub, root, children);
    }
  });
  std::vector<Task> next;
  for (size_t k = 0; k < roots.size(); ++k) {
    // Local node i ≥ 1 lands at base + i − 1; an inner node's `first` is its children's local index.
    const uint32_t base = uint32_t(nodes.size());
    for (BinaryNode<T>& node : subtrees[k]) {
      if (!node.count) node.first += base - 1;
    }
    nodes[roots[k].node] = subtrees[k][0];
    nodes.insert(nodes.end(), subtrees[k].begin() + 1, subtrees[k].end());
    if (!whole && subtrees[k].size() > 1) {
      next.push_back({base, roots[k].depth + 1});
      next.push_back({base + 1, roots[k].depth + 1});
    }
  }
  return next;
}

// The binary tree and, in `order`, the object indices in leaf order. The top levels are split breadth first,
// the nodes of each level on the threads, until there are kSubtrees nodes to split; the subtrees under them
// are built on the threads. Every node is split as a one-thread build would split it.
template <class T>
std::vector<BinaryNode<T>> buildBinary(const std::vector<const Object<T>*>& objects, std::vector<uint32_t>& order,
                                       int threads) {
  const size_t n = objects.size();
  std::vector<Aabb<T>> boxes(n);
  std::vector<Vec3<T>> centroids(n);
  parallelForBlocks(n, kObjectBlock, threads, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      boxes[i] = paddedBounds(*objects[i]);
      centroids[i] = centroid(boxes[i]);
    }
  });
  order.resize(n);
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;

  using Task = typename BinaryBuilder<T>::Task;
  const BinaryBuilder<T> builder(boxes, centroids, order);
  std::vector<BinaryNode<T>> nodes;
  nodes.reserve(2 * n - 1);
  nodes.push_back({{}, 0, uint32_t(n)});
  std::vector<Task> level{{0, 0}};
  if (threads <= 1 || n < kMinParallelBuild) {
    builder.finish(nodes, level);
    return nodes;
  }
  while (!level.empty() && level.size() < kSubtrees) level = splitApart(builder, nodes, level, false, threads);
  splitApart(builder, nodes, level, true, threads);
  return nodes;
}

}  // namespace

template <class T> Bvh<T>::Bvh(const std::vector<const Object<T>*>& objects, int threads) {
  if (objects.empty()) return;
  std::vector<uint32_t> order;
  const std::vector<BinaryNode<T>> binary = buildBinary(objects, order, threads);
  objects_.reserve(objects.size());
  for (uint32_t i : order) objects_.push_back(objects[i]);

  // Collapse: a node takes its binary node's children, then, while it has room, replaces the inner child with
  // the largest surface area by that child's two children (Wald et al. 2008).
  struct Task {
    uint32_t binary, node;
  };
  std::vector<Task> tasks{{0, 0}};
  // Each node but the root takes the place of at least one inner binary node: room for all at once, so that
  // the array never moves (only the pages it fills are touched).
  nodes_.reserve(binary.size() / 2 + 1);
  nodes_.emplace_back();
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    uint32_t children[kWidth];
    int size;
    if (binary[task.binary].count) {
      children[0] = task.binary, size = 1;  // a root that is a leaf: one child
    } else {
      children[0] = binary[task.binary].first, children[1] = children[0] + 1, size = 2;
    }
    while (size < kWidth) {
      int widest = -1;
      for (int c = 0; c < size; ++c) {
        const BinaryNode<T>& b = binary[children[c]];
        if (!b.count && (widest < 0 || area(b.box) > area(binary[children[widest]].box))) widest = c;
      }
      if (widest < 0) break;
      const uint32_t split = binary[children[widest]].first;
      children[widest] = split;
      children[size++] = split + 1;
    }
    Node node{};
    node.size = size;
    for (int k = 0; k < node.size; ++k) {
      const BinaryNode<T>& b = binary[children[k]];
      for (int a = 0; a < 3; ++a) node.lo[a][k] = b.box.min[a], node.hi[a][k] = b.box.max[a];
      node.count[k] = b.count;
      node.first[k] = b.first;
      if (!b.count) {
        node.first[k] = uint32_t(nodes_.size());
        nodes_.emplace_back();
        tasks.push_back({children[k], node.first[k]});
      }
    }
    nodes_[task.node] = node;
  }
}

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
#endif

// The packet a query fills in, one per thread. A kernel computes on whole registers, so it may read the lanes
// of rays that are not in the query: they hold what an earlier query left there, or zeros, and the results
// are masked out. Zeroing a fresh packet for every query would cost more than the rest of a short one.
// Queries never nest (objects do not query the scene), so one packet per thread is enough.
template <class T> typename Bvh<T>::Packet& scratchPacket() {
  thread_local typename Bvh<T>::Packet packet{};
  return packet;
}

}  // namespace

template <class T> const std::vector<typename Bvh<T>::Kernel>& Bvh<T>::kernels() {
  static const std::vector<Kernel> supported = [] {
    std::vector<Kernel> k;
#if defined(__x86_64__)
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2")) k.push_back(&entriesAvx2<T>);
#endif
    k.push_back(&entriesBaseline<T>);
    return k;
  }();
  return supported;
}

template <class T>
void Bvh<T>::entries(const Node& node, const Packet& packet, T tMin, uint32_t rays, uint32_t (&childRays)[kWidth],
                     T (&childEntry)[kWidth]) {
  static const Kernel widest = kernels().front();
  widest(node, packet, tMin, rays, childRays, childEntry);
}

template <class T>
void Bvh<T>::closestHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* best) const {
  if (nodes_.empty() || n == 0) return;
  Packet& packet = scratchPacket<T>();
  // Hits at exactly best->t are still wanted: they win when their object comes first in the file.
  for (int i = 0; i < n; ++i) packet.set(i, rays[i], best[i] ? nextUp(best[i]->t) : range.max);
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
    if (current.count) {
      for (uint32_t o = current.first; o < current.first + current.count; ++o) {
        const Object<T>* object = objects_[o];
        for (uint32_t mask = current.rays; mask; mask &= mask - 1) {
          const int i = __builtin_ctz(mask);
          auto hit = object->intersect(rays[i], Interval<T>{range.min, packet.tMax[i][0]});
          if (hit && (!best[i] || hit->t < best[i]->t || object->id() < best[i]->object->id())) {
            best[i] = hit;
            std::fill_n(packet.tMax[i], kWidth, nextUp(hit->t));
          }
        }
      }
    } else {
      const Node& node = nodes_[current.first];
      uint32_t childRays[kWidth];
      T childEntry[kWidth];
      entries(node, packet, range.min, current.rays, childRays, childEntry);
      const int base = size;
      int nearest = -1;
      for (int k = 0; k < node.size; ++k) {
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
      if (size == 0) return;
      current = stack[--size];
      for (uint32_t mask = current.rays; mask && !found; mask &= mask - 1) {
        found = !(current.t > packet.tMax[__builtin_ctz(mask)][0] * kFarScale<T>);
      }
    }
  }
}

template <class T>
void Bvh<T>::blockers(const Ray<T>* rays, const Interval<T>* ranges, uint32_t active,
                      const Object<T>** blockers) const {
  if (nodes_.empty()) return;
  Packet& packet = scratchPacket<T>();
  // Every ray has its own tMin; the smallest, tested against all, only admits more boxes, whose objects are
  // then tested with each ray's own range.
  T tMin = std::numeric_limits<T>::infinity();
  for (uint32_t mask = active; mask; mask &= mask - 1) {
    const int i = __builtin_ctz(mask);
    packet.set(i, rays[i], ranges[i].max);
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
    const uint32_t live = p.rays & active;  // those not blocked yet
    if (!live) continue;
    const Node& node = nodes_[p.node];
    uint32_t childRays[kWidth];
    T childEntry[kWidth];
    entries(node, packet, tMin, live, childRays, childEntry);
    for (int k = 0; k < node.size; ++k) {
      if (!childRays[k]) continue;
      if (!node.count[k]) {
        stack[size++] = {node.first[k], childRays[k]};
        continue;
      }
      for (uint32_t o = node.first[k]; o < node.first[k] + node.count[k]; ++o) {
        active &= ~objects_[o]->block(rays, ranges, childRays[k] & active, blockers);
        if (!active) return;
      }
    }
  }
}

template <class T> void Bvh<T>::print(std::ostream& out) const {
  size_t leaves = 0, largest = 0;
  for (const Node& n : nodes_) {
    for (int k = 0; k < n.size; ++k) {
      if (n.count[k]) ++leaves, largest = std::max<size_t>(largest, n.count[k]);
    }
  }
  out << "BVH: " << objects_.size() << " objects, " << nodes_.size() << " nodes of up to " << kWidth
      << " children, " << leaves << " leaves, largest leaf " << largest << "\n";
  const auto line = [&](int depth, const char* what, const Aabb<T>& box) {
    out << std::string(size_t(2 * depth), ' ') << what << braces(glm::dvec3(box.min)) << " - "
        << braces(glm::dvec3(box.max));
  };
  struct Item {
    uint32_t node;
    int depth;
  };
  std::vector<Item> stack;
  if (!nodes_.empty()) stack.push_back({0, 0});
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const Node& n = nodes_[item.node];
    Aabb<T> box;
    for (int k = 0; k < n.size; ++k) box.expand(n.box(k));
    line(item.depth, ("Node " + std::to_string(item.node) + ": ").c_str(), box);
    out << "\n";
    for (int k = n.size - 1; k >= 0; --k) {
      if (!n.count[k]) stack.push_back({n.first[k], item.depth + 1});
    }
    for (int k = 0; k < n.size; ++k) {
      if (!n.count[k]) continue;
      line(item.depth + 1, "Leaf: ", n.box(k));
      out << " objects";
      for (uint32_t i = n.first[k]; i < n.first[k] + n.count[k]; ++i) out << " " << objects_[i]->id();
      out << "\n";
    }
  }
}

template class Bvh<float>;
template class Bvh<double>;

}  // namespace rt
