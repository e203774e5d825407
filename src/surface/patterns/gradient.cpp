// gradient <v>: the distance along v, repeating every unit (POV-Ray 3.7 manual, "Gradient").
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Gradient final : public Pattern {
 public:
  explicit Gradient(const glm::dvec3& v) : v_(v) {}
  // Beyond 1 the value wraps to its fraction, below 0 it is left to the wave's wrapping (as POV-Ray does).
  double value(const glm::dvec3& p) const override {
    const double d = glm::dot(p, v_);
    return d > 1 ? std::fmod(d, 1.0) : d;
  }

 private:
  glm::dvec3 v_;
};

}  // namespace

std::unique_ptr<Pattern> makeGradient(const PatternArgs& a) { return std::make_unique<Gradient>(a.vector); }

}  // namespace rt
