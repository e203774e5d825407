// A POV-Ray area light's grid of points and its adaptive sampling (POV-Ray 3.7 manual, "Area Lights"): the
// shadow of an area light is the share of its grid that a point sees, found by splitting the grid into blocks
// from its four corners down.
#pragma once

#include <vector>

#include "raytrace/geometry/math.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

struct AreaLight {
  glm::dvec3 axis1{0}, axis2{0};
  int size1 = 1, size2 = 1;
  int adaptive = -1;
  bool jitter = false, circular = false, orient = false;
  bool illumination = false;  // area_illumination (Tracer::illuminate)

  explicit AreaLight(const AreaDesc& area);

  // The two axes as they light `point` from `center`: as written or, with `orient`, turned about the centre to
  // face the point, their lengths kept.
  void axesToward(const glm::dvec3& center, const glm::dvec3& point, glm::dvec3& a1, glm::dvec3& a2) const;

  // Grid point (i, j) over the axes a1, a2 about `center`: the grid spans each axis end to end, a size of 1
  // sits on the centre; `offset` ∈ [0, 1)² moves it within its cell when jittered. `circular` squeezes the
  // square onto the inscribed ellipse along each ray from the centre.
  glm::dvec3 point(int i, int j, const glm::dvec3& center, const glm::dvec3& a1, const glm::dvec3& a2,
                   glm::vec2 offset) const;

  // The mean of `seen(i, j)` (the light that grid point (i, j) sends to the point shaded) as POV-Ray weighs
  // it: the four corners of a block are averaged unless the block is split, which it is while fewer than
  // `adaptive` splits were made (every split without `adaptive`) or while its corners differ by more than
  // 0.1 in the sum of the channels, down to blocks one cell wide. A block from i1 to i2 splits at the middle
  // point when i2 − i1 is even, and between the two middle points when it is odd: fitted to POV-Ray's
  // pictures of shadows of linear lights of 3 to 6 points. `grid` and `known` are scratch space.
  template <class Seen>
  Color share(Seen&& seen, std::vector<Color>& grid, std::vector<char>& known) const {
    grid.resize(size_t(size1) * size_t(size2));
    known.assign(grid.size(), 0);
    const auto at = [&](int i, int j) -> const Color& {
      const size_t k = size_t(j) * size_t(size1) + size_t(i);
      if (!known[k]) grid[k] = seen(i, j), known[k] = 1;
      return grid[k];
    };
    const auto block = [&](auto&& self, int i1, int j1, int i2, int j2, int level) -> Color {
      const Color c[4] = {at(i1, j1), at(i2, j1), at(i1, j2), at(i2, j2)};
      if ((i2 - i1 > 1 || j2 - j1 > 1) && (adaptive < 0 || level < adaptive || differ(c))) {
        const int ilo = (i1 + i2) / 2, ihi = (i1 + i2 + 1) / 2, jlo = (j1 + j2) / 2, jhi = (j1 + j2 + 1) / 2;
        return (self(self, i1, j1, ilo, jlo, level + 1) + self(self, ihi, j1, i2, jlo, level + 1) +
                self(self, i1, jhi, ilo, j2, level + 1) + self(self, ihi, jhi, i2, j2, level + 1)) *
               0.25f;
      }
      return (c[0] + c[1] + c[2] + c[3]) * 0.25f;
    };
    return block(block, 0, 0, size1 - 1, size2 - 1, 0);
  }

 private:
  static bool differ(const Color (&c)[4]);
};

}  // namespace rt
