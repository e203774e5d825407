// Warps against the points POV-Ray 3.7 reads in their place: each expected value was printed by real POV-Ray
// with `#debug` from pigment functions of gradient x, y and z through the warp (6 decimals, kept as data).
#include <catch2/catch.hpp>

#include "raytrace/surface/warp.hpp"

using namespace rt;

namespace {

struct Case {
  glm::dvec3 p, expected;
};

void check(const Warp& w, std::initializer_list<Case> cases) {
  for (const Case& c : cases) {
    INFO("at " << c.p.x << ", " << c.p.y << ", " << c.p.z);
    const glm::dvec3 q = w.apply(c.p);
    for (int k = 0; k < 3; ++k) CHECK(q[k] == Approx(c.expected[k]).margin(1e-5));
  }
}

}  // namespace

TEST_CASE("repeat warp: each copy shifted by its offset, odd copies flipped first, as POV-Ray reads them", "[warp]") {
  RepeatWarpArgs a;  // repeat 2*x offset <0.1,0.2,0.05> flip <1,1,0>
  a.axis = 0;
  a.width = 2;
  a.offset = {0.1, 0.2, 0.05};
  a.flip = {true, true, false};
  check(*makeRepeatWarp(a), {{{0.3, 0.2, 0.1}, {0.3, 0.2, 0.1}},
                             {{2.3, 0.2, 0.1}, {1.800001, 0.0, 0.150001}},
                             {{-0.7, 0.4, 0.6}, {0.599998, -0.600001, 0.550002}},
                             {{4.9, -0.3, 0.2}, {1.099998, 0.099999, 0.300002}},
                             {{-2.6, 1.5, -0.4}, {1.200002, 1.099998, -0.5}},
                             {{3.3, 1.7, 2.2}, {0.800002, -1.499999, 2.249998}},
                             {{-1.2, -1.3, -0.5}, {1.099998, 1.099998, -0.549999}}});
  RepeatWarpArgs y;  // repeat y*1.5 flip <0,0,1>
  y.axis = 1;
  y.width = 1.5;
  y.flip = {false, false, true};
  check(*makeRepeatWarp(y), {{{4.9, -0.3, 0.2}, {4.900002, 1.200002, -0.2}},
                             {{-2.6, 1.5, -0.4}, {-2.599999, 0.0, 0.400001}},
                             {{3.3, 1.7, 2.2}, {3.299999, 0.199997, -2.200001}}});
  RepeatWarpArgs negative;  // repeat -2*x: the slice (-2, 0]
  negative.width = -2;
  check(*makeRepeatWarp(negative), {{{0.3, 0.2, 0.1}, {-1.699999, 0.2, 0.1}},
                                    {{2.3, 0.2, 0.1}, {-1.699999, 0.2, 0.1}},
                                    {{-0.7, 0.4, 0.6}, {-0.7, 0.4, 0.6}},
                                    {{4.9, -0.3, 0.2}, {-1.100001, -0.3, 0.2}}});
}

TEST_CASE("black hole warp: a point moved along its line from the centre by strength * closeness^falloff", "[warp]") {
  BlackHoleArgs a;  // black_hole <0.5,0.5,0>, 0.5
  a.centre = {0.5, 0.5, 0};
  a.radius = 0.5;
  check(*makeBlackHoleWarp(a), {{{0.3, 0.2, 0.1}, {0.287330, 0.181001, 0.106335}},
                                {{0.6, 0.6, 0.2}, {0.626022, 0.626022, 0.252038}},
                                {{0.45, 0.45, 0.05}, {0.415820, 0.415820, 0.084180}},
                                {{0.9, 0.1, 0.3}, {0.9, 0.1, 0.3}}});
  BlackHoleArgs inverse = a;  // falloff 1 strength 0.7 inverse
  inverse.falloff = 1;
  inverse.strength = 0.7;
  inverse.inverse = true;
  check(*makeBlackHoleWarp(inverse), {{{0.3, 0.2, 0.1}, {0.335234, 0.252849, 0.082386}},
                                      {{0.6, 0.6, 0.2}, {0.564295, 0.564295, 0.128585}},
                                      {{0.45, 0.45, 0.05}, {0.478935, 0.478935, 0.021064}}});
  BlackHoleArgs strong = a;  // strength 3: moved at most as far as the point is from the centre
  strong.strength = 3;
  check(*makeBlackHoleWarp(strong), {{{0.3, 0.2, 0.1}, {0.261998, 0.142998, 0.119001}},
                                     {{0.6, 0.6, 0.2}, {0.678062, 0.678062, 0.356120}},
                                     {{0.45, 0.45, 0.05}, {0.4, 0.4, 0.1}}});
  BlackHoleArgs repeated;  // black_hole <0.5,0.5,0.5>, 0.4 repeat <1,1,1>
  repeated.centre = glm::dvec3(0.5);
  repeated.radius = 0.4;
  repeated.repeat = glm::dvec3(1);
  check(*makeBlackHoleWarp(repeated), {{{0.3, 0.2, 0.1}, {0.3, 0.2, 0.1}},
                                       {{-0.7, 0.4, 0.6}, {-0.730050, 0.384974, 0.615025}},
                                       {{-2.6, 1.5, -0.4}, {-2.641788, 1.5, -0.358212}},
                                       {{-1.2, -1.3, -0.5}, {-1.197082, -1.298055, -0.5}}});
}

