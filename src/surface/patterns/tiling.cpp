// tiling N: one of POV-Ray's 27 tilings of the x-z plane, the same along y (POV-Ray 3.7 manual, "Tiling
// Pattern"). A tiling of T tile types gives tile type t the values t/T at the tile's centre to (t + 1)/T on its
// edges. The bevel between is the polygon's gauge about its centre, max over the edges of (distance toward the
// edge) / (the edge's distance from the centre): linear, and the same on every side of a regular polygon or a
// rhombus; POV-Ray's values fit it to 10⁻⁶ (tests/surface/patterns/test_tiling.cpp). Each tiling here is a
// rectangle of the plane repeated, with the polygons that cover it, placed where POV-Ray's values put them.
#include <cmath>
#include <vector>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

constexpr double kH = 0.86602540378443864676;  // √3/2: the height of a triangle of side 1

struct TileShape {
  int type;
  std::vector<glm::dvec2> corners;  // (x, z), in order round the tile
};

struct TilingShape {
  int types;
  glm::dvec2 period;  // the repeated rectangle's sides along x and z
  std::vector<TileShape> tiles;
};

std::vector<glm::dvec2> hexagonAt(double x, double z) {
  std::vector<glm::dvec2> c;
  for (int i = 0; i < 6; ++i) c.push_back({x + std::cos(i * M_PI / 3), z + std::sin(i * M_PI / 3)});
  return c;
}

// The tilings drawn, by number; an empty shape for those not drawn yet.
TilingShape tilingShape(int n) {
  switch (n) {
    case 1:  // squares of side 1, their corners on the integers
      return {1, {1, 1}, {{0, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}}}};
    case 2:  // hexagons of side 1, corners along ±x, one centred at (−1, 0)
      return {1, {3, 2 * kH}, {{0, hexagonAt(-1, 0)}, {0, hexagonAt(0.5, kH)}, {0, hexagonAt(2, 0)},
                               {0, hexagonAt(0.5, -kH)}}};
    case 3:  // triangles of side 1 in rows along x: pointing to +z type 0, to −z type 1
      return {2, {1, 2 * kH}, {{0, {{0, 0}, {1, 0}, {0.5, kH}}}, {1, {{0.5, kH}, {1, 0}, {1.5, kH}}},
                               {0, {{0.5, kH}, {1.5, kH}, {1, 2 * kH}}}, {1, {{0, 2 * kH}, {0.5, kH}, {1, 2 * kH}}}}};
    case 5:  // rhombi of side 1 in three directions: type 1's long diagonal along z
      return {3, {3, 2 * kH}, {{0, {{0, 0}, {1, 0}, {1.5, kH}, {0.5, kH}}}, {1, {{1, 0}, {1.5, -kH}, {2, 0}, {1.5, kH}}},
                               {2, {{2, 0}, {3, 0}, {2.5, kH}, {1.5, kH}}}, {0, {{1.5, kH}, {2.5, kH}, {3, 2 * kH}, {2, 2 * kH}}},
                               {1, {{0, 0}, {0.5, kH}, {0, 2 * kH}, {-0.5, kH}}},
                               {2, {{0.5, kH}, {1.5, kH}, {1, 2 * kH}, {0, 2 * kH}}}}};
    default:
      return {};
  }
}

class Tiling final : public Pattern {
 public:
  explicit Tiling(const TilingShape& shape) : types_(shape.types), period_(shape.period) {
    for (const TileShape& s : shape.tiles) {
      Tile t{s.type, glm::dvec2(0), {}};
      for (const glm::dvec2& c : s.corners) t.centre += c / double(s.corners.size());
      for (size_t i = 0; i < s.corners.size(); ++i) {
        const glm::dvec2 a = s.corners[i], b = s.corners[(i + 1) % s.corners.size()];
        glm::dvec2 normal = glm::normalize(glm::dvec2(b.y - a.y, a.x - b.x));
        double reach = glm::dot(normal, a - t.centre);
        if (reach < 0) normal = -normal, reach = -reach;
        t.edges.push_back(normal / reach);
      }
      tiles_.push_back(t);
    }
  }

  // The tile whose gauge is least at the point is the one that holds it (gauge ≤ 1); the repeated rectangle's
  // eight neighbours are tried too, for the tiles that reach across its sides.
  double value(const glm::dvec3& p) const override {
    const glm::dvec2 q(p.x - std::floor(p.x / period_.x) * period_.x, p.z - std::floor(p.z / period_.y) * period_.y);
    double best = HUGE_VAL;
    int type = 0;
    for (int sx = -1; sx <= 1; ++sx) {
      for (int sz = -1; sz <= 1; ++sz) {
        const glm::dvec2 shifted = q - glm::dvec2(sx * period_.x, sz * period_.y);
        for (const Tile& t : tiles_) {
          const glm::dvec2 d = shifted - t.centre;
          double gauge = -HUGE_VAL;
          for (const glm::dvec2& e : t.edges) gauge = std::max(gauge, glm::dot(e, d));
          if (gauge < best) best = gauge, type = t.type;
        }
      }
    }
    return (type + std::min(best, 1.0)) / types_;
  }

 private:
  struct Tile {
    int type;
    glm::dvec2 centre;
    std::vector<glm::dvec2> edges;  // each edge's outward normal over its distance from the centre
  };
  int types_;
  glm::dvec2 period_;
  std::vector<Tile> tiles_;
};

}  // namespace

bool tilingDrawn(int n) { return !tilingShape(n).tiles.empty(); }

std::unique_ptr<Pattern> makeTiling(const PatternArgs& a) { return std::make_unique<Tiling>(tilingShape(int(a.vector.x))); }

}  // namespace rt
