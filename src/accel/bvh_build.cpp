// Building the hierarchy: a binary tree by the binned surface area heuristic (Wald 2007), split on the threads,
// then collapsed to kWidth children per node (Wald et al. 2008).
#include "raytrace/accel/bvh.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "raytrace/util/parallel.hpp"

namespace rt {

namespace {

constexpr int kBins = 16;         // Wald 2007: 16 bins lose almost nothing against a full sweep
constexpr uint32_t kMaxLeaf = 4;  // a leaf this small may stay a leaf when no split pays
// SAH cost of one node visit (two box tests) relative to one object test; measured with raytrace_bench.
constexpr double kTraversalCost = 1.0;
// In a tree of triangles only or of spheres only, whose leaves are tested a TriangleGroup or SphereGroup at a
// time: the largest leaf kept when no split pays, and the SAH cost of one group's test relative to a node visit
// (docs/performance.md, "Against Embree": a sphere group's square root and divisions cost more).
constexpr uint32_t kMaxGroupedLeaf = 8;
constexpr double kTriangleGroupCost = 1.0;
constexpr double kSphereGroupCost = 3.0;

template <class T> Vec3<T> centroid(const Aabb<T>& b) { return (b.min + b.max) * T(0.5); }

template <class T> double area(const Aabb<T>& b) {
  const glm::dvec3 e = glm::dvec3(b.max) - glm::dvec3(b.min);
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

// The object's box, grown so that no hit its intersect() reports can fall outside it. A computed t is off by
// at most 1e-3 of the object's size (chooseArithmetic's budget, docs/reference/stability.md §1.1), and the corners
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

  // With a `groupCost` above 0, the objects are triangles or spheres whose leaves are tested in groups of four,
  // each costing that: a leaf's cost is that of its groups, not of its objects one by one.
  BinaryBuilder(const std::vector<Aabb<T>>& boxes, const std::vector<Vec3<T>>& centroids, std::vector<uint32_t>& order,
                double groupCost)
      : boxes_(boxes), centroids_(centroids), order_(order), groupCost_(groupCost) {}

  // Gives the task's node its box and, when a split pays, two children appended to `nodes`, as tasks in `out`.
  // Touches only the node's own range of `order`, so nodes of disjoint ranges may be split at the same time.
  // The task is taken by value, as `out` may be the vector it comes from.
  void split(std::vector<BinaryNode<T>>& nodes, Task task, std::vector<Task>& out) const {
    const uint32_t first = nodes[task.node].first, count = nodes[task.node].count;
    const Bounds bounds = boundsOf(first, count);
    nodes[task.node].box = bounds.box;
    if (count == 1 || task.depth >= Bvh<T>::kMaxDepth) return;
    const Bins bins = binsAlongLongestAxis(bounds.centres);
    const Cut cut = cheapestCut(first, count, bins, bounds);
    if (count <= (groupCost_ > 0 ? kMaxGroupedLeaf : kMaxLeaf) && !(cut.cost < testCost(count))) return;
    const uint32_t middle = partition(first, count, bins, cut);
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
  // The box of a node's objects and the box of their centroids.
  struct Bounds {
    Aabb<T> box, centres;
  };
  // kBins equal bins along the centroids' longest extent.
  struct Bins {
    int axis;
    T min, scale;
    bool usable;  // false when the centroids coincide along the axis

    // Near the top of T's range a centroid or the extent overflows to ∞, and the bin's position becomes ∞·0,
    // a NaN: it is clamped into the bins before it is made an int, which a NaN or ∞ would make undefined.
    int of(const Vec3<T>& centroid) const {
      const T x = (centroid[axis] - min) * scale;
      return x > T(0) ? int(std::min(x, T(kBins - 1))) : 0;
    }
  };
  // The objects in bins below `bin` go left; bin 0 when no cut was found.
  struct Cut {
    int bin = 0;
    double cost = std::numeric_limits<double>::infinity();
  };

  // The SAH cost of testing `count` objects in a leaf.
  double testCost(uint32_t count) const {
    return groupCost_ > 0 ? groupCost_ * double(Bvh<T>::groupsOf(count)) : double(count);
  }

  Bounds boundsOf(uint32_t first, uint32_t count) const {
    Bounds b;
    for (uint32_t i = first; i < first + count; ++i) {
      b.box.expand(boxes_[order_[i]]);
      b.centres.expand(centroids_[order_[i]]);
    }
    return b;
  }

  static Bins binsAlongLongestAxis(const Aabb<T>& centres) {
    const Vec3<T> extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    return {axis, centres.min[axis], T(kBins) / extent[axis], extent[axis] > T(0)};
  }

  // The bin boundary with the lowest surface area heuristic cost,
  // kTraversalCost + (A_left·C(N_left) + A_right·C(N_right)) / A_node, to be weighed against C(N) for a leaf,
  // where C = testCost.
  Cut cheapestCut(uint32_t first, uint32_t count, const Bins& bins, const Bounds& bounds) const {
    Cut best;
    if (!bins.usable) return best;
    std::array<Aabb<T>, kBins> binBox;
    std::array<uint32_t, kBins> binCount{};
    for (uint32_t i = first; i < first + count; ++i) {
      const int b = bins.of(centroids_[order_[i]]);
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
      rightCost[j] = area(right) * testCost(rightCount);
    }
    Aabb<T> left;
    uint32_t leftCount = 0;
    const double nodeArea = area(bounds.box);
    for (int j = 1; j < size; ++j) {
      left.expand(binBox[full[j - 1]]);
      leftCount += binCount[full[j - 1]];
      const double cost = kTraversalCost + (area(left) * testCost(leftCount) + rightCost[j]) / nodeArea;
      if (cost < best.cost) best = {full[j - 1] + 1, cost};
    }
    return best;
  }

  // Reorders the node's range of `order` so the left side comes first; returns where the right side starts.
  uint32_t partition(uint32_t first, uint32_t count, const Bins& bins, const Cut& cut) const {
    if (cut.bin == 0) return first + count / 2;  // all centroids coincide: any halving is as good as another
    const auto middle = std::partition(order_.begin() + first, order_.begin() + first + count,
                                       [&](uint32_t o) { return bins.of(centroids_[o]) < cut.bin; });
    return uint32_t(middle - order_.begin());
  }

  const std::vector<Aabb<T>>& boxes_;
  const std::vector<Vec3<T>>& centroids_;
  std::vector<uint32_t>& order_;
  double groupCost_;
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
                                       double groupCost, int threads) {
  const size_t n = objects.size();
  std::vector<Aabb<T>> boxes(n);
  std::vector<Vec3<T>> centroids(n);
  parallelForChunks(n, kObjectChunk, threads, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      boxes[i] = paddedBounds(*objects[i]);
      centroids[i] = centroid(boxes[i]);
    }
  });
  order.resize(n);
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;

