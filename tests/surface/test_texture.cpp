// Textures: a layer's material from its finish and colour, layers over one another, and the bound the tracer's
// cut-off reads.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "raytrace/surface/texture.hpp"

namespace rt {
namespace {

std::shared_ptr<const Pigment> solid(Rgbft c) {
  auto p = std::make_shared<Pigment>();
  p->solid = c;
  return p;
}

FinishTerms matte() {
  FinishTerms f;
  f.ambient = Color(0.1f);
  f.diffuse = 0.6f;
  return f;
}

TEST_CASE("texture: a layer's ambient and diffuse scale its colour; the other terms are the finish's", "[texture]") {
  FinishTerms f = matte();
  f.specular = Color(0.5f);
  f.exponent = 40;
  const Material m = layerMaterial(f, {Color(1, 0.5f, 0), 0.25f, 0});
  CHECK(m.pigment == Color(1, 0.5f, 0));
  CHECK(m.filter == 0.25f);
  CHECK(m.ambient == Color(0.1f, 0.05f, 0));
  CHECK(m.diffuse == Color(0.6f, 0.3f, 0));
  CHECK(m.specular == Color(0.5f));
  CHECK(m.exponent == 40);
}

TEST_CASE("texture: an upper layer covers the lower where opaque, and lets it through by filter and transmit",
          "[texture]") {
  Texture t;
  t.layers = {{solid({Color(0, 0, 1), 0, 0}), matte()}, {solid({Color(1, 0, 0), 0.5f, 0.25f}), matte()}};
  const Material m = t.at(glm::dvec3(0));
  // cover 1 − 0.5 − 0.25 = 0.25 of red; below, blue seen through 0.5·red + 0.25 = (0.75, 0.25, 0.25).
  CHECK(m.diffuse.r == Approx(0.6f * 0.25f));
  CHECK(m.diffuse.b == Approx(0.6f * 0.25f));
  CHECK(m.diffuse.g == Approx(0));
  // The blue below lets no light through, so neither does the stack.
  CHECK(m.filter == 0);
  const Texture b = bounded(t);
  CHECK(b.bound.diffuse == Color(0.6f, 0, 0.6f));
  CHECK(b.bound.filter == 0.75f);  // filter and transmit together
}

TEST_CASE("texture: transmit lets light through untinted, filter tinted by the colour", "[texture]") {
  // rgbft <1, 0, 0, 0.25, 0.5>: 0.75 of the light goes through, 0.25·red + 0.5·white of it.
  const Material m = layerMaterial(matte(), {Color(1, 0, 0), 0.25f, 0.5f});
  CHECK(m.filter == 0.75f);
  CHECK(m.pigment.r == Approx(1.0f));
  CHECK(m.pigment.g == Approx(0.5f / 0.75f));
  CHECK(m.diffuse == Color(0.6f, 0, 0));  // the surface's own colour, which the tracer weights by 1 − 0.75
}

TEST_CASE("texture: the texture is read at the world point taken into its own space", "[texture]") {
  auto gradient = std::make_shared<Pigment>();
  gradient->pattern = patternKind("gradient")->make(PatternArgs{glm::dvec3(1, 0, 0), true});
  gradient->map = {{0, solid({Color(0), 0, 0})}, {1, solid({Color(1), 0, 0})}};
  Texture t;
  t.layers = {{gradient, matte()}};
  t.fromWorld = glm::inverse(glm::translate(glm::dmat4(1), glm::dvec3(0.25, 0, 0)));
  CHECK(t.at(glm::dvec3(0.75, 0, 0)).pigment.r == Approx(0.5f));
}

}  // namespace
}  // namespace rt
