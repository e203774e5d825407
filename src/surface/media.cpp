#include "raytrace/surface/media.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

// Per unit of length at one point: the light given off toward the viewer, and the extinction.
struct Sample {
  glm::dvec3 light{0};
  glm::dvec3 extinction{0};
};

Sample mean(const Sample& a, const Sample& b) { return {(a.light + b.light) / 2.0, (a.extinction + b.extinction) / 2.0}; }

double difference(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 d = glm::abs(a - b);
  return d.x + d.y + d.z;
}

}  // namespace

double Scattering::phase(const glm::dvec3& dir, const glm::dvec3& toLight) const {
  const double c = glm::dot(dir, toLight);  // 1: the light shines straight at the viewer
  switch (type) {
    case 2:
      return 0.57666 * (1 + 9 * std::pow((1 + c) / 2, 8));
    case 3:
      return 0.495712 * (1 + 50 * std::pow((1 + c) / 2, 32));
    case 4:
      return 0.79937 * (1 + c * c);
    case 5: {
      const double g = eccentricity;
      return (1 - g * g) / std::pow(1 + g * g - 2 * g * c, 1.5);
    }
    default:
      return 1;
  }
}

Color Media::through(const Color& behind, const glm::dvec3& start, const glm::dvec3& dir, double distance,
                     MediaLights* lights) const {
  const Media* self = this;
  return through(&self, 1, behind, start, dir, distance, lights);
}

Color Media::through(const Media* const* media, size_t count, const Color& behind, const glm::dvec3& start,
                     const glm::dvec3& dir, double distance, MediaLights* lights) {
  // The first medium with the most intervals sets the sampling, as measured with POV-Ray 3.7.
  const Media* lead = media[0];
  bool lit = false;
  for (size_t i = 0; i < count; ++i) {
    const Media& m = *media[i];
    if (m.intervals > lead->intervals) lead = &m;
    lit = lit || (m.scattering && m.scattering->color != Color(0));
  }
  const int samples = lead->samples, intervals = lead->intervals, aaLevel = lead->aaLevel;
  const double aaThreshold = lead->aaThreshold;
  lit = lit && lights;
  std::vector<MediaLights::Arrival> arrivals;
  const auto sample = [&](double t) {
    const glm::dvec3 at = start + dir * t;
    if (lit) {
      arrivals.clear();
      lights->at(at, arrivals);
    }
    Sample out;
    for (size_t i = 0; i < count; ++i) {
      const Media& m = *media[i];
      const glm::dvec3 s = m.scattering ? glm::dvec3(m.scattering->color) : glm::dvec3(0);
      glm::dvec3 density(1);
      if (!m.densities.empty()) {
        const glm::dvec3 p = glm::dvec3(m.fromWorld * glm::dvec4(at, 1));
        for (const auto& d : m.densities) density *= glm::dvec3(d->at(p).rgb);
      }
      glm::dvec3 light(m.emission);
      if (lit && m.scattering) {
        for (const auto& arrival : arrivals) light += s * glm::dvec3(arrival.color) * m.scattering->phase(dir, arrival.toLight);
      }
      out.light += light * density;
      out.extinction += (glm::dvec3(m.absorption) + (m.scattering ? m.scattering->extinction : 0.0) * s) * density;
    }
    return out;
  };
  const int n = std::max(2, samples / 2 + 1);
  const double part = distance / intervals;
  const double h = part / n;
  // The mean over [t0, t1] given its ends, read at its middle and, if the light there varies, by halves.
  const auto step = [&](const auto& self, double t0, double t1, const Sample& s0, const Sample& s1, int depth) -> Sample {
    const Sample m = sample((t0 + t1) / 2);
    const double varies = std::max(difference(s0.light, m.light), difference(m.light, s1.light)) * part;
    if (depth + 1 < aaLevel && varies > aaThreshold) {
      return mean(self(self, t0, (t0 + t1) / 2, s0, m, depth + 1), self(self, (t0 + t1) / 2, t1, m, s1, depth + 1));
    }
    return {(s0.light + m.light + s1.light) / 3.0, (s0.extinction + m.extinction + s1.extinction) / 3.0};
  };
  glm::dvec3 seen(0), kept(1);
  for (int i = 0; i < intervals; ++i) {
    const double from = i * part;
    Sample previous = sample(from);
    for (int k = 0; k < n; ++k) {
      const double t0 = from + part * k / (n + 1), t1 = from + part * (k + 1) / (n + 1);
      const Sample next = sample(t1);
      const Sample mid = step(step, t0, t1, previous, next, 0);
      seen += mid.light * h * kept;
      kept *= glm::exp(-mid.extinction * h);
      previous = next;
    }
  }
  return Color(glm::dvec3(behind) * kept + seen);
}

Color Media::kept(const std::vector<Media>& media, const glm::dvec3& start, const glm::dvec3& dir, double distance) {
  std::vector<Media> dark = media;
  std::vector<const Media*> all;
  for (Media& m : dark) {
    m.emission = Color(0);
    all.push_back(&m);
  }
  return through(all.data(), all.size(), Color(1), start, dir, distance);
}

}  // namespace rt
