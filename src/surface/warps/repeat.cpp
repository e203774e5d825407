// The repeat warp (POV-Ray 3.7 manual, "Repeat Warp"): the slice of the pattern between 0 and the width along
// one axis, copied side by side. Copy n (n = floor(a / width) along the axis a) is shifted by n·offset, and an
// odd copy is first mirrored along each flipped axis: within the slice along the repeat axis, across the origin
// along the others (as POV-Ray's pattern values show: docs/povray-noise.md, "Warps").
#include <cmath>

#include "raytrace/surface/warp.hpp"

namespace rt {

namespace {

class RepeatWarp final : public Warp {
 public:
  explicit RepeatWarp(const RepeatWarpArgs& a) : a_(a) {}

  glm::dvec3 apply(const glm::dvec3& p) const override {
    const double n = std::floor(p[a_.axis] / a_.width);
    glm::dvec3 q = p;
    q[a_.axis] -= n * a_.width;
    if (std::fmod(n, 2.0) != 0) {
      for (int k = 0; k < 3; ++k) {
        if (a_.flip[k]) q[k] = k == a_.axis ? a_.width - q[k] : -q[k];
      }
    }
    return q + n * a_.offset;
  }

 private:
  RepeatWarpArgs a_;
};

}  // namespace

std::unique_ptr<Warp> makeRepeatWarp(const RepeatWarpArgs& args) { return std::make_unique<RepeatWarp>(args); }

}  // namespace rt
