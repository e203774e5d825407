#include "raytrace/surface/function.hpp"

#include <algorithm>
#include <cmath>

#include "raytrace/surface/noise.hpp"

namespace rt {

namespace {

constexpr double kPi = 3.14159265358979323846;

// functions.inc's internal functions raytrace computes: x, y, z then `extra` parameters. Each formula was
// checked against POV-Ray's values at sample points (tests/surface/test_function.cpp).
struct Internal {
  int number, extra;
  double (*f)(const double*);
};

double sphere(const double* a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) - a[3]; }
double torus(const double* a) {
  const double ring = std::sqrt(a[0] * a[0] + a[2] * a[2]) - a[3];
  return std::sqrt(ring * ring + a[1] * a[1]) - a[4];
}
// A box of half sizes P1, P2, P3 with edges rounded to radius P0, less 1e-6 everywhere, as POV-Ray's is.
double roundedBox(const double* a) {
  const double r = a[3];
  const glm::dvec3 d = glm::max(glm::abs(glm::dvec3(a[0], a[1], a[2])) - (glm::dvec3(a[4], a[5], a[6]) - r), 0.0);
  return glm::length(d) - r - 1e-6;
}
// 1 − (( |x|^(2/e) + |y|^(2/e) )^(e/n) + |z|^(2/n))^(n/2), e = P0 (east-west), n = P1 (north-south).
double superellipsoid(const double* a) {
  const double e = a[3], n = a[4];
  const double s = std::pow(std::pow(std::abs(a[0]), 2 / e) + std::pow(std::abs(a[1]), 2 / e), e / n) +
                   std::pow(std::abs(a[2]), 2 / n);
  return 1 - std::pow(s, n / 2);
}
double radius(const double* a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
double theta(const double* a) { return std::atan2(a[0], a[2]); }  // the angle about y, from z toward x
double phi(const double* a) { return std::acos(a[1] / radius(a)); }  // the angle from y
double ellipsoid(const double* a) {
  return std::sqrt(std::pow(a[0] * a[3], 2) + std::pow(a[1] * a[4], 2) + std::pow(a[2] * a[5], 2));
}
double noise3d(const double* a) { return noise({a[0], a[1], a[2]}, NoiseGenerator::RangeCorrected); }
double noiseGenerator(const double* a) {
  return noise({a[0], a[1], a[2]}, noiseGeneratorOf(a[3]));
}

constexpr Internal kInternals[] = {
    {17, 3, ellipsoid}, {47, 0, phi},    {57, 0, radius}, {60, 4, roundedBox}, {61, 1, sphere},
    {68, 2, superellipsoid}, {69, 0, theta}, {70, 2, torus}, {76, 0, noise3d}, {78, 1, noiseGenerator},
};

const Internal* internal(int n) {
  for (const Internal& i : kInternals) {
    if (i.number == n) return &i;
  }
  return nullptr;
}

double math1(unsigned kind, double a) {
  switch (Function::Math1Kind(kind)) {
    case Function::Sin: return std::sin(a);
    case Function::Cos: return std::cos(a);
    case Function::Tan: return std::tan(a);
    case Function::Asin: return std::asin(a);
    case Function::Acos: return std::acos(a);
    case Function::Atan: return std::atan(a);
    case Function::Sinh: return std::sinh(a);
    case Function::Cosh: return std::cosh(a);
    case Function::Tanh: return std::tanh(a);
    case Function::Asinh: return std::asinh(a);
    case Function::Acosh: return std::acosh(a);
    case Function::Atanh: return std::atanh(a);
    case Function::Exp: return std::exp(a);
    case Function::Ln: return std::log(a);
    case Function::Log: return std::log10(a);
    case Function::Sqrt: return std::sqrt(a);
    case Function::Abs: return std::abs(a);
    case Function::Floor: return std::floor(a);
    case Function::Ceil: return std::ceil(a);
    case Function::Int: return std::trunc(a);
    case Function::Degrees: return a * (180 / kPi);
    case Function::Radians: return a * (kPi / 180);
  }
  return 0;
}

double math2(unsigned kind, double a, double b) {
  switch (Function::Math2Kind(kind)) {
    case Function::Atan2: return std::atan2(a, b);
    case Function::Pow: return std::pow(a, b);
    case Function::Min: return std::min(a, b);
    case Function::Max: return std::max(a, b);
    case Function::Mod: return std::fmod(a, b);
  }
  return 0;
}

double component(const Rgbft& c, unsigned which) {
  switch (Function::Component(which)) {
    case Function::Red: return c.rgb.r;
    case Function::Green: return c.rgb.g;
    case Function::Blue: return c.rgb.b;
    case Function::Filter: return c.filter;
    case Function::Transmit: return c.transmit;
    case Function::Gray: return c.rgb.r * 0.297 + c.rgb.g * 0.589 + c.rgb.b * 0.114;
  }
  return 0;
}

}  // namespace

int Function::internalParams(int n) {
  const Internal* i = internal(n);
  return i ? 3 + i->extra : -1;
}

int Function::math1(std::string_view name) {
  static constexpr std::string_view kNames[] = {"sin",  "cos",   "tan",  "asin", "acos", "atan",  "sinh", "cosh",
                                                "tanh", "asinh", "acosh", "atanh", "exp",  "ln",   "log",  "sqrt",
                                                "abs",  "floor", "ceil", "int",  "degrees", "radians"};
  for (size_t i = 0; i < std::size(kNames); ++i) {
    if (kNames[i] == name) return int(i);
  }
  return -1;
}

int Function::math2(std::string_view name) {
  static constexpr std::string_view kNames[] = {"atan2", "pow", "min", "max", "mod"};
  for (size_t i = 0; i < std::size(kNames); ++i) {
    if (kNames[i] == name) return int(i);
  }
  return -1;
}

double Function::operator()(const double* args, size_t n) const {
  double param[kMaxParams];
  const size_t given = std::min(n, params_);
  std::copy_n(args, given, param);
  std::fill(param + given, param + params_, 0.0);
  double s[kMaxStack];
  size_t top = 0;  // s[top - 1] is the top
  for (const Instr& i : code_) {
    switch (i.op) {
      case Op::Const: s[top++] = i.value; break;
      case Op::Param: s[top++] = param[i.index]; break;
      case Op::Neg: s[top - 1] = -s[top - 1]; break;
      case Op::Not: s[top - 1] = s[top - 1] == 0; break;
      case Op::Add: --top; s[top - 1] += s[top]; break;
      case Op::Sub: --top; s[top - 1] -= s[top]; break;
      case Op::Mul: --top; s[top - 1] *= s[top]; break;
      case Op::Div: --top; s[top - 1] /= s[top]; break;
      case Op::Lt: --top; s[top - 1] = s[top - 1] < s[top]; break;
      case Op::Le: --top; s[top - 1] = s[top - 1] <= s[top]; break;
      case Op::Eq: --top; s[top - 1] = s[top - 1] == s[top]; break;
      case Op::Ne: --top; s[top - 1] = s[top - 1] != s[top]; break;
      case Op::Ge: --top; s[top - 1] = s[top - 1] >= s[top]; break;
      case Op::Gt: --top; s[top - 1] = s[top - 1] > s[top]; break;
      case Op::And: --top; s[top - 1] = s[top - 1] != 0 && s[top] != 0; break;
      case Op::Or: --top; s[top - 1] = s[top - 1] != 0 || s[top] != 0; break;
      case Op::Choose: top -= 2; s[top - 1] = s[top - 1] != 0 ? s[top] : s[top + 1]; break;
      case Op::Select3: top -= 2; s[top - 1] = s[top - 1] < 0 ? s[top] : s[top + 1]; break;
      case Op::Select4: {
        top -= 3;
        const double a = s[top - 1];
        s[top - 1] = a < 0 ? s[top] : a == 0 ? s[top + 1] : s[top + 2];
        break;
      }
      case Op::Math1: s[top - 1] = rt::math1(i.index, s[top - 1]); break;
      case Op::Math2: --top; s[top - 1] = rt::math2(i.index, s[top - 1], s[top]); break;
      case Op::Call: top -= i.index; s[top] = (*i.callee)(s + top, i.index); ++top; break;
      case Op::Internal: {
        // The compiler passes exactly 3 + extra arguments.
        top -= i.index;
        s[top] = internal(int(i.value))->f(s + top);
        ++top;
        break;
      }
      case Op::Pattern: top -= 2; s[top - 1] = i.pigment->value({s[top - 1], s[top], s[top + 1]}); break;
      case Op::Colour: top -= 2; s[top - 1] = component(i.pigment->at({s[top - 1], s[top], s[top + 1]}), i.index); break;
    }
  }
  return s[0];
}

}  // namespace rt
