// pigment_pattern { PIGMENT }: the pigment's colour as a grey, 0.297·r + 0.589·g + 0.114·b, its filter and
// transmit left out (POV-Ray 3.7 manual, "Pigment Pattern"; the weights are POV-Ray's values of the pattern).
#include "raytrace/surface/patterns.hpp"
#include "raytrace/surface/pigment.hpp"

namespace rt {

namespace {

class PigmentPattern final : public Pattern {
 public:
  explicit PigmentPattern(std::shared_ptr<const Pigment> pigment) : pigment_(std::move(pigment)) {}
  double value(const glm::dvec3& p) const override {
    const Color c = pigment_->at(p).rgb;
    return 0.297 * double(c.r) + 0.589 * double(c.g) + 0.114 * double(c.b);
  }
  bool readsNormal() const override { return rt::readsNormal(*pigment_); }

 private:
  std::shared_ptr<const Pigment> pigment_;
};

}  // namespace

std::unique_ptr<Pattern> makePigmentPattern(const PatternArgs& a) { return std::make_unique<PigmentPattern>(a.pigment); }

}  // namespace rt
