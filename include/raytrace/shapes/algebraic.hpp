// What the polynomial shapes share (torus, quadric, cubic, quartic, poly): the surface f(x, y, z) = 0 of a
// polynomial in three variables, solid where f < 0 as POV-Ray has it, and the runtime object that draws one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "raytrace/geometry/math.hpp"
#include "raytrace/geometry/polynomial.hpp"
#include "raytrace/shapes/object.hpp"

namespace rt {

// One term c·x^x·y^y·z^z.
struct Monomial {
  double c;
  int x, y, z;
};

// The terms of POV-Ray's `poly` of an order (2 to 7) from its coefficients in POV-Ray's order: the powers of x
// from the highest down, within each those of y, within each those of z (the table of the POV-Ray 3.7 manual,
// §3.4.5.3.5). Terms of coefficient 0 are left out.
std::vector<Monomial> povPolyTerms(int order, const std::vector<double>& coefficients);
// The terms as `sceneinfo` lists them: "1.0000 x^2 y, -1.0000".
std::string termsText(const std::vector<Monomial>& terms);
// How many coefficients a poly of that order has: (order+1)(order+2)(order+3)/6.
inline size_t povPolyTermCount(int order) { return size_t((order + 1) * (order + 2) * (order + 3) / 6); }

class AlgebraicSurface {
 public:
  AlgebraicSurface(std::vector<Monomial> terms, RootMethod method);

  double value(const glm::dvec3& p) const;
  glm::dvec3 gradient(const glm::dvec3& p) const;

  // The smallest t in the open interval (lo, hi) where o + t·d meets the surface, looking only within `reach`
  // of the origin (∞ for a surface without bounds). A root that its own rounding error could put at or below
  // lo is not one: it is the surface a spawned ray starts from.
  std::optional<double> firstHit(const glm::dvec3& o, const glm::dvec3& d, double lo, double hi, double reach) const;

 private:
  // Σ|c|·q.x^x·q.y^y·q.z^z: the sum of the terms' magnitudes at a point of non-negative coordinates.
  double magnitude(const glm::dvec3& q) const;

  std::vector<Monomial> terms_;
  int degree_;
  RootMethod method_;
};

// A polynomial shape at run time, computed in double whatever T is (its kinds are not float-bounded).
template <class T> class Algebraic final : public Object<T> {
 public:
  // `reach`: a ball around the origin that holds the whole surface, ∞ if none; `box` its bounds, if any.
  Algebraic(AlgebraicSurface surface, double reach, std::optional<Aabb<T>> box, const char* name,
            const Material& material, int id)
      : Object<T>(material, id), surface_(std::move(surface)), reach_(reach), box_(box), name_(name) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return box_; }
  bool inside(const Vec3<T>& p) const override { return surface_.value(glm::dvec3(p)) < 0; }
  const char* name() const override { return name_; }

 private:
  AlgebraicSurface surface_;
  double reach_;
  std::optional<Aabb<T>> box_;
  const char* name_;
};

}  // namespace rt