  using Task = typename BinaryBuilder<T>::Task;
  const BinaryBuilder<T> builder(boxes, centroids, order, groupCost);
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

// The W-wide tree of `binary`: a node takes its binary node's children, then, while it has room, replaces the
// inner child with the largest surface area by that child's two children (Wald et al. 2008).
template <class T, int W>
std::vector<typename Bvh<T>::template NodeOf<W>> collapse(const std::vector<BinaryNode<T>>& binary) {
  using Node = typename Bvh<T>::template NodeOf<W>;
  struct Task {
    uint32_t binary, node;
  };
  std::vector<Task> tasks{{0, 0}};
  std::vector<Node> nodes;
  // Each node but the root takes the place of at least one inner binary node: room for all at once, so that
  // the array never moves (only the pages it fills are touched).
  nodes.reserve(binary.size() / 2 + 1);
  nodes.emplace_back();
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    uint32_t children[W];
    int size;
    if (binary[task.binary].count) {
      children[0] = task.binary, size = 1;  // a root that is a leaf: one child
    } else {
      children[0] = binary[task.binary].first, children[1] = children[0] + 1, size = 2;
    }
    while (size < W) {
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
    Node node;
    for (int k = 0; k < size; ++k) {
      const BinaryNode<T>& b = binary[children[k]];
      for (int a = 0; a < 3; ++a) node.lo[a][k] = b.box.min[a], node.hi[a][k] = b.box.max[a];
      node.count[k] = b.count;
      node.first[k] = b.first;
      if (!b.count) {
        node.first[k] = uint32_t(nodes.size());
        nodes.emplace_back();
        tasks.push_back({children[k], node.first[k]});
      }
    }
    nodes[task.node] = node;
  }
  return nodes;
}

}  // namespace

template <class T> Bvh<T>::Bvh(const std::vector<const Object<T>*>& objects, int threads) {
  if (objects.empty()) return;
  primitives_.resize(objects.size());
  parallelForChunks(objects.size(), kObjectChunk, threads, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) primitives_[i] = Primitive<T>::of(*objects[i]);
  });
  // A tree of one kind of primitive only (triangles, or spheres of one formula) is built for its groups.
  using Kind = typename Primitive<T>::Kind;
  const Kind kind = primitives_.front().kind;
  const bool oneKind = std::all_of(primitives_.begin(), primitives_.end(),
                                   [&](const Primitive<T>& p) { return p.kind == kind; });
  const double groupCost = !oneKind || kind == Kind::Other ? 0.0
                           : kind == Kind::Triangle        ? kTriangleGroupCost
                                                           : kSphereGroupCost;
  std::vector<uint32_t> order;
  const std::vector<BinaryNode<T>> binary = buildBinary(objects, order, groupCost, threads);
  objects_.reserve(objects.size());
  std::vector<Primitive<T>> unordered = std::move(primitives_);
  primitives_.clear();
  primitives_.reserve(objects.size());
  for (uint32_t i : order) objects_.push_back(objects[i]), primitives_.push_back(unordered[i]);
  nodes_ = collapse<T, kWidth>(binary);
  wideNodes_ = collapse<T, kWideWidth>(binary);
  groupLeaves();
}

