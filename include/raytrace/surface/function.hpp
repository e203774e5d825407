// A POV-Ray user function (`function { … }`, POV-Ray 3.7 manual "User-Defined Functions") compiled once into a
// list of stack operations, evaluated at a point with no allocation: what an isosurface and the function
// pattern call millions of times. The POV-Ray reader compiles it (parse/povray/function_compiler.cpp).
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/pigment.hpp"

namespace rt {

class Function {
 public:
  // The most parameters a function has and the deepest its operand stack goes: the evaluator keeps both on the
  // machine's stack.
  static constexpr size_t kMaxParams = 32, kMaxStack = 64;

  enum class Op : unsigned char {
    Const,   // push value
    Param,   // push parameter `index`
    Neg, Not,
    Add, Sub, Mul, Div,
    Lt, Le, Eq, Ne, Ge, Gt, And, Or,
    Choose,   // c ? a : b
    Select3,  // select(a, b, c): b if a < 0, else c
    Select4,  // select(a, b, c, d): b if a < 0, c if a = 0, d if a > 0
    Math1,    // one argument built-in `index` (Math1Kind)
    Math2,    // two argument built-in `index` (Math2Kind)
    Call,     // user function `callee` with `index` arguments
    Internal,  // functions.inc's internal(`value`) with `index` arguments
    Pattern,   // `pigment`'s value() at the point of the three arguments (`function { pattern { … } }`)
    Colour     // component `index` (Component) of `pigment`'s colour at the point of the three arguments
  };
  // A colour's component as a pigment function's `.red`, `.filter` … reads it; Gray is POV-Ray's
  // 0.297 red + 0.589 green + 0.114 blue (manual, "Color Expressions").
  enum Component { Red, Green, Blue, Filter, Transmit, Gray };
  enum Math1Kind { Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh, Asinh, Acosh, Atanh, Exp, Ln, Log, Sqrt, Abs,
                   Floor, Ceil, Int, Degrees, Radians };
  enum Math2Kind { Atan2, Pow, Min, Max, Mod };

  struct Instr {
    Op op;
    unsigned index;
    double value;
    std::shared_ptr<const Function> callee;
    std::shared_ptr<const Pigment> pigment;
    Instr(Op o, unsigned i = 0, double v = 0, std::shared_ptr<const Function> c = nullptr,
          std::shared_ptr<const Pigment> p = nullptr)
        : op(o), index(i), value(v), callee(std::move(c)), pigment(std::move(p)) {}
  };

  Function(std::vector<Instr> code, size_t params, size_t stackDepth)
      : code_(std::move(code)), params_(params), depth_(stackDepth) {}

  // The value for `n` arguments (the parameters past them are 0, as POV-Ray's are).
  double operator()(const double* args, size_t n) const;
  double at(const glm::dvec3& p) const {
    const double a[3] = {p.x, p.y, p.z};
    return (*this)(a, 3);
  }
  size_t params() const { return params_; }
  size_t stackDepth() const { return depth_; }
  const std::vector<Instr>& code() const { return code_; }

  // How many parameters functions.inc's internal(N) takes (x, y, z and its own), or -1 if raytrace does not
  // compute it.
  static int internalParams(int n);
  // A built-in's kind by name, or -1.
  static int math1(std::string_view name);
  static int math2(std::string_view name);

 private:
  std::vector<Instr> code_;
  size_t params_, depth_;
};

}  // namespace rt
