// Constructive solid geometry: objects combined as POV-Ray combines them, by which of each child's surfaces
// lie inside or outside the others.
#pragma once

#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"

namespace rt {

struct ObjectDesc;

// union: every child's surface; merge: the surfaces outside the other children (no inner walls, for glass);
// intersection: the surfaces inside all the others; difference: the first child less all the others.
enum class CsgOp { Union, Merge, Intersection, Difference };

// What a file says of a CSG group: `union { objects modifiers }`, and likewise `merge`, `intersection`,
// `difference`. Each child keeps its own material and transforms; the group's transforms move them all.
struct CsgDesc {
  CsgOp op = CsgOp::Union;
  std::vector<ObjectDesc> children;

  static std::optional<CsgOp> opNamed(std::string_view word);
  static bool named(std::string_view word) { return opNamed(word).has_value(); }
  const char* name() const;  // "Union", "Merge", "Intersection", "Difference"
  // Whether a hit on a child counts decides on inside tests at points of other surfaces; float's error there,
  // where two surfaces meet, is not bounded yet.
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static CsgDesc read(Reader& r, std::string_view word) {
    CsgDesc csg{*opNamed(word), {}};
    const SourceLoc at = r.here();
    while (r.objectNext()) csg.children.push_back(r.object());
    if (csg.children.empty()) throw ParseError(at, "expected an object inside '" + std::string(word) + "'");
    return csg;
  }
  double smallestFeature() const;
  Ball boundingBall() const;
  FlatFaces flatFaces() const { return {}; }  // computed in double (kFloatErrorBound): no offset to check
  void describe(std::ostream& out) const;
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const;
};

template <class T> class Csg final : public Object<T> {
 public:
  Csg(CsgOp op, std::vector<std::unique_ptr<Object<T>>> children, const char* name, const Material& material, int id);

  // The closest hit on a child that the operation keeps. The hit is the child's own: its material and its
  // normal, turned inward on the parts a difference cuts away with.
  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  bool inside(const Vec3<T>& p) const override;
  std::optional<Aabb<T>> bounds() const override;
  const char* name() const override { return name_; }
  void forEachMaterial(const std::function<void(const Material&)>& f) const override {
    for (const auto& c : children_) c->forEachMaterial(f);
  }

 private:
  // Whether a point on child i's surface is a surface of the whole.
  bool keeps(size_t i, const Vec3<T>& p) const;
  bool insideAnyOther(size_t i, const Vec3<T>& p) const;
  bool outsideOthers(size_t i, const Vec3<T>& p) const;

  CsgOp op_;
  std::vector<std::unique_ptr<Object<T>>> children_;
  const char* name_;
};

}  // namespace rt
