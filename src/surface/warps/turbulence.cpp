// The turbulence warp (POV-Ray 3.7 manual, "Turbulence Warp"): the turbulence a pattern's own `turbulence`
// applies, standing where the warp is written among the transforms.
#include "raytrace/surface/warp.hpp"

namespace rt {

namespace {

class TurbulenceWarp final : public Warp {
 public:
  explicit TurbulenceWarp(const Turbulence& t) : t_(t) {}
  glm::dvec3 apply(const glm::dvec3& p) const override { return p + turbulentOffset(p, t_) * t_.amount; }

 private:
  Turbulence t_;
};

}  // namespace

std::unique_ptr<Warp> makeTurbulenceWarp(const Turbulence& turbulence) {
  return std::make_unique<TurbulenceWarp>(turbulence);
}

}  // namespace rt
