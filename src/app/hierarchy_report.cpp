#include "raytrace/app/hierarchy_report.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "raytrace/util/format.hpp"

namespace rt {

template <class T> void printHierarchy(std::ostream& out, const Bvh<T>& bvh) {
  using Node = typename Bvh<T>::Node;
  const std::vector<Node>& nodes = bvh.nodes();
  size_t leaves = 0, largest = 0;
  for (const Node& n : nodes) {
    for (int k = 0; k < n.size(); ++k) {
      if (n.count[k]) ++leaves, largest = std::max<size_t>(largest, bvh.leafObjects(n, k).second);
    }
  }
  out << "BVH: " << bvh.objects().size() << " objects, " << nodes.size() << " nodes of up to " << Bvh<T>::kWidth
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
  if (!nodes.empty()) stack.push_back({0, 0});
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const Node& n = nodes[item.node];
    Aabb<T> box;
    for (int k = 0; k < n.size(); ++k) box.expand(n.box(k));
    line(item.depth, ("Node " + std::to_string(item.node) + ": ").c_str(), box);
    out << "\n";
    for (int k = n.size() - 1; k >= 0; --k) {
      if (!n.count[k]) stack.push_back({n.first[k], item.depth + 1});
    }
    for (int k = 0; k < n.size(); ++k) {
      if (!n.count[k]) continue;
      line(item.depth + 1, "Leaf: ", n.box(k));
      out << " objects";
      const auto [first, count] = bvh.leafObjects(n, k);
      for (uint32_t i = first; i < first + count; ++i) out << " " << bvh.objects()[i]->id();
      out << "\n";
    }
  }
}

template void printHierarchy(std::ostream&, const Bvh<float>&);
template void printHierarchy(std::ostream&, const Bvh<double>&);

}  // namespace rt
