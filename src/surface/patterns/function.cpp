// function { … }: a user function's value at the point (POV-Ray 3.7 manual "Function as pattern"), wrapped
// into [0, 1) as every pattern's value is (surface/pigment.cpp).
#include "raytrace/surface/function.hpp"
#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class FunctionPattern final : public Pattern {
 public:
  explicit FunctionPattern(std::shared_ptr<const Function> f) : f_(std::move(f)) {}
  double value(const glm::dvec3& p) const override { return f_->at(p); }

 private:
  std::shared_ptr<const Function> f_;
};

}  // namespace

std::unique_ptr<Pattern> makeFunctionPattern(const PatternArgs& a) { return std::make_unique<FunctionPattern>(a.function); }

}  // namespace rt
