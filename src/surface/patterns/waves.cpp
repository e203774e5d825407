// ripples and waves as pigments, and ripples, waves and wrinkles as normals: as normals, like bumps, POV-Ray
// bends by formulas of their own rather than by the slope of the pigments' values (POV-Ray 3.7 manual, "Ripples",
// "Waves", "Wrinkles": "a special normal perturbation function"). Fitted to POV-Ray's renders to their 16-bit
// precision (n·l under three lights, docs/povray-language.md "Normals"): each bends n to n + amount·v(p), with
//   ripples  v = Σ sin 2π(f·d + phase) · u / N
//   waves    v = Σ sin 2π(f·fᵢ·d + phase) · u / (fᵢ·N)
//   wrinkles v = Σₖ |vectorNoise(2ᵏ·p)| / 2ᵏ, k = 0…9, the absolute value taken per component
// where u is the unit vector from the i-th of N = 10 wave sources to p, d the distance between them, and f and
// phase the normal's frequency and phase. The sources are vectorNoise at (i, 0, 0) made unit length; the waves'
// own frequencies fᵢ are kWaveFrequency/32767 + 0.01, both read from POV-Ray's `ripples` and `waves` pigments,
// whose values are 0.5 + Σ sin 2π(dᵢ) / 2N and 0.5 + Σ 0.2·sin 2π(fᵢ·dᵢ) / (fᵢ·N) (measured the same way).
#include <array>
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kWaveSources = 10;
constexpr int kWaveFrequency[kWaveSources] = {29789, 31130, 13866, 22914, 22255, 32159, 25328, 12801, 7198, 5194};

struct WaveSource {
  glm::dvec3 at;
  double frequency;
};

const std::array<WaveSource, kWaveSources>& waveSources() {
  static const std::array<WaveSource, kWaveSources> sources = [] {
    std::array<WaveSource, kWaveSources> s{};
    for (int i = 0; i < kWaveSources; ++i) {
      s[size_t(i)] = {glm::normalize(vectorNoise({double(i), 0, 0})), kWaveFrequency[i] / 32767.0 + 0.01};
    }
    return s;
  }();
  return sources;
}

class WaveNormal final : public Pattern {
 public:
  WaveNormal(double frequency, double phase, bool own, bool bump)
      : frequency_(frequency), phase_(phase), own_(own), bump_(bump) {}
  double value(const glm::dvec3& p) const override {
    double sum = 0;
    for (const WaveSource& s : waveSources()) {
      const double f = own_ ? s.frequency : 1;
      sum += std::sin(2 * kPi * f * glm::length(p - s.at)) * (own_ ? 0.2 / f : 0.5);
    }
    return 0.5 + sum / kWaveSources;
  }
  bool hasBump() const override { return bump_; }
  glm::dvec3 bump(const glm::dvec3& p) const override {
    glm::dvec3 v(0);
    for (const WaveSource& s : waveSources()) {
      const glm::dvec3 u = p - s.at;
      double d = glm::length(u);
      if (d == 0) d = 1;
      const double f = own_ ? s.frequency : 1;
      v += std::sin(2 * kPi * (d * frequency_ * f + phase_)) / (d * f) * u;
    }
    return -v / double(kWaveSources);
  }

 private:
  double frequency_, phase_;
  bool own_;  // waves: each source's own frequency, and its waves' heights inversely as it
  bool bump_;  // as a normal; as a pigment only its value serves
};

class WrinklesNormal final : public Pattern {
 public:
  double value(const glm::dvec3&) const override { return 0; }
  bool hasBump() const override { return true; }
  glm::dvec3 bump(const glm::dvec3& p) const override {
    glm::dvec3 v(0);
    double scale = 1;
    for (int k = 0; k < 10; ++k, scale *= 2) v += glm::abs(vectorNoise(p * scale)) / scale;
    return -v;
  }
};

}  // namespace

std::unique_ptr<Pattern> makeRipples(const PatternArgs&) { return std::make_unique<WaveNormal>(1, 0, false, false); }
std::unique_ptr<Pattern> makeWaves(const PatternArgs&) { return std::make_unique<WaveNormal>(1, 0, true, false); }
std::unique_ptr<Pattern> makeRipplesNormal(const PatternArgs& a) {
  return std::make_unique<WaveNormal>(a.frequency, a.phase, false, true);
}
std::unique_ptr<Pattern> makeWavesNormal(const PatternArgs& a) {
  return std::make_unique<WaveNormal>(a.frequency, a.phase, true, true);
}
std::unique_ptr<Pattern> makeWrinklesNormal(const PatternArgs&) { return std::make_unique<WrinklesNormal>(); }

}  // namespace rt
