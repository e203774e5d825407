#include "raytrace/surface/media.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

Color Media::through(const Color& behind, float distance) const {
  const int n = std::max(2, samples / 2 + 1);
  const double h = double(distance) / n;
  Color out;
  for (int c = 0; c < 3; ++c) {
    double seen = 0, kept = 1;
    const double step = std::exp(-double(absorption[c]) * h);
    for (int k = 0; k < n; ++k) {
      seen += kept;
      kept *= step;
    }
    out[c] = float(double(behind[c]) * kept + double(emission[c]) * h * seen);
  }
  return out;
}

}  // namespace rt
