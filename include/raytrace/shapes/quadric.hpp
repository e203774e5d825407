#pragma once

#include <limits>
#include <memory>
#include <ostream>
#include <string_view>

#include "raytrace/shapes/algebraic.hpp"
#include "raytrace/shapes/kind.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

// What a file says of a quadric: `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }`, the surface
// A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0, solid where it is negative (POV-Ray 3.7
// manual §3.4.5.3.6). Usually unbounded: a scene bounds it by an intersection.
struct QuadricDesc {
  glm::dvec3 squares, products, linear;  // <A,B,C>, <D,E,F>, <G,H,I>
  double constant;                       // J

  static bool named(std::string_view word) { return word == "quadric"; }
  static const char* name() { return "Quadric"; }
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static QuadricDesc read(Reader& r, std::string_view) {
    QuadricDesc q;
    const SourceLoc at = r.here();
    q.squares = r.vec3("the quadric's x², y² and z² coefficients");
    r.comma("after the quadric's x², y² and z² coefficients");
    q.products = r.vec3("the quadric's xy, xz and yz coefficients");
    r.comma("after the quadric's xy, xz and yz coefficients");
    q.linear = r.vec3("the quadric's x, y and z coefficients");
    r.comma("after the quadric's x, y and z coefficients");
    q.constant = r.number("the quadric's constant");
    if (q.squares == glm::dvec3(0) && q.products == glm::dvec3(0) && q.linear == glm::dvec3(0)) {
      throw ParseError(at, "the quadric's coefficients of x, y and z are all zero");
    }
    return q;
  }
  double smallestFeature() const { return std::numeric_limits<double>::infinity(); }  // none known
  Ball boundingBall() const { return {glm::dvec3(0), 0}; }  // unbounded: the origin its equation is written about
  FlatFaces flatFaces() const { return {}; }                // computed in double
  void describe(std::ostream& out) const {
    out << "- Squares: " << braces(squares) << "\n- Products: " << braces(products) << "\n- Linear: "
        << braces(linear) << "\n- Constant: " << fixed4(constant) << "\n";
  }
  std::vector<Monomial> terms() const {
    return {{squares.x, 2, 0, 0},  {squares.y, 0, 2, 0},  {squares.z, 0, 0, 2}, {products.x, 1, 1, 0},
            {products.y, 1, 0, 1}, {products.z, 0, 1, 1}, {linear.x, 1, 0, 0},  {linear.y, 0, 1, 0},
            {linear.z, 0, 0, 1},   {constant, 0, 0, 0}};
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Algebraic<T>>(AlgebraicSurface(terms(), RootMethod::Auto),
                                          std::numeric_limits<double>::infinity(), std::nullopt, name(), b.material,
                                          b.id);
  }
};

}  // namespace rt
