#include "raytrace/surface/normal.hpp"

#include <algorithm>

namespace rt {

// A slope map is a cubic between each two entries with the entries' heights and slopes, the slopes per unit of
// the interval, as POV-Ray draws them (measured: docs/povray-language.md, "Normals").
double Normal::height(const glm::dvec3& q) const {
  const double v = waveValue(pattern->value(q), frequency, phase, wave, exponent);
  if (slopes.empty()) return v;
  if (v <= slopes.front().value) return slopes.front().height;
  if (v >= slopes.back().value) return slopes.back().height;
  const auto upper = std::upper_bound(slopes.begin(), slopes.end(), v, [](double x, const SlopeEntry& e) { return x < e.value; });
  const SlopeEntry& a = *(upper - 1);
  const SlopeEntry& b = *upper;
  const double span = b.value - a.value;
  if (span <= 0) return a.height;
  const double t = (v - a.value) / span, t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * a.height + (t3 - 2 * t2 + t) * a.slope + (3 * t2 - 2 * t3) * b.height + (t3 - t2) * b.slope;
}

// The height is sampled at the four corners of a regular pyramid `accuracy` away from the point (POV-Ray 3.7
// manual, "Normals, Accuracy"); its gradient bends the normal by amount/10 per unit of slope, measured on
// POV-Ray's renders; a pattern with a formula of its own (quilted) gives that vector itself. By default the
// bend is the one in the pattern's space, so that scaling a normal scales its bumps' depth with them ("Scaling
// normals"); no_bump_scale bends by the slope in world space.
glm::dvec3 Normal::bent(const glm::dvec3& n, const glm::dvec3& p, const glm::dmat3& toTexture) const {
  static const glm::dvec3 kPyramid[4] = {{0.942809041582063, -1.0 / 3, 0},
                                         {-0.471404520791032, -1.0 / 3, 0.816496580927726},
                                         {-0.471404520791032, -1.0 / 3, -0.816496580927726},
                                         {0, 1, 0}};
  const glm::dmat3 m = glm::dmat3(fromTexture) * toTexture;
  const glm::dvec3 q = warps.empty() ? glm::dvec3(fromTexture * glm::dvec4(p, 1)) : throughWarps(warps, afterWarps, p);
  if (!map.empty()) return mapped(n, q, m);
  glm::dvec3 slope = pattern->hasBump() ? pattern->bump(q) : glm::dvec3(0);
  if (!pattern->hasBump()) {
    for (const glm::dvec3& corner : kPyramid) slope += height(q + accuracy * corner) * corner;
    slope /= 10 * accuracy;
  }
  double scale = amount;
  if (bumpScale) scale *= glm::length(glm::transpose(glm::inverse(m)) * n);
  return glm::normalize(n - scale * (glm::transpose(m) * slope));
}

// The entries' bent normals are blended, not their slopes: a map's two entries about the pattern's value in
// proportion, an average's all by weight, the sum made unit length; a block pattern takes its block's normal
// (POV-Ray 3.7 manual, "Normal Maps and Normal Lists", "Average"; the blend as measured on its renders).
glm::dvec3 Normal::mapped(const glm::dvec3& n, const glm::dvec3& q, const glm::dmat3& m) const {
  const auto bend = [&](const NormalEntry& e) { return e.normal ? e.normal->bent(n, q, m) : n; };
  if (average) {
    glm::dvec3 sum(0);
    for (const NormalEntry& e : map) sum += e.value * bend(e);
    return glm::length(sum) > 0 ? glm::normalize(sum) : n;
  }
  if (pattern->blocks() > 0) {
    const int block = int(pattern->value(q));
    return block >= 0 && size_t(block) < map.size() ? bend(map[size_t(block)]) : n;
  }
  const double v = waveValue(pattern->value(q), frequency, phase, wave, exponent);
  if (v <= map.front().value) return bend(map.front());
  if (v >= map.back().value) return bend(map.back());
  const auto upper = std::upper_bound(map.begin(), map.end(), v, [](double x, const NormalEntry& e) { return x < e.value; });
  const NormalEntry& a = *(upper - 1);
  const NormalEntry& b = *upper;
  const double t = b.value > a.value ? (v - a.value) / (b.value - a.value) : 0;
  const glm::dvec3 blend = (1 - t) * bend(a) + t * bend(b);
  return glm::length(blend) > 0 ? glm::normalize(blend) : n;
}

}  // namespace rt