TEST_CASE("black hole warp: turbulence moves each block's centre; a hole too big for its block moves it", "[warp]") {
  // black_hole <0.2,0.3,0.5>, 0.4 falloff 1 strength 0.8 repeat <1,1,0> turbulence <0.3,0.2,0.1>: the centre's
  // x and y moved out to the radius, the block's x enlarged to 1.1; points near five blocks' centres.
  BlackHoleArgs a;
  a.centre = {0.2, 0.3, 0.5};
  a.radius = 0.4;
  a.falloff = 1;
  a.strength = 0.8;
  a.repeat = {1, 1, 0};
  a.turbulence = {0.3, 0.2, 0.1};
  check(*makeBlackHoleWarp(a), {{{-1.6047, -0.6045, 0.5826}, {-1.548585, -0.652003, 0.612837}},
                                {{-0.3297, -0.5928, 0.6286}, {-0.273561, -0.640288, 0.658816}},
                                {{0.5469, 1.4775, 0.5853}, {0.603020, 1.430005, 0.615543}},
                                {{1.6514, -0.5231, 0.6222}, {1.707512, -0.570601, 0.652438}},
                                {{2.7632, -0.6411, 0.6107}, {2.819324, -0.688598, 0.640911}},
                                {{0.3, 0.2, 0.1}, {0.300002, 0.199997, 0.099999}}});
  BlackHoleArgs alone;  // black_hole <0.5,0.5,0.5>, 0.4 falloff 0 turbulence 0.2: without a repeat it stays
  alone.centre = glm::dvec3(0.5);
  alone.radius = 0.4;
  alone.falloff = 0;
  alone.turbulence = glm::dvec3(0.2);
  check(*makeBlackHoleWarp(alone), {{{0.6, 0.5, 0.55}, {0.7, 0.5, 0.6}}});
}

TEST_CASE("planar warp: the plane's pattern extruded along z, as POV-Ray reads it for any normal", "[warp]") {
  check(*makePlanarWarp({0, 0, 1}, 0), {{{0.3, 0.2, 0.1}, {0.3, 0.2, 0}}, {{-2.6, 1.5, -0.4}, {-2.6, 1.5, 0}}});
  check(*makePlanarWarp({0, 1, 0}, 0.3), {{{0.3, 0.2, 0.1}, {0.3, -0.3, 0.2}}, {{-2.6, 1.5, -0.4}, {-2.6, -0.3, 1.5}}});
  check(*makePlanarWarp({-1, 0, 0}, 0.3), {{{0.3, 0.2, 0.1}, {-0.3, -0.2, 0.3}}});
  check(*makePlanarWarp(glm::normalize(glm::dvec3(1, 1, 0)), 0.5),
        {{{0.3, 0.2, 0.1}, {0.565684, -0.212133, -0.070712}}, {{4.9, -0.3, 0.2}, {3.818375, -0.565687, -3.676954}}});
  check(*makePlanarWarp(glm::normalize(glm::dvec3(1, 2, 3)), 0.5),
        {{{0.3, 0.2, 0.1}, {0.534523, -0.053453, 0.427616}}, {{4.9, -0.3, 0.2}, {6.681532, -0.587976, -1.069045}}});
}

TEST_CASE("cylindrical warp: the turn round y (times the distance^dist_exp), y and the distance, oriented", "[warp]") {
  MappingWarpArgs a;
  check(*makeCylindricalWarp(a), {{{0.3, 0.2, 0.1}, {0.051210, 0.2, 0.316230}},
                                  {{-2.6, 1.5, -0.4}, {0.524290, 1.5, 2.630590}},
                                  {{0.5, -0.7, -0.3}, {0.913990, -0.7, 0.583100}},
                                  {{1, 2, 3}, {0.198790, 2, 3.162280}},
                                  {{0, 2, 0}, {0, 2, 0}}});
  MappingWarpArgs o;  // orientation <1,2,3> dist_exp 1
  o.orientation = glm::normalize(glm::dvec3(1, 2, 3));
  o.distExp = 1;
  check(*makeCylindricalWarp(o), {{{0.3, 0.2, 0.1}, {0.106150, 0.044780, 0.356120}},
                                  {{-2.6, 1.5, -0.4}, {2.546090, 0.197460, 2.542340}},
                                  {{0.5, -0.7, -0.3}, {0.868010, -1.060010, -0.049080}},
                                  {{1, 2, 3}, {1.685200, 0.447780, 3.436500}},
                                  {{0, 2, 0}, {0, 2, 0}}});
}

