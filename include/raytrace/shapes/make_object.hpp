// A described object made into the runtime object that answers rays: its kind's shape under its transforms.
#pragma once

#include <memory>

#include "raytrace/shapes/object.hpp"
#include "raytrace/shapes/shape_desc.hpp"

namespace rt {

// The object `desc` describes, with the 1-based `id` and the scene's sphere quadratic. `course`: the course
// tier's arithmetic (scene/arithmetic.hpp), which intersects every transformed object on the transformed ray
// with the matrix composed in T, as its reference does; otherwise a sphere moved by a similarity is folded
// into a world sphere, and the matrix is composed in double. `inverted`: the object lies inside an odd number
// of inversions (ObjectBuild::inverted).
template <class T>
std::unique_ptr<Object<T>> makeObject(const ObjectDesc& desc, SphereMethod sphere, int id, bool course,
                                      bool inverted = false);

}  // namespace rt
