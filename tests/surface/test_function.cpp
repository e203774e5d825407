// The compiled function's evaluator (surface/function.hpp) on hand-written operations, and the function pattern.
#include <catch2/catch.hpp>

#include <cmath>

#include "raytrace/surface/function.hpp"
#include "raytrace/surface/pattern.hpp"
#include "raytrace/surface/pigment.hpp"

namespace rt {
namespace {

using Op = Function::Op;

TEST_CASE("function: calls of other functions, missing arguments as 0, and functions.inc's internal ones", "[function]") {
  // g(a, b) = a − 2b
  const auto g = std::make_shared<Function>(
      std::vector<Function::Instr>{{Op::Param, 0}, {Op::Param, 1}, {Op::Const, 0, 2}, {Op::Mul}, {Op::Sub}}, 2, 3);
  // f(x, y, z) = g(x, y) · g(z)
  const Function f({{Op::Param, 0}, {Op::Param, 1}, {Op::Call, 2, 0, g}, {Op::Param, 2}, {Op::Call, 1, 0, g}, {Op::Mul}}, 3, 3);
  CHECK(f.at({5, 1, 4}) == 12);
  const double one[] = {7};
  CHECK(f(one, 1) == 0);  // g(7, 0) · g(0)
  // internal(61) is f_sphere(x, y, z, radius).
  REQUIRE(Function::internalParams(61) == 4);
  const Function sphere({{Op::Param, 0}, {Op::Param, 1}, {Op::Param, 2}, {Op::Param, 3}, {Op::Internal, 4, 61}}, 4, 4);
  const double a[] = {0, 3, 4, 2};
  CHECK(sphere(a, 4) == 3);
  CHECK(Function::internalParams(25) == -1);  // f_helix1: not computed
  CHECK(Function::math1("sqrt") == Function::Sqrt);
  CHECK(Function::math2("atan2") == Function::Atan2);
  CHECK(Function::math1("vlength") == -1);
}

TEST_CASE("function pattern: the function's value, wrapped below 1 by the pigment", "[function]") {
  PatternArgs args;
  args.function = std::make_shared<Function>(std::vector<Function::Instr>{{Op::Param, 0}, {Op::Param, 2}, {Op::Add}}, 3, 2);
  const PatternKind* kind = patternKind("function");
  REQUIRE(kind != nullptr);
  Pigment p;
  p.pattern = makePattern(*kind, args);
  CHECK(p.pattern->value({0.25, 9, 0.5}) == 0.75);
  auto black = std::make_shared<Pigment>(), white = std::make_shared<Pigment>();
  white->solid.rgb = Color(1);
  p.map = {{0, black}, {1, white}};
  CHECK(p.at({0.25, 9, 0.5}).rgb.r == Approx(0.75));
  CHECK(p.at({1.25, 9, 0.5}).rgb.r == Approx(0.75).margin(1e-4));  // 1.75 wraps (modulo 1.00001) to about 0.75
}

}  // namespace
}  // namespace rt
