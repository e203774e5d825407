#pragma once

#include <algorithm>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/shapes/algebraic.hpp"
#include "raytrace/shapes/kind.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

// What a file says of a polynomial surface: `cubic { <20 coefficients> }`, `quartic { <35 coefficients> }`
// or `poly { order, <coefficients> }`, each with an optional `sturm`: the sum of the coefficients times their
// terms in POV-Ray's order (povPolyTerms) equals 0, solid where it is negative (POV-Ray 3.7 manual
// §3.4.5.3.2–5). POV-Ray's orders go up to 35; ours up to 7.
struct PolyDesc {
  static constexpr int kMaxOrder = Polynomial::kMaxDegree;
  int order;
  std::vector<double> coefficients;
  bool sturm = false;  // POV-Ray's `sturm`, a modifier (povray/scene_builder)

  static bool named(std::string_view word) { return word == "cubic" || word == "quartic" || word == "poly"; }
  const char* name() const { return order == 3 ? "Cubic" : order == 4 ? "Quartic" : "Poly"; }
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static PolyDesc read(Reader& r, std::string_view word) {
    PolyDesc p;
    p.order = word == "cubic" ? 3 : word == "quartic" ? 4 : 0;
    if (p.order == 0) {
      const SourceLoc at = r.here();
      const double order = r.number("the poly order");
      if (!(order >= 2 && order < kMaxOrder + 1)) {
        throw ParseError(at, "the poly order must be from 2 to " + std::to_string(kMaxOrder) + ", found " +
                                 shortest(order));
      }
      p.order = int(order);  // as POV-Ray does, the whole part
      r.comma("after the poly order");
    }
    const SourceLoc at = r.here();
    const std::string what = "the " + std::string(word) + " coefficients";
    p.coefficients = r.coefficients(povPolyTermCount(p.order), what.c_str());
    if (std::all_of(p.coefficients.begin(), p.coefficients.end() - 1, [](double c) { return c == 0; })) {
      throw ParseError(at, "the " + std::string(word) + " coefficients of x, y and z are all zero");
    }
    return p;
  }
  double smallestFeature() const { return std::numeric_limits<double>::infinity(); }  // none known
  Ball boundingBall() const { return {glm::dvec3(0), 0}; }  // unbounded: the origin its equation is written about
  FlatFaces flatFaces() const { return {}; }                // computed in double
  void describe(std::ostream& out) const {
    out << "- Order: " << order << "\n- Terms: " << termsText(povPolyTerms(order, coefficients))
        << "\n- Sturm: " << (sturm ? "yes" : "no") << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Algebraic<T>>(AlgebraicSurface(povPolyTerms(order, coefficients),
                                                           sturm ? RootMethod::Sturm : RootMethod::Auto),
                                          std::numeric_limits<double>::infinity(), std::nullopt, name(), b.material,
                                          b.id);
  }
};

}  // namespace rt
