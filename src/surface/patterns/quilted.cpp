// quilted: unit cubes with rounded seams between them, the seam's profile a cubic with control0 and control1
// (POV-Ray 3.7 manual, "Quilted Pattern"). The manual gives no formula; this one fits POV-Ray's renders:
// with d the point less its cube's centre and r = |d|, the profile is the cubic Bézier c(r) through 0,
// control0, control1, 1; the pigment's value is c(r)·(|dx| + |dy| + |dz|)·2/(3√3), and as a normal it bends
// the normal toward d by c(r)·2/√3 per unit of amount.
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Quilted final : public Pattern {
 public:
  Quilted(double control0, double control1) : c0_(control0), c1_(control1) {}
  double value(const glm::dvec3& p) const override {
    const glm::dvec3 d = offset(p);
    return profile(glm::length(d)) * (std::abs(d.x) + std::abs(d.y) + std::abs(d.z)) * 2 / (3 * std::sqrt(3.0));
  }
  bool hasBump() const override { return true; }
  glm::dvec3 bump(const glm::dvec3& p) const override {
    const glm::dvec3 d = offset(p);
    return -profile(glm::length(d)) * 2 / std::sqrt(3.0) * d;
  }

 private:
  static glm::dvec3 offset(const glm::dvec3& p) { return p - glm::floor(p) - 0.5; }
  double profile(double t) const {
    const double s = 1 - t;
    return 3 * s * s * t * c0_ + 3 * s * t * t * c1_ + t * t * t;
  }
  double c0_, c1_;
};

}  // namespace

std::unique_ptr<Pattern> makeQuilted(const PatternArgs& a) { return std::make_unique<Quilted>(a.control0, a.control1); }

}  // namespace rt
