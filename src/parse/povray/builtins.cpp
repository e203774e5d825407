// The built-in constants and functions of POV-Ray 3.7's float, vector and string function lists.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include <sys/stat.h>

#include <glm/glm.hpp>

#include "interpreter_state.hpp"

namespace rt::povray {

namespace {

constexpr double kPi = 3.1415926535897932384626;


// printf's %f as str() and vstr() use it: a negative width pads with zeros, a negative precision means 6.
std::string format(double x, double width, double precision) {
  const int w = int(width), p = int(precision);
  char buffer[512];
  if (p < 0) {
    std::snprintf(buffer, sizeof buffer, w < 0 ? "%0*f" : "%*f", std::min(std::abs(w), 200), x);
  } else {
    std::snprintf(buffer, sizeof buffer, w < 0 ? "%0*.*f" : "%*.*f", std::min(std::abs(w), 200), std::min(p, 200), x);
  }
  return buffer;
}

Value vec3(const glm::dvec3& v) { return Value::vector({v.x, v.y, v.z, 0, 0}, 3); }

}  // namespace

std::vector<Value> Interpreter::arguments(const SourceLoc& at) {
  (void)at;
  expect("(", "before the arguments");
  std::vector<Value> args;
  if (peek().is(")")) {
    next();
    return args;
  }
  for (;;) {
    args.push_back(expression());
    SourceLoc sepAt;
    const Token sep = next(&sepAt);
    if (sep.is(")")) return args;
    if (!sep.is(",")) fail(sepAt, "expected ',' or ')' between arguments, found " + quote(sep.text));
  }
}

Value Interpreter::builtin(std::string_view name, const SourceLoc& at) {
  // Constants.
  if (name == "pi") return Value::number(kPi);
  if (name == "true" || name == "yes" || name == "on") return Value::number(1);
  if (name == "false" || name == "no" || name == "off") return Value::number(0);
  if (name == "x") return Value::vector({1, 0, 0, 0, 0}, 3);
  if (name == "y") return Value::vector({0, 1, 0, 0, 0}, 3);
  if (name == "z") return Value::vector({0, 0, 1, 0, 0}, 3);
  if (name == "t") return Value::vector({0, 0, 0, 1, 0}, 4);
  if (name == "u") return Value::vector({1, 0, 0, 0, 0}, 2);
  if (name == "v") return Value::vector({0, 1, 0, 0, 0}, 2);
  const Clock& c = options_.clock;
  if (name == "clock") return Value::number(c.clock);
  if (name == "clock_delta") return Value::number(c.delta);
  if (name == "clock_on") return Value::number(c.on);
  if (name == "frame_number") return Value::number(c.frame);
  if (name == "initial_clock") return Value::number(c.initialClock);
  if (name == "final_clock") return Value::number(c.finalClock);
  if (name == "initial_frame") return Value::number(c.initialFrame);
  if (name == "final_frame") return Value::number(c.finalFrame);
  if (name == "image_width") return Value::number(options_.imageWidth);
  if (name == "image_height") return Value::number(options_.imageHeight);
  if (name == "version") return Value::number(version_);
  if (name == "input_file_name") return Value::string(files_.front()->name.str());
  if (name == "now") return Value::number((double(std::time(nullptr)) - 946684800.0) / 86400.0);
  if ((name == "min_extent" || name == "max_extent") && options_.extent) {
    expect("(", "after the function's name");
    const SourceLoc oAt = here();
    const Value o = expression();
    expect(")", "after the object");
    if (o.type != Value::Type::Node) fail(oAt, "expected an object, found a " + std::string(typeName(o)));
    const auto box = options_.extent(std::static_pointer_cast<const Node>(o.ref));
    if (!box) fail(oAt, "'" + std::string(name) + "' of an object without bounds, such as a plane");
    const size_t k = name == "min_extent" ? 0 : 3;
    return Value::vector({(*box)[k], (*box)[k + 1], (*box)[k + 2], 0, 0}, 3);
  }
  // trace(Object, Start, Direction [, Normal]): the first point on the object, or <0,0,0>; Normal receives
  // the normal there, or <0,0,0>.
  if (name == "trace" && options_.trace) {
    expect("(", "after trace");
    const SourceLoc oAt = here();
    const Value o = expression();
    if (o.type != Value::Type::Node) fail(oAt, "expected an object, found a " + std::string(typeName(o)));
    const auto vec = [this](const char* what) {
      expect(",", what);
      const SourceLoc vAt = here();
      const Value v = expression();
      if (!v.numeric()) fail(vAt, "expected a vector, found a " + std::string(typeName(v)));
      return v.type == Value::Type::Float ? InterpreterOptions::Vec{v.v[0], v.v[0], v.v[0]}
                                          : InterpreterOptions::Vec{v.v[0], v.v[1], v.v[2]};
    };
    const InterpreterOptions::Vec start = vec("before trace's start"), dir = vec("before trace's direction");
    const auto hit = options_.trace(std::static_pointer_cast<const Node>(o.ref), start, dir);
    const auto vector = [](const InterpreterOptions::Vec& v) { return Value::vector({v[0], v[1], v[2], 0, 0}, 3); };
    if (peekOperator(",")) {
      next();
      SourceLoc nAt;
      const std::string_view normal = expectWord("an identifier for the normal", &nAt);
      if (isKeyword(normal)) fail(nAt, "'" + std::string(normal) + "' is a keyword and cannot be declared");
      Value n = hit ? vector((*hit)[1]) : vector({0, 0, 0});
      if (Slot* slot = find(normal)) {
        slot->value = std::move(n);
      } else {
        assign(normal, std::move(n), scopes_.size() - 1);
      }
    }
    expect(")", "after trace's arguments");
    return hit ? vector((*hit)[0]) : vector({0, 0, 0});
  }
  if (name == "inside" || name == "trace" || name == "vturbulence" || name == "min_extent" || name == "max_extent" ||
      name == "sum" || name == "prod" || name == "internal" || name == "datetime") {
    fail(at, "'" + std::string(name) + "' is not supported yet");
  }

  // Functions whose arguments are not plain expressions.
  if (name == "defined") {
    expect("(", "after defined");
    const std::string_view id = expectWord("an identifier");
    expect(")", "after the identifier");
    return Value::number(find(id) != nullptr);
  }
  if (name == "dimensions" || name == "dimension_size") {
    expect("(", "after the function's name");
    const SourceLoc aAt = here();
    const Value a = expression();
    if (a.type != Value::Type::Array) fail(aAt, "expected an array, found a " + std::string(typeName(a)));
    const auto& arr = static_cast<const ArrayValue&>(*a.ref);
    if (name == "dimensions") {
      expect(")", "after the array");
      return Value::number(double(arr.dims.size()));
    }
    expect(",", "after the array");
    const double d = number("as the dimension");
    expect(")", "after the dimension");
    if (!(d >= 1 && d <= arr.dims.size())) fail(at, "the array has no dimension " + format(d, 0, 0));
    return Value::number(arr.dims[size_t(d) - 1]);
  }
  if (name == "seed") {
    const std::vector<Value> a = arguments(at);
    if (a.size() != 1 || a[0].type != Value::Type::Float) fail(at, "seed takes one float");
    randStates_.push_back(std::uint32_t(std::int64_t(a[0].v[0])));
    return Value::number(double(randStates_.size() - 1));
  }

  const std::vector<Value> a = arguments(at);
  auto count = [&](size_t low, size_t high) {
    if (a.size() < low || a.size() > high) {
      fail(at, std::string(name) + " takes " +
                   (low == high ? std::to_string(low) : std::to_string(low) + " to " + std::to_string(high)) +
                   " arguments, found " + std::to_string(a.size()));
    }
  };
  auto f = [&](size_t i) {
    if (a[i].type != Value::Type::Float) {
      fail(at, "argument " + std::to_string(i + 1) + " of " + std::string(name) + " must be a float, found a " +
                   typeName(a[i]));
    }
    return a[i].v[0];
  };
  auto s = [&](size_t i) -> const std::string& {
    if (a[i].type != Value::Type::String) {
      fail(at, "argument " + std::to_string(i + 1) + " of " + std::string(name) + " must be a string, found a " +
                   typeName(a[i]));
    }
    return a[i].s;
  };
  auto vec = [&](size_t i) {
    if (!a[i].numeric()) fail(at, "argument " + std::to_string(i + 1) + " of " + std::string(name) + " must be a vector");
    if (a[i].type == Value::Type::Float) return glm::dvec3(a[i].v[0]);
    return glm::dvec3(a[i].v[0], a[i].size > 1 ? a[i].v[1] : 0, a[i].size > 2 ? a[i].v[2] : 0);
  };
  using Fn = double (*)(double);
  static const std::pair<std::string_view, Fn> kOneFloat[] = {
      {"abs", [](double x) { return std::abs(x); }},     {"acos", [](double x) { return std::acos(x); }},
      {"acosh", [](double x) { return std::acosh(x); }}, {"asin", [](double x) { return std::asin(x); }},
      {"asinh", [](double x) { return std::asinh(x); }}, {"atan", [](double x) { return std::atan(x); }},
      {"atanh", [](double x) { return std::atanh(x); }}, {"ceil", [](double x) { return std::ceil(x); }},
      {"cos", [](double x) { return std::cos(x); }},     {"cosh", [](double x) { return std::cosh(x); }},
      {"degrees", [](double x) { return x * 180 / kPi; }}, {"exp", [](double x) { return std::exp(x); }},
      {"floor", [](double x) { return std::floor(x); }}, {"int", [](double x) { return std::trunc(x); }},
      {"ln", [](double x) { return std::log(x); }},      {"log", [](double x) { return std::log10(x); }},
      {"radians", [](double x) { return x * kPi / 180; }}, {"sin", [](double x) { return std::sin(x); }},
      {"sinh", [](double x) { return std::sinh(x); }},   {"sqrt", [](double x) { return std::sqrt(x); }},
      {"tan", [](double x) { return std::tan(x); }},     {"tanh", [](double x) { return std::tanh(x); }},
  };
  for (const auto& [n, fn] : kOneFloat) {
    if (n == name) {
      count(1, 1);
      return Value::number(fn(f(0)));
    }
  }
  if (name == "atan2" || name == "pow" || name == "mod" || name == "div") {
    count(2, 2);
    const double p = f(0), q = f(1);
    if (name == "atan2") return Value::number(std::atan2(p, q));
    if (name == "pow") return Value::number(std::pow(p, q));
    if (name == "mod") return Value::number(std::fmod(p, q));
    return Value::number(std::trunc(p / q));
  }
  if (name == "min" || name == "max") {
    count(1, 1000);
    double r = f(0);
    for (size_t i = 1; i < a.size(); ++i) r = name == "min" ? std::min(r, f(i)) : std::max(r, f(i));
    return Value::number(r);
  }
  if (name == "bitwise_and" || name == "bitwise_or" || name == "bitwise_xor") {
    count(1, 1000);
    long r = long(f(0));
    for (size_t i = 1; i < a.size(); ++i) {
      const long b = long(f(i));
      r = name == "bitwise_and" ? (r & b) : name == "bitwise_or" ? (r | b) : (r ^ b);
    }
    return Value::number(double(r));
  }
  if (name == "select") {
    count(3, 4);
    const double c = f(0);
    if (a.size() == 3) return c < 0 ? a[1] : a[2];
    return c < 0 ? a[1] : c == 0 ? a[2] : a[3];
  }
  if (name == "rand") {
    count(1, 1);
    const double i = f(0);
    if (!(i >= 0 && i < double(randStates_.size()))) fail(at, "rand needs a stream made by seed()");
    // POV-Ray's generator: a 32-bit linear congruence, scaled to [0, 1].
    std::uint32_t& state = randStates_[size_t(i)];
    state = state * 1812433253u + 12345u;
    return Value::number(double(state) / 4294967295.0);
  }
  if (name == "vlength" || name == "vnormalize") {
    count(1, 1);
    const glm::dvec3 v = vec(0);
    if (name == "vlength") return Value::number(glm::length(v));
    const double l = glm::length(v);
    return vec3(l > 0 ? v / l : glm::dvec3(0));
  }
  if (name == "vdot" || name == "vcross") {
    count(2, 2);
    if (name == "vdot") return Value::number(glm::dot(vec(0), vec(1)));
    return vec3(glm::cross(vec(0), vec(1)));
  }
  if (name == "vrotate") {
    count(2, 2);
    glm::dvec3 p = vec(0);
    const glm::dvec3 r = glm::radians(vec(1));
    p = glm::dvec3(p.x, p.y * std::cos(r.x) - p.z * std::sin(r.x), p.y * std::sin(r.x) + p.z * std::cos(r.x));
    p = glm::dvec3(p.x * std::cos(r.y) + p.z * std::sin(r.y), p.y, -p.x * std::sin(r.y) + p.z * std::cos(r.y));
    p = glm::dvec3(p.x * std::cos(r.z) - p.y * std::sin(r.z), p.x * std::sin(r.z) + p.y * std::cos(r.z), p.z);
    return vec3(p);
  }
  if (name == "vaxis_rotate") {
    count(3, 3);
    const glm::dvec3 p = vec(0), k = glm::normalize(vec(1));
    const double th = f(2) * kPi / 180, c = std::cos(th), sn = std::sin(th);
    return vec3(p * c + glm::cross(k, p) * sn + k * glm::dot(k, p) * (1 - c));
  }
  if (name == "str") {
    count(3, 3);
    return Value::string(format(f(0), f(1), f(2)));
  }
  if (name == "vstr") {
    count(5, 5);
    if (!a[1].numeric()) fail(at, "argument 2 of vstr must be a vector");
    const int n = std::clamp(int(f(0)), 1, 5);
    std::string r;
    for (int i = 0; i < n; ++i) {
      if (i) r += s(2);
      const double c = a[1].type == Value::Type::Float ? a[1].v[0] : i < a[1].size ? a[1].v[size_t(i)] : 0;
      r += format(c, f(3), f(4));
    }
    return Value::string(r);
  }
  if (name == "concat") {
    count(1, 1000);
    std::string r;
    for (size_t i = 0; i < a.size(); ++i) r += s(i);
    return Value::string(r);
  }
  if (name == "chr") {
    count(1, 1);
    return Value::string(std::string(1, char(int(f(0)))));
  }
  if (name == "asc") {
    count(1, 1);
    return Value::number(s(0).empty() ? 0 : double(static_cast<unsigned char>(s(0)[0])));
  }
  if (name == "strlen") {
    count(1, 1);
    return Value::number(double(s(0).size()));
  }
  if (name == "val") {
    count(1, 1);
    return Value::number(std::atof(s(0).c_str()));
  }
  if (name == "strcmp") {
    count(2, 2);
    return Value::number(std::strcmp(s(0).c_str(), s(1).c_str()));
  }
  if (name == "strupr" || name == "strlwr") {
    count(1, 1);
    std::string r = s(0);
    for (char& c : r) c = char(name == "strupr" ? std::toupper(static_cast<unsigned char>(c)) : std::tolower(static_cast<unsigned char>(c)));
    return Value::string(r);
  }
  if (name == "substr") {
    count(3, 3);
    const std::string& text = s(0);
    const double p = f(1), l = f(2);
    if (!(p >= 1 && l >= 0 && p - 1 + l <= double(text.size()))) fail(at, "substr reaches outside its string");
    return Value::string(text.substr(size_t(p) - 1, size_t(l)));
  }
  if (name == "file_exists") {
    count(1, 1);
    struct stat st;
    const std::string& file = s(0);
    std::vector<std::string> paths{!file.empty() && file[0] == '/' ? file : sceneFolder_ + file};
    for (const std::string& l : options_.libraryPaths) paths.push_back(l + "/" + file);
    paths.push_back(options_.standardLibrary + "/" + file);
    for (const std::string& p : paths) {
      if (stat(p.c_str(), &st) == 0) return Value::number(1);
    }
    return Value::number(0);
  }
  fail(at, "'" + std::string(name) + "' is not supported yet");
}

}  // namespace rt::povray
