// gradient <v>: the distance along v, repeating every unit (POV-Ray 3.7 manual, "Gradient").
#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Gradient final : public Pattern {
 public:
  explicit Gradient(const glm::dvec3& v) : v_(v) {}
  double value(const glm::dvec3& p) const override { return glm::dot(p, v_); }

 private:
  glm::dvec3 v_;
};

}  // namespace

std::unique_ptr<Pattern> makeGradient(const PatternArgs& a) { return std::make_unique<Gradient>(a.vector); }

}  // namespace rt
