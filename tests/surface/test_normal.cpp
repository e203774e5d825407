// Normals: a pattern's slope bends the shading normal; slope maps, bump sizes, and the bump scale under
// transforms, against the analytic answers; a texture's top normal.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "raytrace/surface/patterns.hpp"
#include "raytrace/surface/texture.hpp"

namespace rt {
namespace {

Normal gradient(const glm::dvec3& v, double amount) {
  Normal n;
  n.pattern = makeGradient({v, true});
  n.amount = amount;
  return n;
}

void checkNear(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-12) {
  CHECK(glm::length(a - b) == Approx(0).margin(tolerance));
}

const glm::dvec3 kUp(0, 1, 0);
const glm::dvec3 kMiddle(0.5, 0, 0.5);  // away from the gradient's wrap at whole x

TEST_CASE("normal: a gradient bends the normal against its slope by amount·2/15 per unit of slope", "[normal]") {
  // The pyramid's estimate of a linear function's gradient is exact: the tilt is amount·2/15, measured on
  // POV-Ray's renders (docs/povray-language.md, "Normals").
  for (const double amount : {0.25, 0.5, 1.0, 7.5}) {
    checkNear(gradient({1, 0, 0}, amount).bent(kUp, kMiddle, glm::dmat3(1)),
              glm::normalize(glm::dvec3(-amount * 2 / 15, 1, 0)));
  }
  // Negative amounts invert the bumps.
  checkNear(gradient({1, 0, 0}, -0.5).bent(kUp, kMiddle, glm::dmat3(1)), glm::normalize(glm::dvec3(1.0 / 15, 1, 0)));
}

TEST_CASE("normal: amount 0, and a slope along the normal itself, leave the normal as it is", "[normal]") {
  CHECK(gradient({1, 0, 0}, 0).bent(kUp, kMiddle, glm::dmat3(1)) == kUp);
  checkNear(gradient({0, 1, 0}, 3).bent(kUp, {0.5, 0.5, 0.5}, glm::dmat3(1)), kUp);
}

TEST_CASE("normal: accuracy does not change a linear slope", "[normal]") {
  Normal n = gradient({1, 0, 0}, 1);
  n.accuracy = 0.1;
  checkNear(n.bent(kUp, kMiddle, glm::dmat3(1)), glm::normalize(glm::dvec3(-2.0 / 15, 1, 0)));
}

TEST_CASE("normal: scaling a normal scales its bumps' depth with them, unless no_bump_scale", "[normal]") {
  const glm::dvec3 expected = glm::normalize(glm::dvec3(-2.0 / 15, 1, 0));
  Normal n = gradient({1, 0, 0}, 1);
  // scale 0.5: the slope doubles and the depth halves.
  n.fromTexture = glm::scale(glm::dmat4(1), glm::dvec3(2));
  checkNear(n.bent(kUp, {0.25, 0, 0.25}, glm::dmat3(1)), expected);
  // The same scale on the object: the texture space's own map.
  n.fromTexture = glm::dmat4(1);
  checkNear(n.bent(kUp, {0.25, 0, 0.25}, glm::dmat3(2)), expected);
  // no_bump_scale: the doubled slope.
  n.bumpScale = false;
  checkNear(n.bent(kUp, {0.25, 0, 0.25}, glm::dmat3(2)), glm::normalize(glm::dvec3(-4.0 / 15, 1, 0)));
  // scale <1, 0.5, 1>: the same slope along x, half the depth along y.
  n.bumpScale = true;
  n.fromTexture = glm::scale(glm::dmat4(1), glm::dvec3(1, 2, 1));
  checkNear(n.bent(kUp, kMiddle, glm::dmat3(1)), glm::normalize(glm::dvec3(-1.0 / 15, 1, 0)));
}

TEST_CASE("normal: a slope map's height is a cubic through its entries' heights and slopes", "[normal]") {
  Normal n = gradient({1, 0, 0}, 1);
  n.slopes = {{0, 0, 1}, {0.5, 0.5, 1}, {1, 1, 1}};
  // In [0.5, 1], t = 0.5: the cubic with heights 0.5, 1 and slopes 1, 1 (per unit of t).
  CHECK(n.height({0.75, 0, 0}) == Approx(0.5 * 0.5 + 0.125 + 0.5 * 1 - 0.125));
  CHECK(n.height({0.5, 0, 0}) == 0.5);
  CHECK(n.height({0, 0, 0}) == 0);
  // A wave shapes the value before the map reads it.
  n.slopes.clear();
  n.wave = Wave::Triangle;
  CHECK(n.height({0.75, 0, 0}) == 0.5);
}

TEST_CASE("normal: a texture bends by its top normal, in its own texture space; without one, not at all",
          "[normal]") {
  FinishTerms f;
  Texture t;
  auto white = std::make_shared<Pigment>();
  t.layers.push_back({white, f, nullptr, std::make_shared<Normal>(gradient({1, 0, 0}, 0.5))});
  t.layers.push_back({white, f, nullptr, std::make_shared<Normal>(gradient({0, 0, 1}, 0.5))});
  t = bounded(t);
  CHECK(t.bumpy);
  checkNear(t.bent(kMiddle, kUp), glm::normalize(glm::dvec3(0, 1, -1.0 / 15)));
  t.fromWorld = glm::translate(glm::dmat4(1), glm::dvec3(0, 0, 0.25));
  checkNear(t.bent({0.5, 0, 0.5}, kUp), glm::normalize(glm::dvec3(0, 1, -1.0 / 15)));
  Texture plain;
  plain.layers.push_back({white, f, nullptr, nullptr});
  CHECK_FALSE(bounded(plain).bumpy);
}

TEST_CASE("normal: quilted's value and bend, against POV-Ray's renders", "[normal]") {
  // Pigment values read once from POV-Ray's 16-bit renders of `quilted color_map { [0 rgb 0] [1 rgb 1] }`.
  PatternArgs args;
  CHECK(makeQuilted(args)->value({0.025, 0.5, 0.5}) == Approx(0.1564).margin(1e-4));
  args.control0 = 0;
  args.control1 = 0;
  CHECK(makeQuilted(args)->value({0.025, 0.1, 0.1}) == Approx(0.1978).margin(1e-4));
  CHECK(makeQuilted(args)->value({1.025, -0.9, 2.1}) == Approx(0.1978).margin(1e-4));  // every unit cube alike
  args.control0 = 1;
  CHECK(makeQuilted(args)->value({0.025, 0.5, 0.5}) == Approx(0.0914).margin(1e-4));
  // `normal { quilted 1 }` on the plane y = 0 at (0.95, 0, 0.45): n·l under lights straight up, along +x and
  // along +z, from POV-Ray's renders.
  Normal n;
  n.pattern = makeQuilted({});
  n.amount = 1;
  const glm::dvec3 b = n.bent(kUp, {0.95, 0, 0.45}, glm::dmat3(1));
  CHECK(b.y == Approx(0.6592).margin(1e-4));
  CHECK(glm::dot(b, glm::normalize(glm::dvec3(1, 1, 0))) == Approx(0.9946).margin(1e-4));
  CHECK(glm::dot(b, glm::normalize(glm::dvec3(0, 1, 1))) == Approx(0.4074).margin(1e-4));
}

// n·l of a bent normal under lights straight up, along +x and along +z (as POV-Ray's renders read).
void checkLit(const glm::dvec3& b, double up, double x, double z) {
  CHECK(b.y == Approx(up).margin(1e-4));
  CHECK(glm::dot(b, glm::normalize(glm::dvec3(1, 1, 0))) == Approx(x).margin(1e-4));
  CHECK(glm::dot(b, glm::normalize(glm::dvec3(0, 1, 1))) == Approx(z).margin(1e-4));
}

TEST_CASE("normal: ripples, waves and wrinkles bend by their own formulas, against POV-Ray's renders", "[normal]") {
  // `normal { ripples 0.5 }` (and the others) on the plane y = 0, read once from POV-Ray's 16-bit renders.
  const auto bent = [](std::unique_ptr<Pattern> pattern, double amount, const glm::dvec3& p) {
    Normal n;
    n.pattern = std::move(pattern);
    n.amount = amount;
    return n.bent(kUp, p, glm::dmat3(1));
  };
  const glm::dvec3 a(-1.3125, 0, 1.0625), b(0.5625, 0, -1.3125);
  PatternArgs args;
  checkLit(bent(makeRipplesNormal(args), 0.5, a), 0.9949, 0.6417, 0.7388);
  checkLit(bent(makeRipplesNormal(args), 0.5, b), 0.9798, 0.7831, 0.5840);
  checkLit(bent(makeWavesNormal(args), 0.5, a), 0.9948, 0.6475, 0.6574);
  checkLit(bent(makeWavesNormal(args), 0.5, b), 0.8926, 0.7572, 0.3383);
  checkLit(bent(makeWrinklesNormal(args), 0.5, a), 0.9823, 0.8000, 0.7750);
  checkLit(bent(makeWrinklesNormal(args), 0.5, b), 0.9649, 0.8353, 0.7876);
  // As pigments, their values: POV-Ray's `function { pattern { ripples } }` and `waves` printed by #debug.
  CHECK(makeRipples(args)->value({-1, 0.3, 0.5}) == Approx(0.407660390622).margin(1e-9));
  CHECK(makeRipples(args)->value({0.48, 1.14, -0.02}) == Approx(0.556025102241).margin(1e-9));
  CHECK(makeWaves(args)->value({-1, 0.3, 0.5}) == Approx(0.720588585563).margin(1e-9));
  CHECK(makeWaves(args)->value({0.48, 1.14, -0.02}) == Approx(0.524153764426).margin(1e-9));
  // frequency and phase go inside the waves: `ripples 0.5 frequency 3 phase 0.2`, `waves 0.7 frequency 2 phase 0.3`.
  args.frequency = 3;
  args.phase = 0.2;
  checkLit(bent(makeRipplesNormal(args), 0.5, a), 0.9986, 0.6929, 0.7412);
  checkLit(bent(makeRipplesNormal(args), 0.5, b), 0.9977, 0.7252, 0.6612);
  args.frequency = 2;
  args.phase = 0.3;
  checkLit(bent(makeWavesNormal(args), 0.7, a), 0.8154, 0.2423, 0.8128);
  checkLit(bent(makeWavesNormal(args), 0.7, b), 0.9622, 0.6473, 0.8702);
}

TEST_CASE("normal: a normal_map blends its entries' bent normals, a list picks its block's, an average weighs them",
          "[normal]") {
  // As POV-Ray's renders of the plane y = 0 show them (to their 16-bit precision).
  const auto entry = [](double value, const glm::dvec3& v, double amount) {
    return NormalEntry{value, std::make_shared<const Normal>(gradient(v, amount))};
  };
  const glm::dvec3 a = glm::normalize(glm::dvec3(0, 1, -4.0 / 15)), b = glm::normalize(glm::dvec3(0, 1, 4.0 / 15));
  // `gradient x normal_map { [0 gradient z 2] [1 gradient -z 2] }`: at x = 0.125, one eighth of the way.
  Normal map = gradient({1, 0, 0}, 0.5);
  map.map = {entry(0, {0, 0, 1}, 2), entry(1, {0, 0, -1}, 2)};
  checkNear(map.bent(kUp, {0.125, 0, 0.5}, glm::dmat3(1)), glm::normalize(0.875 * a + 0.125 * b));
  checkNear(map.bent(kUp, {0.625, 0, 0.5}, glm::dmat3(1)), glm::normalize(0.375 * a + 0.625 * b));
  // `checker normal { gradient z 2 } normal { gradient -z 2 }`.
  Normal list;
  list.pattern = makeChecker({});
  list.map = {entry(0, {0, 0, 1}, 2), entry(1, {0, 0, -1}, 2)};
  checkNear(list.bent(kUp, {0.5, 0, 0.5}, glm::dmat3(1)), a);
  checkNear(list.bent(kUp, {1.5, 0, 0.5}, glm::dmat3(1)), b);
  // `average normal_map { [3 gradient x 6] [1 gradient z 6] }`.
  Normal average;
  average.average = true;
  average.map = {entry(3, {1, 0, 0}, 6), entry(1, {0, 0, 1}, 6)};
  const glm::dvec3 x = glm::normalize(glm::dvec3(-0.8, 1, 0)), z = glm::normalize(glm::dvec3(0, 1, -0.8));
  checkNear(average.bent(kUp, {0.5, 0, 0.5}, glm::dmat3(1)), glm::normalize(3.0 * x + z));
}

}  // namespace
}  // namespace rt
