#include "raytrace/bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <limits>
#include <string>

#include "raytrace/report.hpp"

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

}  // namespace

template <class T> Bvh<T>::Bvh(const std::vector<const Object<T>*>& objects) {
  if (objects.empty()) return;
  std::vector<Aabb<T>> boxes;
  std::vector<Vec3<T>> centroids;
  boxes.reserve(objects.size());
  centroids.reserve(objects.size());
  for (const Object<T>* o : objects) {
    boxes.push_back(paddedBounds(*o));
    centroids.push_back(centroid(boxes.back()));
  }
  std::vector<uint32_t> order(objects.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;

  nodes_.reserve(2 * objects.size() - 1);
  nodes_.push_back(Node{{}, 0, uint32_t(objects.size())});
  struct Task {
    uint32_t node;
    int depth;
  };
  std::vector<Task> tasks{{0, 0}};
  while (!tasks.empty()) {
    const Task task = tasks.back();
    tasks.pop_back();
    const uint32_t first = nodes_[task.node].first, count = nodes_[task.node].count;
    Aabb<T> box, centres;
    for (uint32_t i = first; i < first + count; ++i) {
      box.expand(boxes[order[i]]);
      centres.expand(centroids[order[i]]);
    }
    nodes_[task.node].box = box;
    if (count == 1 || task.depth >= kMaxDepth) continue;

    // Bin the centroids along their longest extent and sweep the bin boundaries for the lowest surface area
    // heuristic cost, kTraversalCost + (A_left·N_left + A_right·N_right) / A_node, against N for a leaf.
    const Vec3<T> extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const T binScale = T(kBins) / extent[axis];
    const auto binOf = [&](uint32_t object) {
      return std::min(kBins - 1, int((centroids[object][axis] - centres.min[axis]) * binScale));
    };
    double bestCost = std::numeric_limits<double>::infinity();
    int bestSplit = 0;
    if (extent[axis] > T(0)) {
      std::array<Aabb<T>, kBins> binBox;
      std::array<uint32_t, kBins> binCount{};
      for (uint32_t i = first; i < first + count; ++i) {
        const int b = binOf(order[i]);
        binBox[b].expand(boxes[order[i]]);
        ++binCount[b];
      }
      // rightCost[s] is A·N of bins s..end, the right side of a split before bin s.
      std::array<double, kBins> rightCost{};
      Aabb<T> right;
      uint32_t rightCount = 0;
      for (int s = kBins - 1; s > 0; --s) {
        right.expand(binBox[s]);
        rightCount += binCount[s];
        rightCost[s] = rightCount ? area(right) * rightCount : 0.0;
      }
      Aabb<T> left;
      uint32_t leftCount = 0;
      const double nodeArea = area(box);
      for (int s = 1; s < kBins; ++s) {
        left.expand(binBox[s - 1]);
        leftCount += binCount[s - 1];
        if (leftCount == 0 || leftCount == count) continue;
        const double cost = kTraversalCost + (area(left) * leftCount + rightCost[s]) / nodeArea;
        if (cost < bestCost) bestCost = cost, bestSplit = s;
      }
    }
    if (count <= kMaxLeaf && !(bestCost < double(count))) continue;

    uint32_t middle;
    if (bestSplit > 0) {
      const auto split = std::partition(order.begin() + first, order.begin() + first + count,
                                        [&](uint32_t o) { return binOf(o) < bestSplit; });
      middle = uint32_t(split - order.begin());
    } else {
      middle = first + count / 2;  // all centroids coincide: any halving is as good as another
    }
    const uint32_t left = uint32_t(nodes_.size());
    nodes_.push_back(Node{{}, first, middle - first});
    nodes_.push_back(Node{{}, middle, first + count - middle});
    nodes_[task.node].first = left;
    nodes_[task.node].count = 0;
    tasks.push_back({left, task.depth + 1});
    tasks.push_back({left + 1, task.depth + 1});
  }
  objects_.reserve(objects.size());
  for (uint32_t i : order) objects_.push_back(objects[i]);
}

template <class T>
std::optional<Hit<T>> Bvh<T>::closestHit(const Ray<T>& ray, Interval<T> range, std::optional<Hit<T>> best) const {
  if (nodes_.empty()) return best;
  const Vec3<T> invDir = T(1) / ray.dir;
  constexpr T inf = std::numeric_limits<T>::infinity();
  // Hits at exactly best->t are still wanted: they win when their object comes first in the file.
  T limit = best ? nextUp(best->t) : range.max;
  if (rayBoxEntry(nodes_[0].box, ray.origin, invDir, range.min, limit) == inf) return best;

  struct Pending {
    const Node* node;
    T t;
  };
  std::array<Pending, kMaxDepth> stack;
  int size = 0;
  const Node* node = &nodes_[0];
  for (;;) {
    if (node->leaf()) {
      for (uint32_t i = node->first; i < node->first + node->count; ++i) {
        const Object<T>* object = objects_[i];
        auto hit = object->intersect(ray, Interval<T>{range.min, limit});
        if (hit && (!best || hit->t < best->t || object->id() < best->object->id())) {
          best = hit;
          limit = nextUp(hit->t);
        }
      }
    } else {
      // Visit the nearer child first so that its hits cut off the farther one.
      const Node* near = &nodes_[node->first];
      const Node* far = near + 1;
      T tNear = rayBoxEntry(near->box, ray.origin, invDir, range.min, limit);
      T tFar = rayBoxEntry(far->box, ray.origin, invDir, range.min, limit);
      if (tFar < tNear) std::swap(near, far), std::swap(tNear, tFar);
      if (tNear != inf) {
        if (tFar != inf) stack[size++] = {far, tFar};
        node = near;
        continue;
      }
    }
    // Next: the nearest postponed subtree that a hit found since has not ruled out.
    do {
      if (size == 0) return best;
      --size;
    } while (stack[size].t > limit * kFarScale<T>);
    node = stack[size].node;
  }
}

template <class T> bool Bvh<T>::occluded(const Ray<T>& ray, Interval<T> range) const {
  if (nodes_.empty()) return false;
  const Vec3<T> invDir = T(1) / ray.dir;
  constexpr T inf = std::numeric_limits<T>::infinity();
  if (rayBoxEntry(nodes_[0].box, ray.origin, invDir, range.min, range.max) == inf) return false;
  std::array<const Node*, kMaxDepth> stack;
  int size = 0;
  const Node* node = &nodes_[0];
  for (;;) {
    if (node->leaf()) {
      for (uint32_t i = node->first; i < node->first + node->count; ++i) {
        if (objects_[i]->intersect(ray, range)) return true;
      }
    } else {
      const Node* a = &nodes_[node->first];
      const bool hitA = rayBoxEntry(a->box, ray.origin, invDir, range.min, range.max) != inf;
      const bool hitB = rayBoxEntry(a[1].box, ray.origin, invDir, range.min, range.max) != inf;
      if (hitA || hitB) {
        if (hitA && hitB) stack[size++] = a + 1;
        node = hitA ? a : a + 1;
        continue;
      }
    }
    if (size == 0) return false;
    node = stack[--size];
  }
}

template <class T> void Bvh<T>::print(std::ostream& out) const {
  size_t leaves = 0, largest = 0;
  for (const Node& n : nodes_) {
    if (n.leaf()) ++leaves, largest = std::max<size_t>(largest, n.count);
  }
  out << "BVH: " << objects_.size() << " objects, " << nodes_.size() << " nodes, " << leaves
      << " leaves, largest leaf " << largest << "\n";
  if (nodes_.empty()) return;
  struct Item {
    uint32_t node;
    int depth;
  };
  std::vector<Item> stack{{0, 0}};
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const Node& n = nodes_[item.node];
    out << std::string(size_t(2 * item.depth), ' ') << (n.leaf() ? "Leaf " : "Node ") << item.node << ": "
        << braces(glm::dvec3(n.box.min)) << " - " << braces(glm::dvec3(n.box.max));
    if (n.leaf()) {
      out << " objects";
      for (uint32_t i = n.first; i < n.first + n.count; ++i) out << " " << objects_[i]->id();
    }
    out << "\n";
    if (!n.leaf()) {
      stack.push_back({n.first + 1, item.depth + 1});
      stack.push_back({n.first, item.depth + 1});
    }
  }
}

template class Bvh<float>;
template class Bvh<double>;

}  // namespace rt
