#pragma once

#include <memory>
#include <ostream>
#include <string_view>
#include <vector>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class JuliaFractal;

// The iterated function f of h ← f(h) + p (POV-Ray 3.7 manual, "Julia Fractal").
enum class JuliaFunction { Sqr, Cube };

// What a file says of a julia_fractal (POV-Ray 3.7 manual, "Julia Fractal"): the 3-D slice of a 4-D Julia set,
// the points whose orbit under h ← f(h) + p stays within the bailout radius for max_iteration terms, in
// quaternion or hypercomplex algebra. The ray marches in steps no shorter than 1/precision (docs/shapes.md).
struct JuliaFractalParams {
  glm::dvec4 constant{0};  // p
  bool hypercomplex = false;
  JuliaFunction function = JuliaFunction::Sqr;
  int maxIteration = 20;
  double precision = 20;  // as written; below 1 it counts as 1
  glm::dvec4 slice{0, 0, 0, 1};  // the 4-D normal, unit length
  double sliceDistance = 0;

  // The squared bailout radius, which is also the squared radius of the bounding sphere.
  double bailout() const;
  double step() const { return 1 / std::max(precision, 1.0); }
};

// The description holds its parameters behind a pointer, as an isosurface's: every object's description is as
// large as the largest kind's.
struct JuliaFractalDesc {
  std::shared_ptr<const JuliaFractalParams> params;

  static bool named(std::string_view word) { return word == "julia_fractal"; }
  static const char* name() { return "JuliaFractal"; }
  static constexpr bool kFloatErrorBound = false;  // an iterated orbit, computed in double

  template <class Reader> static JuliaFractalDesc read(Reader& r, std::string_view) {
    JuliaFractalParams d;
    const std::vector<double> p = r.coefficients(4, "the julia_fractal parameter's components");
    d.constant = {p[0], p[1], p[2], p[3]};
    SourceLoc cubeAt;
    for (;;) {
      const SourceLoc at = r.here();
      if (r.keyword("quaternion")) {
        d.hypercomplex = false;
      } else if (r.keyword("hypercomplex")) {
        d.hypercomplex = true;
      } else if (r.keyword("sqr")) {
        d.function = JuliaFunction::Sqr;
      } else if (r.keyword("cube")) {
        d.function = JuliaFunction::Cube;
        cubeAt = at;
      } else if (r.keyword("max_iteration")) {
        d.maxIteration = static_cast<int>(r.positive("the julia_fractal max_iteration"));
        if (d.maxIteration < 1) d.maxIteration = 1;
      } else if (r.keyword("precision")) {
        d.precision = r.number("the julia_fractal precision");
      } else if (r.keyword("slice")) {
        const SourceLoc normalAt = r.here();
        const std::vector<double> n = r.coefficients(4, "the julia_fractal slice normal's components");
        r.comma("the slice normal");
        d.sliceDistance = r.number("the julia_fractal slice distance");
        const glm::dvec4 normal(n[0], n[1], n[2], n[3]);
        // The manual: a zero normal, or one with a zero fourth component, is illegal.
        if (normal.w == 0) throw ParseError(normalAt, "the julia_fractal slice normal needs a non-zero fourth component");
        d.slice = glm::normalize(normal);
      } else {
        break;
      }
    }
    // POV-Ray 3.7's hypercomplex cube draws what its inside() calls the sqr set, yet not the sqr picture.
    if (d.hypercomplex && d.function == JuliaFunction::Cube) {
      throw ParseError(cubeAt, "'cube' with 'hypercomplex' is not supported yet");
    }
    return {std::make_shared<const JuliaFractalParams>(d)};
  }
  double smallestFeature() const { return params->step(); }
  Ball boundingBall() const { return {glm::dvec3(0), std::sqrt(params->bailout())}; }
  FlatFaces flatFaces() const { return {}; }  // computed in double (kFloatErrorBound): no offset to check
  void describe(std::ostream& out) const;
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<JuliaFractal<T>>(*params, b.material, b.id);
  }
};

// Computed in double whatever T is.
template <class T> class JuliaFractal final : public Object<T> {
 public:
  JuliaFractal(const JuliaFractalParams& d, const Material& material, int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override;
  bool inside(const Vec3<T>& p) const override { return escape(glm::dvec3(p)) < 0; }
  const char* name() const override { return JuliaFractalDesc::name(); }

  // The first term of p's orbit outside the bailout radius, or -1 when the first max_iteration stay inside.
  int escape(const glm::dvec3& p) const {
    double ignored;
    return orbit(p, ignored);
  }
  // |h_k|², the squared norm of the orbit's k-th term, and its gradient.
  double normSquared(const glm::dvec3& p, int k) const;
  glm::dvec3 gradient(const glm::dvec3& p, int k) const;

 private:
  // escape(p), and in `step` how far the march may go from p: the quaternions' distance estimate where the
  // orbit escapes, never less than the precision's step.
  int orbit(const glm::dvec3& p, double& step) const;
  glm::dvec4 point4(const glm::dvec3& p) const;

  JuliaFractalParams d_;
  double bailout_, radius_;
};

}  // namespace rt