template <class T> void Bvh<T>::groupLeaves() {
  using Kind = typename Primitive<T>::Kind;
  // The first group and the kind of group that the leaf starting at object o became: the wide tree's leaves
  // are the same and take them over.
  std::vector<std::pair<uint32_t, uint32_t>> grouped(objects_.size());
  // Lane k of group g holds the leaf's object k, g = k / kSize, whatever the kind of group.
  const auto fill = [&](auto& groups, uint32_t first, uint32_t count, auto shape) {
    const uint32_t start = uint32_t(groups.size());
    groups.resize(groups.size() + groupsOf(count));
    for (uint32_t k = 0; k < count; ++k) {
      groups[start + k / TriangleGroup<T>::kSize].set(int(k % TriangleGroup<T>::kSize), shape(*objects_[first + k]),
                                                      first + k);
    }
    return start;
  };
  for (Node& node : nodes_) {
    for (int k = 0; k < kWidth; ++k) {
      const uint32_t first = node.first[k], count = node.count[k];
      if (!count) continue;
      const Kind kind = primitives_[first].kind;
      bool same = kind != Kind::Other;
      for (uint32_t o = first; o < first + count; ++o) same = same && primitives_[o].kind == kind;
      if (!same) continue;
      if (kind == Kind::Triangle) {
        node.first[k] = fill(triangleGroups_, first, count,
                             [](const Object<T>& o) -> const Triangle<T>& { return static_cast<const Triangle<T>&>(o); });
        node.count[k] |= kTriangleLeaf;
      } else {
        node.first[k] = fill(sphereGroups_, first, count,
                             [](const Object<T>& o) -> const Sphere<T>& { return static_cast<const Sphere<T>&>(o); });
        node.count[k] |= kSphereLeaf;
      }
      grouped[first] = {node.first[k], node.count[k] & ~kLeafCount};
    }
  }
  for (WideNode& node : wideNodes_) {
    for (int k = 0; k < kWideWidth; ++k) {
      if (!node.count[k]) continue;
      const auto [group, kind] = grouped[node.first[k]];
      if (!kind) continue;
      node.first[k] = group;
      node.count[k] |= kind;
    }
  }
}

template Bvh<float>::Bvh(const std::vector<const Object<float>*>&, int);
template Bvh<double>::Bvh(const std::vector<const Object<double>*>&, int);

}  // namespace rt
