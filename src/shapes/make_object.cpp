#include "raytrace/shapes/make_object.hpp"

#include <cmath>
#include <optional>

#include "raytrace/shapes/clipped.hpp"
#include "raytrace/shapes/inverted.hpp"
#include "raytrace/shapes/transformed.hpp"

namespace rt {

namespace {

// "Model no more than a scene needs": a sphere moved by a similarity (any mix of rotations, uniform scales and
// translations, as on the thousands of spheres of balls2 and gnarly) is still a sphere, centred at M·c with
// radius s·r. Folding the matrix into it saves the two matrix products per test and keeps its bounds tight.
// The similarity test is LᵀL = s²·I for the linear part L, up to the rounding of the rotation matrices.
// Nothing when there is nothing to fold: not a sphere, or not moved, or not by a similarity.
std::optional<ObjectDesc> foldSimilarityIntoSphere(const ObjectDesc& desc) {
  const auto* sphere = std::get_if<SphereDesc>(&desc.shape);
  if (!sphere || desc.transforms.empty()) return std::nullopt;
  const glm::dmat4 worldFromObject = desc.worldFromObject();
  const glm::dmat3 linear(worldFromObject);
  const glm::dmat3 gram = glm::transpose(linear) * linear;
  const double s2 = gram[0][0];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (std::abs(gram[i][j] - (i == j ? s2 : 0.0)) > 1e-12 * s2) return std::nullopt;
    }
  }
  ObjectDesc folded = desc;
  folded.shape = SphereDesc{glm::dvec3(worldFromObject * glm::dvec4(sphere->center, 1.0)),
                            std::sqrt(s2) * sphere->radius};
  folded.transforms.clear();
  return folded;
}

}  // namespace

template <class T>
std::unique_ptr<Object<T>> makeObject(const ObjectDesc& desc, SphereMethod sphere, int id, bool course,
                                      bool inverted) {
  const std::optional<ObjectDesc> folded = course ? std::nullopt : foldSimilarityIntoSphere(desc);
  const ObjectDesc& o = folded ? *folded : desc;
  const ObjectBuild build{o.material, id, sphere, course, inverted != o.inverse};
  auto object = std::visit([&](const auto& k) { return k.template make<T>(build); }, o.shape);
  object->setTexture(o.texture);
  const Mat4<T> m = course ? composeTransforms<T>(o.transforms) : Mat4<T>(o.worldFromObject());
  // An identity transform (`translate <0,0,0>`) costs nothing: the shape is used as it is.
  if (m != Mat4<T>(T(1))) object = std::make_unique<Transformed<T>>(std::move(object), m, o.material, id, course);
  if (o.inverse) object = std::make_unique<Inverted<T>>(std::move(object), o.material, id);
  if (o.clip.empty()) return object;
  std::vector<std::unique_ptr<Object<T>>> clips;
  for (const ClipDesc& c : o.clip) {
    ObjectDesc placed = c.object;
    placed.transforms.insert(placed.transforms.end(), desc.transforms.begin() + long(c.from), desc.transforms.end());
    clips.push_back(makeObject<T>(placed, sphere, id, course));
  }
  return std::make_unique<Clipped<T>>(std::move(object), std::move(clips), o.material, id);
}

template std::unique_ptr<Object<float>> makeObject<float>(const ObjectDesc&, SphereMethod, int, bool, bool);
template std::unique_ptr<Object<double>> makeObject<double>(const ObjectDesc&, SphereMethod, int, bool, bool);

}  // namespace rt
