#pragma once

#include <cmath>
#include <memory>
#include <ostream>
#include <string_view>
#include <vector>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Superellipsoid;

// What a file says of a superellipsoid: `superellipsoid { <e, n> }`, POV-Ray's superquadric ellipsoid
// f(x,y,z) = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) − 1 = 0 (POV-Ray 3.7 manual §3.4.5.1.14), solid where
// f < 0, inside the box from <−1,−1,−1> to <1,1,1>; e = n = 1 is the unit sphere.
struct SuperellipsoidDesc {
  double e, n;

  static bool named(std::string_view word) { return word == "superellipsoid"; }
  static const char* name() { return "Superellipsoid"; }
  static constexpr bool kFloatErrorBound = false;  // an iterative root, computed in double

  template <class Reader> static SuperellipsoidDesc read(Reader& r, std::string_view) {
    const SourceLoc at = r.here();
    const std::vector<double> en = r.coefficients(2, "the superellipsoid exponents");
    if (!(en[0] > 0) || !(en[1] > 0)) {
      throw ParseError(at, "the superellipsoid exponents must be greater than 0, found <" + shortest(en[0]) + ", " +
                               shortest(en[1]) + ">");
    }
    return {en[0], en[1]};
  }
  double smallestFeature() const { return 1; }
  Ball boundingBall() const { return {glm::dvec3(0), std::sqrt(3.0)}; }
  FlatFaces flatFaces() const { return {}; }  // computed in double (kFloatErrorBound): no offset to check
  void describe(std::ostream& out) const { out << "- Exponents: " << fixed4(e) << " " << fixed4(n) << "\n"; }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Superellipsoid<T>>(e, n, b.material, b.id);
  }
};

// Computed in double whatever T is: the powers of tiny or large exponents need its range.
template <class T> class Superellipsoid final : public Object<T> {
 public:
  Superellipsoid(double e, double n, const Material& material, int id) : Object<T>(material, id), e_(e), n_(n) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return Aabb<T>{Vec3<T>(-1), Vec3<T>(1)}; }
  bool inside(const Vec3<T>& p) const override { return f(glm::dvec3(p)) < 0; }
  const char* name() const override { return SuperellipsoidDesc::name(); }

 private:
  double f(const glm::dvec3& p) const;
  glm::dvec3 normal(const glm::dvec3& p) const;

  double e_, n_;
};

}  // namespace rt