TEST_CASE("spherical warp: the turn round y and the latitude (times the distance^dist_exp) and the distance", "[warp]") {
  MappingWarpArgs a;  // dist_exp 1
  a.distExp = 1;
  check(*makeSphericalWarp(a), {{{0.3, 0.2, 0.1}, {0.019160, 0.254250, 0.374170}},
                                {{-2.6, 1.5, -0.4}, {1.587670, 2.013630, 3.028200}},
                                {{0.5, -0.7, -0.3}, {0.832680, 0.201410, 0.911040}},
                                {{1, 2, 3}, {0.743810, 2.542490, 3.741660}},
                                {{0, 2, 0}, {0, 2, 2}},
                                {{0, 0, 0}, {0, 0, 0}}});
  MappingWarpArgs o;  // orientation -x dist_exp 0.5
  o.orientation = {-1, 0, 0};
  o.distExp = 0.5;
  check(*makeSphericalWarp(o), {{{0.3, 0.2, 0.1}, {-0.374170, -0.415650, 0.031320}},
                                {{-2.6, 1.5, -0.4}, {-3.028200, -1.157140, 0.912360}},
                                {{0.5, -0.7, -0.3}, {-0.911050, -0.211020, 0.872390}},
                                {{1, 2, 3}, {-3.741660, -1.314400, 0.384530}},
                                {{0, 2, 0}, {-2, -1.414220, 0}}});
}

TEST_CASE("toroidal warp: the turns round y and round the tube, and the distance from the core circle", "[warp]") {
  MappingWarpArgs a;
  check(*makeToroidalWarp(a), {{{0.3, 0.2, 0.1}, {0.051210, 0.954710, 0.712420}},
                               {{-2.6, 1.5, -0.4}, {0.524290, 0.618360, 2.215590}},
                               {{0.5, -0.7, -0.3}, {0.913990, 0.164510, 0.814750}},
                               {{1, 2, 3}, {0.198790, 0.618800, 2.945410}},
                               {{0, 2, 0}, {0, 2, 0}},
                               {{1, 0, 0}, {0, 0, 0}},
                               {{0.5, 0, 0}, {0, 0, 0.5}},
                               {{1.5, 0, 0}, {0, 0.5, 0.5}},
                               {{1, 0.5, 0}, {0, 0.75, 0.5}}});
  MappingWarpArgs o;  // orientation y major_radius 0.5 dist_exp 1.5
  o.orientation = {0, 1, 0};
  o.majorRadius = 0.5;
  o.distExp = 1.5;
  check(*makeToroidalWarp(o), {{{0.3, 0.2, 0.1}, {0.007250, -0.271610, 0.122910}},
                               {{-2.6, 1.5, -0.4}, {2.205210, -2.605650, 2.513660}},
                               {{0.5, -0.7, -0.3}, {0.540940, -0.704910, 0.159090}},
                               {{1, 2, 3}, {1.207900, -3.329830, 3.661160}}});
}

TEST_CASE("cubic warp: each face of the cube round the origin where a box's uv_mapping lays it", "[warp]") {
  check(*makeCubicWarp(), {{{0.3, 0.2, 0.1}, {0.583330, 0.611110, 0.3}},
                           {{-2.6, 1.5, -0.4}, {0.105770, 0.596150, 2.6}},
                           {{0.2, 0.9, 0.3}, {0.402780, 0.777780, 0.9}},
                           {{0.5, -0.7, -0.3}, {0.464290, 0.095240, 0.7}},
                           {{-0.2, -0.1, 0.9}, {0.347220, 0.481480, 0.9}},
                           {{0.7, 0.1, -1.2}, {0.802080, 0.513890, 1.2}},
                           {{0, 0, 0}, {0, 0, 0}}});
  // On an edge the face is the first of +x, +y, −x, −y, +z, −z.
  check(*makeCubicWarp(), {{{1, 1, 0.2}, {0.6, 0.666670, 1}},
                           {{-1, 1, 0.2}, {0.25, 0.8, 1}},
                           {{-1, -1, 0.2}, {0.15, 0.333330, 1}},
                           {{0.2, -1, -1}, {0.4, 0, 1}},
                           {{0.2, 1, -1}, {0.4, 1, 1}},
                           {{-1, 0.2, -1}, {0, 0.533330, 1}}});
}
