// `printbvh`'s picture of a hierarchy.
#pragma once

#include <ostream>

#include "raytrace/accel/bvh.hpp"

namespace rt {

// A summary line, then the tree, one child per line, indented by depth: boxes, and object ids in the leaves.
template <class T> void printHierarchy(std::ostream& out, const Bvh<T>& bvh);

}  // namespace rt
