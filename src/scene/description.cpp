#include "raytrace/scene/description.hpp"

namespace rt {

const char* shapeName(const ShapeDesc& shape) {
  static const char* const names[] = {"Sphere", "Plane", "Triangle", "Box", "Cone", "Cylinder"};
  static_assert(std::variant_size_v<ShapeDesc> == 6);
  return names[shape.index()];
}

}  // namespace rt
