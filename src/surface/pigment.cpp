#include "raytrace/surface/pigment.hpp"

#include <algorithm>
#include <cmath>

#include "raytrace/surface/image_map.hpp"

namespace rt {

Rgbft mix(const Rgbft& a, const Rgbft& b, float t) {
  return {a.rgb + (b.rgb - a.rgb) * t, a.filter + (b.filter - a.filter) * t, a.transmit + (b.transmit - a.transmit) * t};
}

namespace {

// The wave shapes of the POV-Ray 3.7 manual ("Waveform"), on a value already wrapped into [0, 1).
double shaped(double v, Wave wave, double exponent) {
  constexpr double kPi = 3.14159265358979323846;
  switch (wave) {
    case Wave::Ramp: return v;
    case Wave::Triangle: return v < 0.5 ? 2 * v : 2 - 2 * v;
    case Wave::Sine: return 0.5 + 0.5 * std::sin(2 * kPi * v);
    case Wave::Scallop: return std::abs(std::sin(kPi * v));
    case Wave::Cubic: return v * v * (3 - 2 * v);
    case Wave::Poly: return std::pow(v, exponent);
  }
  return v;
}

}  // namespace

// frequency and phase, then the value wrapped as POV-Ray wraps it: modulo 1.00001, which keeps 1 itself where
// the pattern reaches it (and shows as a slow drift far from the origin, which POV-Ray's pictures have too).
double waveValue(double raw, double frequency, double phase, Wave wave, double exponent) {
  double v = std::fmod(raw * frequency + phase, 1.00001);
  if (v < 0) v -= std::floor(v);
  return shaped(v, wave, exponent);
}

bool readsNormal(const Pigment& p) {
  if (p.pattern && p.pattern->readsNormal()) return true;
  for (const MapEntry& e : p.map) {
    if (readsNormal(*e.pigment)) return true;
  }
  return std::any_of(p.list.begin(), p.list.end(), [](const auto& q) { return readsNormal(*q); });
}

glm::dvec3 throughWarps(const std::vector<WarpStage>& warps, const glm::dmat4& afterWarps, const glm::dvec3& p) {
  glm::dvec3 q = p;
  for (const WarpStage& w : warps) {
    q = glm::dvec3(w.before * glm::dvec4(q, 1));
    q = w.warp->apply(q);
  }
  return glm::dvec3(afterWarps * glm::dvec4(q, 1));
}

glm::dvec3 Pigment::patternPoint(const glm::dvec3& p) const {
  if (warps.empty()) return glm::dvec3(fromTexture * glm::dvec4(p, 1));
  return throughWarps(warps, afterWarps, p);
}

double Pigment::value(const glm::dvec3& p) const {
  if (!pattern) return 0;
  const double raw = pattern->value(patternPoint(p));
  return pattern->blocks() > 0 ? raw : waveValue(raw, frequency, phase, wave, exponent);
}

Rgbft Pigment::at(const glm::dvec3& p) const {
  if (!pattern && !average) return image ? image->at(patternPoint(p)) : solid;
  const glm::dvec3 q = glm::dvec3(fromTexture * glm::dvec4(p, 1));
  if (average) {
    // Without a pattern to read it, the warps move the point the averaged pigments read (as POV-Ray's pictures show).
    const glm::dvec3 a = warps.empty() ? q : patternPoint(p);
    Rgbft sum;
    double weights = 0;
    for (const MapEntry& e : map) {
      const Rgbft c = e.pigment->at(a);
      const float w = float(e.value);
      sum = {sum.rgb + w * c.rgb, sum.filter + w * c.filter, sum.transmit + w * c.transmit};
      weights += e.value;
    }
    return weights > 0 ? mix(Rgbft{}, sum, float(1 / weights)) : solid;
  }
  const double raw = pattern->value(warps.empty() ? q : patternPoint(p));
  if (pattern->blocks() > 0) {
    const size_t i = std::min(size_t(raw), list.size() - 1);
    return list[i]->at(q);
  }
  const double v = waveValue(raw, frequency, phase, wave, exponent);
  if (map.empty()) return solid;
  if (v <= map.front().value) return map.front().pigment->at(q);
  if (v >= map.back().value) return map.back().pigment->at(q);
  const auto upper = std::upper_bound(map.begin(), map.end(), v, [](double x, const MapEntry& e) { return x < e.value; });
  const MapEntry& lo = *(upper - 1);
  const MapEntry& hi = *upper;
  const double span = hi.value - lo.value;
  const Rgbft a = lo.pigment->at(q);
  if (span <= 0) return a;
  return mix(a, hi.pigment->at(q), float((v - lo.value) / span));
}

}  // namespace rt
