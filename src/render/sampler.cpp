#include "raytrace/render/sampler.hpp"

namespace rt {

Strata strataFor(int n) {
  Strata s;
  for (int rows = 1; rows * rows <= n; ++rows) {
    if (n % rows == 0) s.rows = rows;
  }
  s.cols = n / s.rows;
  return s;
}

}  // namespace rt
