// tiling N: one of POV-Ray's 27 tilings of the x-z plane, the same along y (POV-Ray 3.7 manual, "Tiling
// Pattern"). A tiling of T tile types gives tile type t the values t/T at its middle to (t + 1)/T on its edges:
// "each individual tile ... has the same beveling", so the value rises from the edges inward by the distance to
// the nearest edge over one bevel width, the inradius of the tiling's smallest tile, and stays at t/T beyond it
// (octagons among squares keep a flat middle). POV-Ray's values fit this to 10⁻⁶
// (tests/surface/patterns/test_tiling.cpp). Each tiling here is a rectangle of the plane repeated, with the
// polygons that cover it, placed where POV-Ray's values put them.
#include <algorithm>
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
    case 4:  // rhombi of side 1, all one way: their sides along x and at 60° to it
      return {1, {1, 2 * kH},
              {{0, {{0, 0}, {1, 0}, {1.5, kH}, {0.5, kH}}}, {0, {{0.5, kH}, {1.5, kH}, {2, 2 * kH}, {1, 2 * kH}}}}};
    case 5:  // rhombi of side 1 in three directions: type 1's long diagonal along z
      return {3,
              {3, 2 * kH},
              {{0, {{0, 0}, {1, 0}, {1.5, kH}, {0.5, kH}}},
               {1, {{1, 0}, {1.5, -kH}, {2, 0}, {1.5, kH}}},
               {2, {{2, 0}, {3, 0}, {2.5, kH}, {1.5, kH}}},
               {0, {{1.5, kH}, {2.5, kH}, {3, 2 * kH}, {2, 2 * kH}}},
               {1, {{0, 0}, {0.5, kH}, {0, 2 * kH}, {-0.5, kH}}},
               {2, {{0.5, kH}, {1.5, kH}, {1, 2 * kH}, {0, 2 * kH}}}}};
    case 6: {  // 2 × 1 bricks: along x type 0, along z type 1, each row's shifted one on from the last
      TilingShape t{2, {4, 4}, {}};
      for (double j = 0; j < 4; ++j) {
        t.tiles.push_back({0, {{j + 1, j}, {j + 3, j}, {j + 3, j + 1}, {j + 1, j + 1}}});
        t.tiles.push_back({1, {{j, j}, {j + 1, j}, {j + 1, j + 2}, {j, j + 2}}});
      }
      return t;
    }
    case 7: {  // octagons of side 1 (type 1) centred on the multiples of 1 + √2, squares (type 0) between
      const double period = 1 + std::sqrt(2.0), mid = period / 2, half = std::sqrt(0.5);
      const double reach = 0.5 / std::sin(M_PI / 8);  // an octagon's corners from its centre
      std::vector<glm::dvec2> octagon;
      for (int i = 0; i < 8; ++i) {
        const double angle = (2 * i + 1) * M_PI / 8;
        octagon.push_back(reach * glm::dvec2(std::cos(angle), std::sin(angle)));
      }
      return {2, {period, period},
              {{1, octagon}, {0, {{mid + half, mid}, {mid, mid + half}, {mid - half, mid}, {mid, mid - half}}}}};
    }
    case 8:  // rows of unit squares (type 2) between rows of triangles, pointing to +z type 0, to −z type 1
      return {3,
              {1, 2 + 2 * kH},
              {{2, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
               {0, {{0, 1}, {1, 1}, {0.5, 1 + kH}}},
               {1, {{0.5, 1 + kH}, {1, 1}, {1.5, 1 + kH}}},
               {2, {{0.5, 1 + kH}, {1.5, 1 + kH}, {1.5, 2 + kH}, {0.5, 2 + kH}}},
               {0, {{0.5, 2 + kH}, {1.5, 2 + kH}, {1, 2 + 2 * kH}}},
               {1, {{0, 2 + 2 * kH}, {0.5, 2 + kH}, {1, 2 + 2 * kH}}}}};
    case 9:  // hexagons (type 2) with triangles between, pointing to +z type 0, to −z type 1
      return {3,
              {2, 4 * kH},
              {{0, {{1, 0}, {2, 0}, {1.5, kH}}},
               {1, {{1, 2 * kH}, {1.5, kH}, {2, 2 * kH}}},
               {0, {{0, 2 * kH}, {1, 2 * kH}, {0.5, 3 * kH}}},
               {1, {{0, 4 * kH}, {0.5, 3 * kH}, {1, 4 * kH}}},
               {2, hexagonAt(0.5, kH)},
               {2, hexagonAt(1.5, 3 * kH)}}};
    case 10:  // unit squares in rows along x, every other row shifted by a half
      return {1, {1, 2}, {{0, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, {0, {{-0.5, 1}, {0.5, 1}, {0.5, 2}, {-0.5, 2}}}}};
    default:
      return {};
  }
}

class Tiling final : public Pattern {
 public:
  explicit Tiling(const TilingShape& shape) : types_(shape.types), period_(shape.period) {
    for (const TileShape& s : shape.tiles) {
      glm::dvec2 centre(0);
      for (const glm::dvec2& c : s.corners) centre += c / double(s.corners.size());
      Tile t{s.type, {}};
      double inradius = HUGE_VAL;
      for (size_t i = 0; i < s.corners.size(); ++i) {
        const glm::dvec2 a = s.corners[i], b = s.corners[(i + 1) % s.corners.size()];
        glm::dvec2 normal = glm::normalize(glm::dvec2(b.y - a.y, a.x - b.x));
        if (glm::dot(normal, a - centre) < 0) normal = -normal;
        t.edges.push_back({normal, glm::dot(normal, a)});
        inradius = std::min(inradius, glm::dot(normal, a - centre));
      }
      bevel_ = std::min(bevel_, inradius);
      tiles_.push_back(t);
    }
  }

  // The tile that holds the point is the one whose nearest edge is farthest inside (its distance ≥ 0); the
  // repeated rectangle's eight neighbours are tried too, for the tiles that reach across its sides.
  double value(const glm::dvec3& p) const override {
    const glm::dvec2 q(p.x - std::floor(p.x / period_.x) * period_.x, p.z - std::floor(p.z / period_.y) * period_.y);
    double best = -HUGE_VAL;
    int type = 0;
    for (int sx = -1; sx <= 1; ++sx) {
      for (int sz = -1; sz <= 1; ++sz) {
        const glm::dvec2 shifted = q + glm::dvec2(sx * period_.x, sz * period_.y);
        for (const Tile& t : tiles_) {
          double inside = HUGE_VAL;
          for (const Edge& e : t.edges) inside = std::min(inside, e.offset - glm::dot(e.normal, shifted));
          if (inside > best) best = inside, type = t.type;
        }
      }
    }
    return (type + std::clamp(1 - best / bevel_, 0.0, 1.0)) / types_;
  }

 private:
  struct Edge {
    glm::dvec2 normal;  // outward
    double offset;      // the edge's line: dot(normal, q) = offset
  };
  struct Tile {
    int type;
    std::vector<Edge> edges;
  };
  int types_;
  glm::dvec2 period_;
  double bevel_ = HUGE_VAL;
  std::vector<Tile> tiles_;
};

}  // namespace

bool tilingDrawn(int n) { return !tilingShape(n).tiles.empty(); }

std::unique_ptr<Pattern> makeTiling(const PatternArgs& a) {
  return std::make_unique<Tiling>(tilingShape(int(a.vector.x)));
}

}  // namespace rt
