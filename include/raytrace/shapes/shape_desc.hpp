// The shape kinds: one entry each in ShapeDesc (shapes/kind.hpp says what a kind provides), and the object a
// scene file describes with one of them. Adding a kind is its header and its entry here; every stage that
// visits a ShapeDesc then handles it, or fails to compile.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "raytrace/geometry/transform.hpp"
#include "raytrace/shapes/blob.hpp"
#include "raytrace/shapes/box.hpp"
#include "raytrace/shapes/cone.hpp"
#include "raytrace/shapes/csg.hpp"
#include "raytrace/shapes/cylinder.hpp"
#include "raytrace/shapes/disc.hpp"
#include "raytrace/shapes/isosurface.hpp"
#include "raytrace/shapes/julia_fractal.hpp"
#include "raytrace/shapes/lathe.hpp"
#include "raytrace/shapes/mesh.hpp"
#include "raytrace/shapes/plane.hpp"
#include "raytrace/shapes/poly.hpp"
#include "raytrace/shapes/polygon.hpp"
#include "raytrace/shapes/prism.hpp"
#include "raytrace/shapes/quadric.hpp"
#include "raytrace/shapes/sor.hpp"
#include "raytrace/shapes/sphere.hpp"
#include "raytrace/shapes/sphere_sweep.hpp"
#include "raytrace/shapes/superellipsoid.hpp"
#include "raytrace/shapes/torus.hpp"
#include "raytrace/shapes/text.hpp"
#include "raytrace/shapes/triangle.hpp"
#include "raytrace/surface/material.hpp"
#include "raytrace/util/error.hpp"

namespace rt {

using ShapeDesc = std::variant<SphereDesc, PlaneDesc, TriangleDesc, BoxDesc, ConeDesc, CylinderDesc, CsgDesc, TorusDesc,
                               QuadricDesc, PolyDesc, TextDesc, PrismDesc, LatheDesc, SorDesc, DiscDesc,
                               SuperellipsoidDesc, BlobDesc, MeshDesc, PolygonDesc, IsosurfaceDesc,
                               SphereSweepDesc, JuliaFractalDesc>;

struct ClipDesc;

// An object's finish as written, held by a pointer that the objects of one surface share: a million objects'
// descriptions are then 40 bytes smaller each, fewer pages to fill. No pointer reads as the default Finish.
class SharedFinish {
 public:
  SharedFinish() = default;
  SharedFinish(const Finish& f) : finish_(std::make_shared<const Finish>(f)) {}  // NOLINT: implicit
  const Finish& operator*() const { return finish_ ? *finish_ : kDefault; }
  const Finish* operator->() const { return &**this; }

 private:
  static inline const Finish kDefault{};
  std::shared_ptr<const Finish> finish_;
};

struct ObjectDesc {
  ShapeDesc shape;
  Material material;
  SharedFinish finish;  // POV: as written, for sceneinfo
  SourceLoc loc;  // where the object starts, for messages
  bool textured = false;  // the file gave it a pigment or finish of its own (a CSG child without takes its group's)
  bool noShadow = false;  // POV-Ray's no_shadow: it casts no shadow
  bool noImage = false;       // POV-Ray's no_image: image rays do not see it (accel/scene's Sight)
  bool noReflection = false;  // POV-Ray's no_reflection: reflected rays do not see it
  bool noRadiosity = false;   // POV-Ray's no_radiosity: gathered rays (-gi) do not see it
  bool inverse = false;   // POV-Ray's inverse: inside and outside swap (shapes/inverted)
  std::optional<bool> hollow;  // POV-Ray's hollow as written (SurfaceExtras::hollow; a CSG's goes to its children)
  // A texture that varies over the surface, in world space; none when `material` is the same everywhere.
  std::shared_ptr<const Texture> texture;
  // The POV transforms as written (§c.10), in file order; a scene built in code gives its own the same way.
  std::vector<TransformStep> transforms;
  std::vector<ClipDesc> clip;  // POV-Ray's clipped_by: the surface inside all of these remains (shapes/clipped)

  // The transforms composed in double. Made when asked, not stored: most objects have none, and the matrix
  // would be a third of every object's description, to fill, copy and page in.
  glm::dmat4 worldFromObject() const { return composeTransforms<double>(transforms); }
};

// A clipping object. The transforms written after its clipped_by, its owner's from `from` on, move it too.
struct ClipDesc {
  ObjectDesc object;
  size_t from;
};

// As POV-Ray does: a CSG group's child without a texture of its own takes the group's, and so do its own
// children.
inline void passTextureDown(ObjectDesc& group) {
  auto* csg = std::get_if<CsgDesc>(&group.shape);
  if (!csg || !group.textured) return;
  for (ObjectDesc& child : csg->children) {
    if (child.textured) continue;
    child.material = group.material;
    child.finish = group.finish;
    child.texture = group.texture;
    child.textured = true;
    passTextureDown(child);
  }
}

template <class K> struct KindTag {
  using Kind = K;
};

template <class F, size_t... I> bool anyShapeKind(F& f, std::index_sequence<I...>) {
  return (f(KindTag<std::variant_alternative_t<I, ShapeDesc>>{}) || ...);
}
// Calls f(KindTag<K>{}) for each kind K in turn while it returns false; true when one did.
template <class F> bool anyShapeKind(F&& f) {
  return anyShapeKind(f, std::make_index_sequence<std::variant_size_v<ShapeDesc>>{});
}

// The kind named by the keyword `word`, read by `reader` (see shapes/kind.hpp); nothing for any other word.
template <class Reader> std::optional<ShapeDesc> readShape(std::string_view word, Reader& reader) {
  std::optional<ShapeDesc> shape;
  anyShapeKind([&](auto tag) {
    using K = typename decltype(tag)::Kind;
    if (!K::named(word)) return false;
    shape = K::read(reader, word);
    return true;
  });
  return shape;
}

// Whether `word` starts a shape.
inline bool isShapeKeyword(std::string_view word) {
  return anyShapeKind([&](auto tag) { return decltype(tag)::Kind::named(word); });
}

// The type name reports print ("Sphere", "Plane", …).
inline const char* shapeName(const ShapeDesc& shape) {
  return std::visit([](const auto& s) { return s.name(); }, shape);
}

}  // namespace rt
