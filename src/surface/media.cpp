#include "raytrace/surface/media.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

Color Media::through(const Color& behind, const glm::dvec3& start, const glm::dvec3& dir, double distance) const {
  const int n = std::max(2, samples / 2 + 1);
  const double part = distance / intervals;
  const double h = part / n;
  glm::dvec3 seen(0), kept(1);
  const glm::dvec3 a(absorption), e(emission);
  for (int i = 0; i < intervals; ++i) {
    for (int k = 0; k < n; ++k) {
      glm::dvec3 density(1);
      if (!densities.empty()) {
        const glm::dvec3 at = start + dir * (i * part + part * (k + 0.5) / (n + 1));
        const glm::dvec3 p = glm::dvec3(fromWorld * glm::dvec4(at, 1));
        for (const auto& d : densities) density *= glm::dvec3(d->at(p).rgb);
      }
      seen += e * density * h * kept;
      kept *= glm::exp(-a * density * h);
    }
  }
  return Color(glm::dvec3(behind) * kept + seen);
}

}  // namespace rt
