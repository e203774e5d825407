// The built-in constants and functions of POV-Ray 3.7's float, vector and string function lists.
#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include <sys/stat.h>

#include <glm/glm.hpp>

#include "interpreter_state.hpp"
#include "raytrace/surface/noise.hpp"

namespace rt::povray {

namespace {

constexpr double kPi = 3.1415926535897932384626;


// A number as an int, clamped first: a double outside int's range (or NaN) has none.
int clampedInt(double v, int lo, int hi) { return std::isnan(v) ? 0 : int(std::clamp(v, double(lo), double(hi))); }

// printf's %f as str() and vstr() use it: a negative width pads with zeros, a negative precision means 6.
std::string format(double x, double width, double precision) {
  const int w = clampedInt(width, -200, 200), p = clampedInt(precision, -1, 200);
  char buffer[512];
  if (p < 0) {
    std::snprintf(buffer, sizeof buffer, w < 0 ? "%0*f" : "%*f", std::abs(w), x);
  } else {
    std::snprintf(buffer, sizeof buffer, w < 0 ? "%0*.*f" : "%*.*f", std::abs(w), p, x);
  }
  return buffer;
}

// The built-ins, in the order of their names (builtinIndex): a token carries its built-in's place, found
// once by the lexer, so a call neither compares names nor hashes one.
enum class B : std::uint8_t {
  none,
  abs_, acos_, acosh_, asc_, asin_, asinh_, atan_, atan2_, atanh_, bitwise_and_, bitwise_or_, bitwise_xor_, ceil_,
  chr_, clock_, clock_delta_, clock_on_, concat_, cos_, cosh_, datetime_, defined_, degrees_, dimension_size_,
  dimensions_, div_, exp_, false_, file_exists_, final_clock_, final_frame_, floor_, frame_number_, image_height_,
  image_width_, initial_clock_, initial_frame_, input_file_name_, inside_, int_, internal_, ln_, log_, max_,
  max_extent_, min_, min_extent_, mod_, no_, now_, off_, on_, pi_, pow_, prod_, radians_, rand_, seed_, select_,
  sin_, sinh_, sqrt_, str_, strcmp_, strlen_, strlwr_, strupr_, substr_, sum_, t_, tan_, tanh_, trace_, true_, u_,
  v_, val_, vaxis_rotate_, vcross_, vdot_, version_, vlength_, vnormalize_, vrotate_, vstr_, vturbulence_, x_, y_,
  yes_, z_,
};

Value vec3(const glm::dvec3& v) { return Value::vector({v.x, v.y, v.z, 0, 0}, 3); }

}  // namespace

Interpreter::Arguments::Arguments(Interpreter& interpreter) : in(interpreter) {
  if (!in.spareArguments_.empty()) {
    values = std::move(in.spareArguments_.back());
    in.spareArguments_.pop_back();
  }
  in.readArguments(values);
}

Interpreter::Arguments::~Arguments() {
  if (in.spareArguments_.size() == kSpareArguments) return;
  values.clear();
  in.spareArguments_.push_back(std::move(values));
}

void Interpreter::readArguments(std::vector<Value>& args) {
  expect("(", "before the arguments");
  if (peek().is(")")) {
    next();
    return;
  }
  for (;;) {
    args.push_back(expression());
    // The separator by reference, and its place only for the message: this runs for every argument.
    const Token& sep = peek();
    const bool close = sep.is(")");
    if (!close && !sep.is(",")) {
      SourceLoc sepAt;
      next(&sepAt);
      fail(sepAt, "expected ',' or ')' between arguments, found " + quote(sep.text));
    }
    next();
    if (close) return;
  }
}

Value Interpreter::builtin(std::string_view name, std::uint8_t index, const SourceLoc& at) {
  const B id = B(index);
  const Clock& c = options_.clock;
  // Constants, and the functions whose arguments are not plain expressions. A switch: a scene's loop calls
  // rand and the like millions of times, which a chain of comparisons would walk each time.
  switch (id) {
    case B::pi_: return Value::number(kPi);
    case B::true_: case B::yes_: case B::on_: return Value::number(1);
    case B::false_: case B::no_: case B::off_: return Value::number(0);
    case B::x_: return Value::vector({1, 0, 0, 0, 0}, 3);
    case B::y_: return Value::vector({0, 1, 0, 0, 0}, 3);
    case B::z_: return Value::vector({0, 0, 1, 0, 0}, 3);
    case B::t_: return Value::vector({0, 0, 0, 1, 0}, 4);
    case B::u_: return Value::vector({1, 0, 0, 0, 0}, 2);
    case B::v_: return Value::vector({0, 1, 0, 0, 0}, 2);
    case B::clock_: return Value::number(c.clock);
    case B::clock_delta_: return Value::number(c.delta);
    case B::clock_on_: return Value::number(c.on);
    case B::frame_number_: return Value::number(c.frame);
    case B::initial_clock_: return Value::number(c.initialClock);
    case B::final_clock_: return Value::number(c.finalClock);
    case B::initial_frame_: return Value::number(c.initialFrame);
    case B::final_frame_: return Value::number(c.finalFrame);
    case B::image_width_: return Value::number(options_.imageWidth);
    case B::image_height_: return Value::number(options_.imageHeight);
    case B::version_: return Value::number(version_);
    case B::input_file_name_: return Value::string(files_.front()->name.str());
    case B::now_: return Value::number((double(std::time(nullptr)) - 946684800.0) / 86400.0);
    case B::min_extent_: case B::max_extent_: {
      if (!options_.extent) fail(at, "'" + std::string(name) + "' is not supported yet");
      expect("(", "after the function's name");
      const SourceLoc oAt = here();
      const Value o = expression();
      expect(")", "after the object");
      if (o.type != Value::Type::Node) fail(oAt, "expected an object, found a " + std::string(typeName(o)));
      const auto box = options_.extent(std::static_pointer_cast<const Node>(o.ref));
      if (!box) fail(oAt, "'" + std::string(name) + "' of an object without bounds, such as a plane");
      const size_t k = id == B::min_extent_ ? 0 : 3;
      return Value::vector({(*box)[k], (*box)[k + 1], (*box)[k + 2], 0, 0}, 3);
    }
    // trace(Object, Start, Direction [, Normal]): the first point on the object, or <0,0,0>; Normal receives
    // the normal there, or <0,0,0>.
    case B::trace_: {
      if (!options_.trace) fail(at, "'" + std::string(name) + "' is not supported yet");
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
    // inside(Object, Point): 1 if the point is inside the object, else 0.
    case B::inside_: {
      if (!options_.inside) fail(at, "'" + std::string(name) + "' is not supported yet");
      expect("(", "after inside");
      const SourceLoc oAt = here();
      const Value o = expression();
      if (o.type != Value::Type::Node) fail(oAt, "expected an object, found a " + std::string(typeName(o)));
      expect(",", "before the point");
      const SourceLoc pAt = here();
      const Value p = expression();
      if (!p.numeric()) fail(pAt, "expected a vector, found a " + std::string(typeName(p)));
      expect(")", "after inside's arguments");
      const InterpreterOptions::Vec point = p.type == Value::Type::Float
                                                ? InterpreterOptions::Vec{p.v[0], p.v[0], p.v[0]}
                                                : InterpreterOptions::Vec{p.v[0], p.v[1], p.v[2]};
      return Value::number(options_.inside(std::static_pointer_cast<const Node>(o.ref), point) ? 1 : 0);
    }
    case B::sum_: case B::prod_: case B::internal_: case B::datetime_:
      fail(at, "'" + std::string(name) + "' is not supported yet");
    case B::defined_: {
      expect("(", "after defined");
      const std::string_view id = expectWord("an identifier");
      expect(")", "after the identifier");
      return Value::number(find(id) != nullptr);
    }
    case B::dimensions_: case B::dimension_size_: {
      expect("(", "after the function's name");
      const SourceLoc aAt = here();
      const Value a = expression();
      if (a.type != Value::Type::Array) fail(aAt, "expected an array, found a " + std::string(typeName(a)));
      const auto& arr = static_cast<const ArrayValue&>(*a.ref);
      if (id == B::dimensions_) {
        expect(")", "after the array");
        return Value::number(double(arr.dims.size()));
      }
      expect(",", "after the array");
      const double d = number("as the dimension");
      expect(")", "after the dimension");
      if (!(d >= 1 && d <= arr.dims.size())) fail(at, "the array has no dimension " + format(d, 0, 0));
      return Value::number(arr.dims[size_t(d) - 1]);
    }
    case B::seed_: {
      const Arguments args(*this);
      const std::vector<Value>& a = args.values;
      if (a.size() != 1 || a[0].type != Value::Type::Float) fail(at, "seed takes one float");
      randStates_.push_back(std::uint32_t(std::int64_t(a[0].v[0])));
      return Value::number(double(randStates_.size() - 1));
    }
    default:
      break;
  }

  const Arguments args(*this);
  const std::vector<Value>& a = args.values;
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
    return a[i].str();
  };
  auto vec = [&](size_t i) {
    if (!a[i].numeric()) fail(at, "argument " + std::to_string(i + 1) + " of " + std::string(name) + " must be a vector");
    if (a[i].type == Value::Type::Float) return glm::dvec3(a[i].v[0]);
    return glm::dvec3(a[i].v[0], a[i].size > 1 ? a[i].v[1] : 0, a[i].size > 2 ? a[i].v[2] : 0);
  };
  using Fn = double (*)(double);
  static const std::pair<B, Fn> kOneFloat[] = {
      {B::abs_, [](double x) { return std::abs(x); }},     {B::acos_, [](double x) { return std::acos(x); }},
      {B::acosh_, [](double x) { return std::acosh(x); }}, {B::asin_, [](double x) { return std::asin(x); }},
      {B::asinh_, [](double x) { return std::asinh(x); }}, {B::atan_, [](double x) { return std::atan(x); }},
      {B::atanh_, [](double x) { return std::atanh(x); }}, {B::ceil_, [](double x) { return std::ceil(x); }},
      {B::cos_, [](double x) { return std::cos(x); }},     {B::cosh_, [](double x) { return std::cosh(x); }},
      {B::degrees_, [](double x) { return x * 180 / kPi; }}, {B::exp_, [](double x) { return std::exp(x); }},
      {B::floor_, [](double x) { return std::floor(x); }}, {B::int_, [](double x) { return std::trunc(x); }},
      {B::ln_, [](double x) { return std::log(x); }},      {B::log_, [](double x) { return std::log10(x); }},
      {B::radians_, [](double x) { return x * kPi / 180; }}, {B::sin_, [](double x) { return std::sin(x); }},
      {B::sinh_, [](double x) { return std::sinh(x); }},   {B::sqrt_, [](double x) { return std::sqrt(x); }},
      {B::tan_, [](double x) { return std::tan(x); }},     {B::tanh_, [](double x) { return std::tanh(x); }},
  };
  switch (id) {
    case B::abs_: case B::acos_: case B::acosh_: case B::asin_: case B::asinh_: case B::atan_: case B::atanh_:
    case B::ceil_: case B::cos_: case B::cosh_: case B::degrees_: case B::exp_: case B::floor_: case B::int_:
    case B::ln_: case B::log_: case B::radians_: case B::sin_: case B::sinh_: case B::sqrt_: case B::tan_:
    case B::tanh_:
      for (const auto& [n, fn] : kOneFloat) {
        if (n == id) {
          count(1, 1);
          return Value::number(fn(f(0)));
        }
      }
      break;
    case B::atan2_: case B::pow_: case B::mod_: case B::div_: {
      count(2, 2);
      const double p = f(0), q = f(1);
      if (id == B::atan2_) return Value::number(std::atan2(p, q));
      if (id == B::pow_) return Value::number(std::pow(p, q));
      if (id == B::mod_) return Value::number(std::fmod(p, q));
      return Value::number(std::trunc(p / q));
    }
    case B::min_: case B::max_: {
      count(1, 1000);
      double r = f(0);
      for (size_t i = 1; i < a.size(); ++i) r = id == B::min_ ? std::min(r, f(i)) : std::max(r, f(i));
      return Value::number(r);
    }
    case B::bitwise_and_: case B::bitwise_or_: case B::bitwise_xor_: {
      count(1, 1000);
      long r = long(f(0));
      for (size_t i = 1; i < a.size(); ++i) {
        const long b = long(f(i));
        r = id == B::bitwise_and_ ? (r & b) : id == B::bitwise_or_ ? (r | b) : (r ^ b);
      }
      return Value::number(double(r));
    }
    case B::select_: {
      count(3, 4);
      const double c = f(0);
      if (a.size() == 3) return c < 0 ? a[1] : a[2];
      return c < 0 ? a[1] : c == 0 ? a[2] : a[3];
    }
    case B::rand_: {
      count(1, 1);
      const double i = f(0);
      if (!(i >= 0 && i < double(randStates_.size()))) fail(at, "rand needs a stream made by seed()");
      // POV-Ray's generator: a 32-bit linear congruence, scaled to [0, 1].
      std::uint32_t& state = randStates_[size_t(i)];
      state = state * 1812433253u + 12345u;
      return Value::number(double(state) / 4294967295.0);
    }
    // vturbulence(Lambda, Omega, Octaves, Point): turbulence's displacement at the point, the same octaves a
    // pattern's turbulence 1 adds (POV-Ray prints the same nine decimals).
    case B::vturbulence_: {
      count(4, 4);
      Turbulence t;
      t.amount = glm::dvec3(1);
      t.lambda = float(f(0));
      t.omega = float(f(1));
      t.octaves = int(std::clamp(f(2), 1.0, 10.0));
      return vec3(turbulentOffset(vec(3), t));
    }
    case B::vlength_: case B::vnormalize_: {
      count(1, 1);
      const glm::dvec3 v = vec(0);
      if (id == B::vlength_) return Value::number(glm::length(v));
      const double l = glm::length(v);
      return vec3(l > 0 ? v / l : glm::dvec3(0));
    }
    case B::vdot_: case B::vcross_: {
      count(2, 2);
      if (id == B::vdot_) return Value::number(glm::dot(vec(0), vec(1)));
      return vec3(glm::cross(vec(0), vec(1)));
    }
    case B::vrotate_: {
      count(2, 2);
      glm::dvec3 p = vec(0);
      const glm::dvec3 r = glm::radians(vec(1));
      p = glm::dvec3(p.x, p.y * std::cos(r.x) - p.z * std::sin(r.x), p.y * std::sin(r.x) + p.z * std::cos(r.x));
      p = glm::dvec3(p.x * std::cos(r.y) + p.z * std::sin(r.y), p.y, -p.x * std::sin(r.y) + p.z * std::cos(r.y));
      p = glm::dvec3(p.x * std::cos(r.z) - p.y * std::sin(r.z), p.x * std::sin(r.z) + p.y * std::cos(r.z), p.z);
      return vec3(p);
    }
    case B::vaxis_rotate_: {
      count(3, 3);
      const glm::dvec3 p = vec(0), k = glm::normalize(vec(1));
      const double th = f(2) * kPi / 180, c = std::cos(th), sn = std::sin(th);
      return vec3(p * c + glm::cross(k, p) * sn + k * glm::dot(k, p) * (1 - c));
    }
    case B::str_: {
      count(3, 3);
      return Value::string(format(f(0), f(1), f(2)));
    }
    case B::vstr_: {
      count(5, 5);
      if (!a[1].numeric()) fail(at, "argument 2 of vstr must be a vector");
      const int n = clampedInt(f(0), 1, 5);
      std::string r;
      for (int i = 0; i < n; ++i) {
        if (i) r += s(2);
        const double c = a[1].type == Value::Type::Float ? a[1].v[0] : i < a[1].size ? a[1].v[size_t(i)] : 0;
        r += format(c, f(3), f(4));
      }
      return Value::string(r);
    }
    case B::concat_: {
      count(1, 1000);
      std::string r;
      for (size_t i = 0; i < a.size(); ++i) r += s(i);
      return Value::string(r);
    }
    case B::chr_: {
      count(1, 1);
      return Value::string(std::string(1, char(clampedInt(f(0), INT_MIN, INT_MAX))));
    }
    case B::asc_: {
      count(1, 1);
      return Value::number(s(0).empty() ? 0 : double(static_cast<unsigned char>(s(0)[0])));
    }
    case B::strlen_: {
      count(1, 1);
      return Value::number(double(s(0).size()));
    }
    case B::val_: {
      count(1, 1);
      return Value::number(std::atof(s(0).c_str()));
    }
    case B::strcmp_: {
      count(2, 2);
      return Value::number(std::strcmp(s(0).c_str(), s(1).c_str()));
    }
    case B::strupr_: case B::strlwr_: {
      count(1, 1);
      std::string r = s(0);
      for (char& c : r) c = char(id == B::strupr_ ? std::toupper(static_cast<unsigned char>(c)) : std::tolower(static_cast<unsigned char>(c)));
      return Value::string(r);
    }
    case B::substr_: {
      count(3, 3);
      const std::string& text = s(0);
      const double p = f(1), l = f(2);
      if (!(p >= 1 && l >= 0 && p - 1 + l <= double(text.size()))) fail(at, "substr reaches outside its string");
      return Value::string(text.substr(size_t(p) - 1, size_t(l)));
    }
    case B::file_exists_: {
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
    default:
      break;
  }
  fail(at, "'" + std::string(name) + "' is not supported yet");
}

}  // namespace rt::povray
