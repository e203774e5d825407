// slope { <direction>, lo, hi altitude <altitude>, lo, hi }: how far the surface's normal turns toward the
// direction, 0.5 + asin(n·d)/π (0 facing away, 0.5 across, 1 along it), blended with a gradient along the
// altitude vector, each weighted by its vector's length (POV-Ray 3.7 manual, "Slope Pattern"; the asin and
// the unclamped ranges measured on POV-Ray's pictures, tests/surface/patterns/test_slope.cpp). The normal is
// the world's, which neither the pattern's nor the object's transforms turn, as POV-Ray's pictures show.
#include <algorithm>
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Slope final : public Pattern {
 public:
  explicit Slope(const SlopeArgs& a)
      : direction_(glm::normalize(a.direction)),
        lo_(a.lo),
        span_(a.hi - a.lo),
        altitudeLo_(a.altitudeLo),
        altitudeSpan_(a.altitudeHi - a.altitudeLo),
        slopeWeight_(glm::length(a.direction)),
        altitudeWeight_(glm::length(a.altitude)),
        altitude_(altitudeWeight_ > 0 ? a.altitude / altitudeWeight_ : glm::dvec3(0)) {}

  double value(const glm::dvec3& p) const override {
    constexpr double kPi = 3.14159265358979323846;
    const double cosine = std::clamp(glm::dot(surfaceNormal(), direction_), -1.0, 1.0);
    const double slope = (0.5 + std::asin(cosine) / kPi - lo_) / span_;
    if (altitudeWeight_ == 0) return slope;
    const double altitude = (glm::dot(p, altitude_) - altitudeLo_) / altitudeSpan_;
    return (slopeWeight_ * slope + altitudeWeight_ * altitude) / (slopeWeight_ + altitudeWeight_);
  }
  bool readsNormal() const override { return true; }

 private:
  glm::dvec3 direction_;
  double lo_, span_, altitudeLo_, altitudeSpan_, slopeWeight_, altitudeWeight_;
  glm::dvec3 altitude_;
};

}  // namespace

std::unique_ptr<Pattern> makeSlope(const PatternArgs& a) { return std::make_unique<Slope>(a.slope); }

}  // namespace rt
