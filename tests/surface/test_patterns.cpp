// hexagon, brick and the fractal patterns against values POV-Ray 3.7 printed at these points (a pattern function,
// `#declare F = function { pattern { … } }`, written with #debug str(F(x, y, z), 0, 16); docs/povray-noise.md).
#include <catch2/catch.hpp>

#include <cmath>
#include <iterator>
#include <vector>

#include "raytrace/surface/pattern.hpp"
#include "pov_scene.hpp"

namespace rt {
namespace {

// Ten points at random, then some on either side of the default bricks' mortar.
const glm::dvec3 kBlockPoints[] = {
    {-0.8572, 0.8368, 7.6358}, {-0.6183, 0.1098, 1.5729}, {-5.6761, 0.1667, 2.3379}, {5.2736, -5.6823, -3.5388},
    {-7.3679, 4.3350, 3.4819}, {-8.2462, 6.7507, 8.3656}, {2.7706, 1.6179, -6.1651}, {-8.7300, 0.3973, -7.9281},
    {-5.5763, -3.6128, -8.4585}, {-0.6492, -0.8326, 6.1637}, {1.0, 2.7, 1.0}, {-0.2, 1.0, 1.0},
    {3.7, 4.0, 1.0}, {1.0, 1.0, 2.0}, {1.0, 4.0, 4.2}, {1.0, 4.0, 2.0},
    {1.4, -0.9, 0.3}, {-1.2, 0.5, -1.1}};

// Points about the Mandelbrot set, and about the magnet sets.
const glm::dvec3 kMandelPoints[] = {
    {-0.5559, 0.3464, 0.3328}, {-1.2863, -1.0761, -0.2505}, {-0.9971, 0.6828, 0.3812}, {-0.2768, 0.1280, 0.3226},
    {-1.2803, -0.1319, -0.6755}, {0.3931, -0.9706, 0.6376}, {-1.4359, 0.4113, -0.3260}, {-0.7098, 0.7533, -0.9628},
    {-1.4663, 0.9131, 0.0179}, {-1.3998, 1.0717, 0.8934}, {-1.3524, -0.1689, -0.7299}, {-0.9124, 0.2672, -0.6730}};
const glm::dvec3 kMagnetPoints[] = {
    {0.0360, 0.7410, 0.3682}, {2.3973, -1.2571, -0.5389}, {-0.4114, -1.0993, 0.4680}, {-0.4791, 0.1253, -0.5722},
    {0.1786, -0.2737, 0.6753}, {1.4336, -1.9423, -0.4483}, {-0.4132, 1.4851, 0.6195}, {2.2242, 1.3055, 0.4895},
    {2.7973, 1.1751, -0.4866}, {2.3998, -0.0529, 0.5100}, {1.2566, -0.2817, -0.2716}, {0.7193, -0.7450, -0.7653}};

// POV-Ray printed 16 decimals; a fractal's orbit carries the rounding of every step.
constexpr double kClose = 1e-9;

template <size_t N>
void check(const char* name, const PatternArgs& args, const glm::dvec3 (&points)[N], const std::vector<double>& expected) {
  const PatternKind* kind = patternKind(name);
  REQUIRE(kind != nullptr);
  REQUIRE(expected.size() == N);
  const auto pattern = makePattern(*kind, args);
  for (size_t i = 0; i < N; ++i) {
    INFO(name << " at point " << i);
    // POV-Ray's pattern functions wrap a continuous pattern's value as a ramp wave does, and give a block
    // pattern's index as it is.
    double v = pattern->value(points[i]);
    if (pattern->blocks() == 0) v = std::fmod(v, 1.00001);
    if (v < 0) v -= std::floor(v);
    CHECK(v == Approx(expected[i]).margin(kClose));
  }
}

FractalArgs fractal(FractalArgs::Set set, int iterations) {
  FractalArgs f;
  f.set = set;
  f.iterations = iterations;
  return f;
}

TEST_CASE("patterns: hexagon's three colours and brick's mortar", "[patterns]") {
  PatternArgs a;
  check("hexagon", a, kBlockPoints, {0, 1, 1, 1, 1, 2, 2, 1, 1, 2, 2, 1, 2, 0, 1, 0, 2, 1});
  check("brick", a, kBlockPoints, {1, 1, 1, 1, 1, 0, 1, 1, 1, 1, 0, 0, 0, 0, 0, 1, 1, 1});
  a.brickSize = {2, 1, 1.5};
  a.mortar = 0.2;
  check("brick", a, kBlockPoints, {0, 1, 1, 1, 1, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1});
  CHECK(makePattern(*patternKind("hexagon"), a)->blocks() == 3);
  CHECK(makePattern(*patternKind("brick"), a)->defaultBlock(1) == Color(0.6f, 0.15f, 0.15f));
}

TEST_CASE("patterns: mandel, its exponents and its interior and exterior types", "[patterns]") {
  using Set = FractalArgs::Set;
  PatternArgs a;
  a.fractal = fractal(Set::Mandel, 30);  // mandel 30
  check("mandel", a, kMandelPoints,
        {1.0, 0.0333333333333333, 0.0666666666666667, 1.0, 0.3, 0.0333333333333333, 0.0666666666666667,
         0.0666666666666667, 0.0333333333333333, 0.0, 0.2, 1.0});
  a.fractal.interiorType = 1;  // interior 1, 1 exterior 6, 0.1
  a.fractal.exteriorType = 6;
  a.fractal.exteriorFactor = 0.1;
  check("mandel", a, kMandelPoints,
        {0.3006317323402200, 0.5146883067979758, 0.2852114216060694, 0.2239768215262856, 0.2002379327148071,
         0.2488862185348891, 0.2319755215178330, 0.2219974850008730, 0.4780647432508593, 0.2016537373721515,
         0.2492043543716286, 0.1808378858894005});
  a.fractal = fractal(Set::Mandel, 20);  // mandel 20 exponent 3 interior 6, 0.5 exterior 2, 0.5
  a.fractal.exponent = 3;
  a.fractal.interiorType = 6;
  a.fractal.interiorFactor = 0.5;
  a.fractal.exteriorType = 2;
  a.fractal.exteriorFactor = 0.5;
  check("mandel", a, kMandelPoints,
        {0.7284693439428371, 0.5270009303110005, 0.7030831182905000, 0.0893758066431550, 0.3439577873110000,
         0.2480233797851583, 0.1661461939670001, 0.1931262553431117, 0.5243463124910004, 0.3402792227370006,
         0.1449201272939997, 0.7903308512152074});
  a.fractal = fractal(Set::Mandel, 20);  // mandel 20 exponent 5 interior 4, 1 exterior 3, 1
  a.fractal.exponent = 5;
  a.fractal.interiorType = 4;
  a.fractal.exteriorType = 3;
  check("mandel", a, kMandelPoints,
        {0.2321916711590296, 0.3690600017748751, 0.0817538350319853, 0.0757595112440596, 0.1336926987747427,
         0.3397844029509440, 0.7307170742290325, 0.5038516474631034, 0.2843068368266950, 0.9403156692505259,
         0.0940955431541228, 0.5045148906935113});
}

TEST_CASE("patterns: julia with its constant", "[patterns]") {
  using Set = FractalArgs::Set;
  PatternArgs a;
  a.fractal = fractal(Set::Julia, 30);  // julia <0.353, 0.288> 30 interior 2, 1 exterior 5, 0.2
  a.fractal.constant = {0.353, 0.288};
  a.fractal.interiorType = 2;
  a.fractal.exteriorType = 5;
  a.fractal.exteriorFactor = 0.2;
  check("julia", a, kMandelPoints,
        {0.1466609295612410, 0.8682754569680040, 0.0264337528980547, 0.1712172470939707, 0.0783108954514119,
         0.9826201107875294, 0.1595510085194791, 0.2886214830843931, 0.1421777611639687, 0.4713382378905886,
         0.1109575396340237, 0.0079329006214745});
  a.fractal = fractal(Set::Julia, 20);  // julia <-0.5, 0.5> 20 exponent 4 interior 0, 0.3 exterior 4, 0.05
  a.fractal.constant = {-0.5, 0.5};
  a.fractal.exponent = 4;
  a.fractal.interiorType = 0;
  a.fractal.interiorFactor = 0.3;
  a.fractal.exteriorType = 4;
  a.fractal.exteriorFactor = 0.05;
  check("julia", a, kMandelPoints,
        {0.2372271216503350, 0.1341608041644218, 0.2153407406321424, 0.3938588532902197, 0.2032267229728384,
         0.8923487723274024, 0.1422857429017826, 0.0065913506082511, 0.7628510279336980, 0.9111676304092295,
         0.3207911637465624, 0.7580932856178311});
}

TEST_CASE("patterns: magnet 1 and 2, mandel and julia forms", "[patterns]") {
  using Set = FractalArgs::Set;
  PatternArgs a;
  a.fractal = fractal(Set::Magnet1Mandel, 30);  // magnet 1 mandel 30 interior 1, 1
  a.fractal.interiorType = 1;
  check("magnet", a, kMagnetPoints,
        {0.3355085141375783, 0.1333333333333333, 0.2333333333333333, 0.1666666666666667, 0.2209667249354747,
         0.4333333333333333, 0.1666666666666667, 0.3, 0.3333333333333333, 0.0666666666666667, 0.0790561915822691,
         0.2609797765707371});
  a.fractal = fractal(Set::Magnet2Mandel, 30);  // magnet 2 mandel 30 exterior 2, 0.5
  a.fractal.exteriorType = 2;
  a.fractal.exteriorFactor = 0.5;
  check("magnet", a, kMagnetPoints,
        {1.0, 0.4996403339934815, 0.5002803919760721, 0.4996119729095259, 1.0, 0.5001378510427887,
         0.4999673136635822, 0.5006896299017255, 0.5000058343088234, 0.5005338451647521, 1.0, 1.0});
  a.fractal = fractal(Set::Magnet1Julia, 30);  // magnet 1 julia <0.5, 0.3> 30 interior 6, 0.5 exterior 0, 0.7
  a.fractal.constant = {0.5, 0.3};
  a.fractal.interiorType = 6;
  a.fractal.interiorFactor = 0.5;
  a.fractal.exteriorType = 0;
  a.fractal.exteriorFactor = 0.7;
  check("magnet", a, kMagnetPoints,
        {0.0269384612405658, 0.0269384612499539, 0.0269384612397196, 0.0269384612402609, 0.0269384612401642,
         0.0269384612352595, 0.0269384612398432, 0.0269384612371127, 0.7, 0.7, 0.0269384613573187,
         0.0269384612399792});
  a.fractal = fractal(Set::Magnet2Julia, 30);  // magnet 2 julia <1.5, -0.3> 30 interior 3, 1
  a.fractal.constant = {1.5, -0.3};
  check("magnet", a, kMagnetPoints,
        {0.1, 0.0666666666666667, 0.2, 0.0333333333333333, 0.0, 0.1333333333333333, 0.1333333333333333, 0.1, 0.1,
         0.0666666666666667, 0.0333333333333333, 0.0666666666666667});
}

TEST_CASE("patterns: the scene reader's brick, hexagon and fractal syntax", "[patterns]") {
  const SceneDesc s = test::pov(R"(
plane { y, 0 pigment { hexagon } }
plane { y, 0 pigment { brick rgb 1, pigment { rgb <0, 0, 1> } brick_size <2, 1, 1.5> mortar 0.2 } }
plane { y, 0 pigment { julia <0.353, 0.288>, 30 interior 2, 1 exterior 5, 0.2 } }
plane { y, 0 pigment { magnet 2 julia <1.5, -0.3> 30 interior 3, 1 } }
plane { y, 0 pigment { mandel 20 exponent 5 interior 4, 1 exterior 3, 1 color_map { [0 rgb 0] [1 rgb 1] } } }
plane { y, 0 pigment { mandel 1000 } }
)");
  REQUIRE(s.objects.size() == 6);
  const auto colour = [&](size_t object, const glm::dvec3& p) { return s.objects[object].texture->at(p).pigment; };
  CHECK(colour(0, {0, 0, 0}) == Color(0, 0, 1));  // POV-Ray's blue, green and red
  CHECK(colour(0, {0, 0, 1.7}) == Color(0, 1, 0));
  CHECK(colour(0, {1.5, 0, 0.8}) == Color(1, 0, 0));
  CHECK(colour(1, {-0.8572, 0.8368, 7.6358}) == Color(1));  // in the mortar
  CHECK(colour(1, {-0.6183, 0.1098, 1.5729}) == Color(0, 0, 1));
  // The fractals' values (the test cases above) as the default grey ramp.
  CHECK(colour(2, kMandelPoints[1]).r == Approx(0.8682754569680040).margin(1e-6));
  CHECK(colour(3, kMagnetPoints[2]).r == Approx(0.2).margin(1e-6));
  CHECK(colour(4, kMandelPoints[6]).r == Approx(0.7307170742290325).margin(1e-6));
  // mandel's own colour map, as POV-Ray's pigment function gave it at values 0, 0.002, 0.013, 0.02 and 1.
  const auto near = [](const Color& a, const Color& b) { return glm::all(glm::lessThan(glm::abs(a - b), Color(1e-5f))); };
  CHECK(near(colour(5, {-2.1, 0, 0}), Color(0)));
  CHECK(near(colour(5, {-1.9974, 0.03534, 0}), Color(0.09091f, 1, 0.90909f)));
  CHECK(near(colour(5, {-1.2099, 0.30659, 0}), Color(1, 0.66667f, 0.33333f)));
  CHECK(near(colour(5, {-1.1982, 0.31062, 0}), Color(0.94118f, 0.05882f, 1)));
  CHECK(near(colour(5, {0, 0, 0}), Color(0, 1, 1)));
}

TEST_CASE("patterns: bad fractal and brick settings stop the scene", "[patterns]") {
  CHECK(test::povFailure("plane { y, 0 pigment { magnet 3 mandel 30 } }") ==
        "scene.pov:2:24: error: 'magnet' needs its type, 1 or 2");
  CHECK(test::povFailure("plane { y, 0 pigment { magnet 1 30 } }") ==
        "scene.pov:2:24: error: 'magnet' needs 'mandel' or 'julia' after its type");
  CHECK(test::povFailure("plane { y, 0 pigment { julia 30 } }") ==
        "scene.pov:2:24: error: 'julia' needs its number of iterations");
  CHECK(test::povFailure("plane { y, 0 pigment { mandel 30 exterior 7, 1 } }") ==
        "scene.pov:2:34: error: the fractal exterior type must be 0 to 6");
  CHECK(test::povFailure("plane { y, 0 pigment { mandel 30 interior 1 } }") ==
        "scene.pov:2:34: error: 'interior' needs a type and a factor");
  CHECK(test::povFailure("plane { y, 0 pigment { magnet 1 mandel 30 exponent 3 } }") ==
        "scene.pov:2:43: error: 'exponent' belongs to a mandel or julia pattern");
  CHECK(test::povFailure("plane { y, 0 pigment { bozo interior 1, 1 } }") ==
        "scene.pov:2:29: error: 'interior' belongs to a mandel, julia or magnet pattern");
  CHECK(test::povFailure("plane { y, 0 pigment { hexagon mortar 0.3 } }") ==
        "scene.pov:2:32: error: 'mortar' belongs to a brick pattern");
}

TEST_CASE("patterns: a later pigment block remakes the earlier block's pattern with its own modifiers",
          "[patterns]") {
  // What POV-Ray's pigment function gave for bozo turbulence 0.5 octaves 2 (and without octaves) rotate 90*z.
  const SceneDesc s = test::pov(R"(
#declare T = texture { pigment { bozo turbulence 0.5 color_map { [0 rgb 0] [1 rgb 1] } } }
plane { y, 0 texture { T pigment { octaves 2 rotate 90*z } } }
plane { y, 0 texture { T pigment { rotate 90*z } } }
)");
  REQUIRE(s.objects.size() == 2);
  const glm::dvec3 points[] = {{0.3, 0.2, 0.1}, {1.7, -0.4, 2.2}, {-2.6, 1.5, -0.4}, {0.9, 3.1, -1.3}};
  const double octaves2[] = {0.568297, 0.564489, 0.528309, 0.583634};
  const double octaves6[] = {0.529166, 0.576050, 0.514104, 0.599669};
  for (size_t i = 0; i < 4; ++i) {
    CHECK(s.objects[0].texture->at(points[i]).pigment.r == Approx(octaves2[i]).margin(2e-6));
    CHECK(s.objects[1].texture->at(points[i]).pigment.r == Approx(octaves6[i]).margin(2e-6));
  }
}

}  // namespace
}  // namespace rt
