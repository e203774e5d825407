// What a shape kind gives the stages around its runtime object. A kind is one header, shapes/<kind>.hpp,
// holding its description `XDesc` next to its runtime class, and one entry in ShapeDesc (shape_desc.hpp).
// Every stage reaches a kind only through these members, so a kind missing one fails to compile:
//
//   static bool named(std::string_view)     whether a POV keyword starts it
//   name()                                  the type name reports print ("Sphere")
//   static XDesc read(Reader&, keyword)     its grammar between `keyword {` and its modifiers (below)
//   double smallestFeature() const          the precision budget's lengths (scene/scene_scale)
//   Ball boundingBall() const
//   FlatFaces flatFaces() const             the faces the course tier's offset check samples (scene/tier_domain)
//   static constexpr bool kFloatErrorBound  whether float's error on it is bounded and tested; if not, a scene
//                                           holding it is computed in double (scene/arithmetic)
//   void describe(std::ostream&) const      its `sceneinfo` lines
//   make<T>(const ObjectBuild&) const       its runtime object (shapes/make_object, under its transforms)
#pragma once

#include <array>
#include <cstddef>

#include "raytrace/geometry/math.hpp"
#include "raytrace/geometry/roots.hpp"
#include "raytrace/surface/material.hpp"
#include "raytrace/util/error.hpp"

namespace rt {

// A ball around a shape in its own space. An unbounded shape gives a point of it, with radius 0.
struct Ball {
  glm::dvec3 center;
  double radius;
};

// A flat face: the parallelogram corner + s·u + t·v for s, t in [0, 1], or the triangle s + t ≤ 1.
struct FlatFace {
  glm::dvec3 corner, u, v;
  bool triangle = false;
};
struct FlatFaces {
  std::array<FlatFace, 6> face{};
  size_t count = 0;
};

// What a runtime object is made with besides its description.
struct ObjectBuild {
  const Material& material;
  int id;               // 1-based position in the scene file
  SphereMethod sphere;  // the quadratic chosen for the scene (scene/arithmetic)
  bool course;          // the course tier's transforms (shapes/make_object.hpp)
  bool inverted = false;  // under an odd number of inversions (an `inverse`, a difference's later child)
};

// The calls a kind's read() makes on the scene parser. Each names what it reads ("the sphere radius") for the
// message of a ParseError at the place it stops; `here()` is where the next token starts.
//   glm::dvec3 vec3(const char* what);      double number(const char* what);
//   double positive(const char* what);      double nonNegative(const char* what);
//   void comma(const char* after);          SourceLoc here() const;
//   bool objectNext() const;                ObjectDesc object();   (a whole object, for CSG)
//   std::vector<double> coefficients(size_t n, const char* what);   `<c1, …, cn>`, exactly n numbers (a poly's)
//   bool keyword(std::string_view word);    takes the keyword `word` if it comes next
//   bool valueNext();                       whether a number or vector comes next (one too many, for a list)
//   bool moreNumbers() const;               whether an optional number follows (`, n` in the course language)
//   bool block(std::string_view word, F read);   `word { … }` next: read(reader of its items) (a blob's parts)
//   std::vector<TransformStep> transforms();     the transforms that come next
//   std::string string(const char* what);   std::string findFont(const std::string& name);  ("" if nowhere)
//   std::string findFile(const std::string& name);   where an include file of that name is ("" if nowhere)
//   bool functionNext() const;              whether a function comes next (`function { … }`)
//   bool texture(FaceSurface& s, const void*& source);   a `texture { … }` next: its surface, and the syntax
//                                           it was read from (the same for two uses of one declared texture)
//   bool function(std::shared_ptr<const Function>& into);   a `function { … }` next: its compiled form (null,
//                                           and refused, if it did not compile) (an isosurface's)
//   bool imageFunction(std::shared_ptr<const Function>& into, double& width, double& height);   `function W, H
//                                           { … }` next: its size and its value at (x, y, 0), a pigment
//                                           function's grey (null, and refused, if it did not compile) (a
//                                           height field's)
// The course language has no strings, keywords inside a shape or blocks: its parser refuses the calls for them.
// A template parameter rather than a base class: the parser's calls stay inline in its per-object loop.

}  // namespace rt
