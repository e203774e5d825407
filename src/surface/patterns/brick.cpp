// brick: bricks of brick_size (mortar included) laid in courses along y, each course shifted by half a brick in
// x and in z from the next, with `mortar` of mortar at the top end of each brick along each axis (POV-Ray 3.7
// manual, "Brick Pattern"; where the mortar lies measured on POV-Ray's values, docs/povray-noise.md).
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Brick final : public Pattern {
 public:
  Brick(const glm::dvec3& size, double mortar) : size_(size), mortar_(mortar) {}
  // 0 in the mortar, 1 in a brick.
  double value(const glm::dvec3& p) const override {
    const bool odd = std::fmod(std::floor(p.y / size_.y), 2.0) != 0;
    const bool mortar = inMortar(p.y, size_.y) || inMortar(p.x + (odd ? size_.x / 2 : 0), size_.x) ||
                        inMortar(p.z + (odd ? 0 : size_.z / 2), size_.z);
    return mortar ? 0 : 1;
  }
  int blocks() const override { return 2; }
  Color defaultBlock(int i) const override { return i == 0 ? Color(0.5f) : Color(0.6f, 0.15f, 0.15f); }

 private:
  bool inMortar(double u, double size) const { return u - size * std::floor(u / size) >= size - mortar_; }

  glm::dvec3 size_;
  double mortar_;
};

}  // namespace

std::unique_ptr<Pattern> makeBrick(const PatternArgs& a) { return std::make_unique<Brick>(a.brickSize, a.mortar); }

}  // namespace rt
