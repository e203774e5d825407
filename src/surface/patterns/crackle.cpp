// crackle: cells around random points, one in each unit cube; the value weighs the distances to the nearest
// three points by `form` (default F2 − F1, the cells' walls), clamped to [0, 1] as POV-Ray clamps it; `solid`
// gives a whole cell the noise at its point (POV-Ray 3.7 manual, "Crackle Pattern"; the points and every rule
// here measured from POV-Ray: docs/povray-noise.md).
#include <algorithm>
#include <cmath>
#include <limits>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Crackle final : public Pattern {
 public:
  Crackle(const CrackleArgs& a, NoiseChoice n) : a_(a), noise_(std::move(n)) {}

  double value(const glm::dvec3& p) const override {
    const glm::ivec3 base(glm::floor(p));
    const int needed = a_.form.z != 0 ? 3 : 2;
    constexpr double kFar = std::numeric_limits<double>::infinity();
    double d[3] = {kFar, kFar, kFar};
    glm::ivec3 nearest = base;
    // The 27 cubes around p, then the next shell, whose cubes are skipped when even their nearest corner is
    // farther than the distances still wanted (a metric below 2 can reach them).
    for (int shell = 1; shell <= 2; ++shell) {
      for (int i = -shell; i <= shell; ++i) {
        for (int j = -shell; j <= shell; ++j) {
          for (int k = -shell; k <= shell; ++k) {
            if (std::max({std::abs(i), std::abs(j), std::abs(k)}) != shell && shell > 1) continue;
            const glm::ivec3 c = base + glm::ivec3(i, j, k);
            if (shell > 1 && rank(glm::max(glm::max(glm::dvec3(c) - p, p - glm::dvec3(c + 1)), 0.0)) >= d[needed - 1]) {
              continue;
            }
            const double r = rank(glm::abs(cellPoint(c.x, c.y, c.z) - p));
            if (r < d[0]) nearest = c;
            if (r < d[2]) {
              d[2] = r;
              if (d[2] < d[1]) std::swap(d[1], d[2]);
              if (d[1] < d[0]) std::swap(d[0], d[1]);
            }
          }
        }
      }
    }
    if (a_.solid) return noise(cellPoint(nearest.x, nearest.y, nearest.z), noise_.get());
    return std::clamp(a_.form.x * length(d[0]) + a_.form.y * length(d[1]) + a_.form.z * length(d[2]), 0.0, 1.0);
  }

 private:
  // What orders the offsets as the metric's lengths do, lifted by `offset` along a fourth axis: the length
  // before its root, so that only the three kept take one.
  double rank(const glm::dvec3& v) const {
    if (a_.metric == 2) return glm::dot(v, v) + a_.offset * a_.offset;
    if (a_.metric == 1) return v.x + v.y + v.z + std::abs(a_.offset);
    const double m = a_.metric;
    return std::pow(v.x, m) + std::pow(v.y, m) + std::pow(v.z, m) + std::pow(std::abs(a_.offset), m);
  }
  double length(double rank) const {
    return a_.metric == 2 ? std::sqrt(rank) : a_.metric == 1 ? rank : std::pow(rank, 1 / a_.metric);
  }

  CrackleArgs a_;
  NoiseChoice noise_;
};

}  // namespace

std::unique_ptr<Pattern> makeCrackle(const PatternArgs& a) { return std::make_unique<Crackle>(a.crackle, a.noise); }

}  // namespace rt
