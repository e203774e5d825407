// Expressions with POV-Ray's precedence: outside parentheses only arithmetic (+ - * / and unary + - !), since
// `<` and `>` also delimit vectors; inside parentheses also relations, & and |, and ?:.
#include <algorithm>
#include <cmath>

#include "interpreter_state.hpp"
#include "raytrace/parse/povray/spline.hpp"

namespace rt::povray {

namespace {

constexpr double kEpsilon = 1e-10;

// sRGB-encoded to linear, for srgb, srgbf …
double fromSrgb(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// Whether the token after a number or an identifier may make it part of a larger operand (sum's shortcut).
bool continuesOperand(const Token& after) {
  if (after.kind == Token::Kind::End || after.kind == Token::Kind::Directive) return true;
  if (after.kind != Token::Kind::Symbol) return false;
  switch (after.text[0]) {
    case '+': case '-': case '*': case '/': case '.': case '(': case '[':
      return true;
    default:
      return false;
  }
}

}  // namespace

int componentIndex(std::string_view c) {
  if (c == "x" || c == "u" || c == "red") return 0;
  if (c == "y" || c == "v" || c == "green") return 1;
  if (c == "z" || c == "blue") return 2;
  if (c == "t" || c == "filter") return 3;
  return c == "transmit" ? 4 : -1;
}

const char* typeName(const Value& v) {
  switch (v.type) {
    case Value::Type::None: return "nothing";
    case Value::Type::Float: return "float";
    case Value::Type::Vector: return "vector";
    case Value::Type::Colour: return "colour";
    case Value::Type::String: return "string";
    case Value::Type::Array: return "array";
    case Value::Type::Node: return "scene item";
    case Value::Type::Function: return "function";
    case Value::Type::Macro: return "macro";
    case Value::Type::File: return "file";
  }
  return "value";
}

double Interpreter::number(const char* what) {
  const SourceLoc at = here();
  const Value v = expression();
  if (v.type != Value::Type::Float) fail(at, std::string("expected a float ") + what + ", found a " + typeName(v));
  return v.v[0];
}

double Interpreter::truth(const Value& v, const SourceLoc& at) {
  if (v.type != Value::Type::Float) fail(at, std::string("expected a float condition, found a ") + typeName(v));
  return std::abs(v.v[0]) > kEpsilon ? 1 : 0;
}

Value Interpreter::fullExpression() {
  const SourceLoc at = here();
  Value c = logical();
  if (!peekOperator("?")) return c;
  next();
  const bool t = truth(c, at) != 0;
  Value a = fullExpression();
  expect(":", "in the ?: expression");
  Value b = fullExpression();
  return t ? a : b;
}

Value Interpreter::logical() {
  const SourceLoc at = here();
  Value a = relation();
  while (peekOperator("&") || peekOperator("|")) {
    const bool isAnd = next().is("&");
    const SourceLoc bAt = here();
    const Value b = relation();
    const bool ta = truth(a, at) != 0, tb = truth(b, bAt) != 0;
    a = Value::number(isAnd ? (ta && tb) : (ta || tb));
  }
  return a;
}

Value Interpreter::relation() {
  SourceLoc at = here();
  Value a = sum();
  for (;;) {
    const char first = peekSymbol();
    if (first != '<' && first != '=' && first != '!' && first != '>') return a;
    const std::string_view op = rawPeek().text;
    if (op == "!") return a;
    next();
    const SourceLoc bAt = here();
    const Value b = sum();
    if (a.type == Value::Type::String && b.type == Value::Type::String) {
      const int d = a.str().compare(b.str());
      a = Value::number(op == "<" ? d < 0 : op == "<=" ? d <= 0 : op == "=" ? d == 0 : op == "!=" ? d != 0 : op == ">=" ? d >= 0 : d > 0);
      continue;
    }
    if (a.type != Value::Type::Float) fail(at, std::string("a comparison needs floats, found a ") + typeName(a));
    if (b.type != Value::Type::Float) fail(bAt, std::string("a comparison needs floats, found a ") + typeName(b));
    const double x = a.v[0], y = b.v[0];
    bool r = false;
    if (op == "<") r = x < y;
    else if (op == "<=") r = x <= y;
    else if (op == "=") r = std::abs(x - y) < kEpsilon;
    else if (op == "!=") r = std::abs(x - y) >= kEpsilon;
    else if (op == ">=") r = x >= y;
    else r = x > y;
    a = Value::number(r);
  }
}

Value Interpreter::sum() {
  // A lone number or identifier, most of a scene's operands: when the token after it can continue no operand
  // (no operator, '.', '(' or '[', and neither a directive nor the frame's end, which may run on elsewhere), the
  // precedence levels below would each read it and return it unchanged.
  const Token& t = peek();
  if (t.kind == Token::Kind::Number || (t.kind == Token::Kind::Word && !t.keyword)) {
    const Frame& f = frames_.back();
    const Token& after = f.file->tokens[f.pos + 1];
    if (!continuesOperand(after)) return t.kind == Token::Kind::Number ? Value::number(next().number) : identifierValue(t, locOf(t));
  }
  Value a = product();
  for (;;) {
    const char op = peekSymbol();
    if (op != '+' && op != '-') return a;
    SourceLoc at;
    next(&at);
    a = binary(op, std::move(a), product(), at);
  }
}

inline Value Interpreter::product() {
  Value a = unary();
  for (;;) {
    const char op = peekSymbol();
    if (op != '*' && op != '/') return a;
    SourceLoc at;
    next(&at);
    a = binary(op, std::move(a), unary(), at);
  }
}

Value Interpreter::unary() {
  const Token& t = peek();
  if (t.is("-") || t.is("+") || t.is("!")) {
    SourceLoc at;
    const char op = next(&at).text[0];
    const Nested nested(*this, at);
    Value v = unary();
    if (!v.numeric()) fail(at, std::string("'") + op + "' needs a number, found a " + typeName(v));
    if (op == '-') {
      for (double& c : v.v) c = -c;
    } else if (op == '!') {
      v = Value::number(truth(v, at) == 0);
    }
    return v;
  }
  return postfix();
}

inline Value Interpreter::postfix() {
  Value v = primary();
  while (peekSymbol() == '.') {
    SourceLoc at;
    next(&at);
    const std::string_view c = expectWord("a component after '.'");
    if (!v.numeric()) fail(at, std::string("a ") + typeName(v) + " has no components");
    const int i = componentIndex(c);
    if (c == "gray" || c == "grey") {
      v = Value::number(v.v[0] * 0.297 + v.v[1] * 0.589 + v.v[2] * 0.114);
      continue;
    }
    if (i < 0) fail(at, "unknown component '." + std::string(c) + "'");
    if (v.type == Value::Type::Float) {
      v = Value::number(v.v[0]);
    } else {
      if (v.type == Value::Type::Vector && i >= v.size) fail(at, "this vector has no component '." + std::string(c) + "'");
      v = Value::number(v.v[size_t(i)]);
    }
  }
  return v;
}

Value Interpreter::binary(char op, Value a, Value b, const SourceLoc& at) {
  if (!a.numeric() || !b.numeric()) {
    fail(at, std::string("'") + op + "' needs numbers, found a " + typeName(a.numeric() ? b : a));
  }
  if (a.size > 5 || b.size > 5) fail(at, "a list of more than 5 numbers is no vector to compute with");
  if (a.type == Value::Type::Float && b.type == Value::Type::Float) {
    const double x = a.v[0], y = b.v[0];
    return Value::number(op == '+' ? x + y : op == '-' ? x - y : op == '*' ? x * y : x / y);
  }
  // A float stands for every component; a shorter vector is padded with zeros.
  const bool colour = a.type == Value::Type::Colour || b.type == Value::Type::Colour;
  const int n = colour ? 5 : std::max(a.type == Value::Type::Float ? 0 : a.size, b.type == Value::Type::Float ? 0 : b.size);
  auto widen = [n](const Value& x) {
    std::array<double, 5> c{};
    for (int i = 0; i < n; ++i) c[size_t(i)] = x.type == Value::Type::Float ? x.v[0] : i < x.size ? x.v[size_t(i)] : 0;
    return c;
  };
  const std::array<double, 5> x = widen(a), y = widen(b);
  std::array<double, 5> r{};
  for (size_t i = 0; i < size_t(n); ++i) {
    r[i] = op == '+' ? x[i] + y[i] : op == '-' ? x[i] - y[i] : op == '*' ? x[i] * y[i] : x[i] / y[i];
  }
  return colour ? Value::colour(r) : Value::vector(r, n);
}

Value Interpreter::primary() {
  SourceLoc at;
  const Token& t = peek();
  at = locOf(t);
  switch (t.kind) {
    case Token::Kind::Number:
      return Value::number(next().number);
    case Token::Kind::String:
      return Value::string(std::string(next().text));
    case Token::Kind::Symbol:
      if (t.is("(")) {
        const Nested nested(*this, at);
        next();
        Value v = fullExpression();
        expect(")", "to close the parenthesis");
        return v;
      }
      if (t.is("<")) return vectorLiteral(at);
      fail(at, "expected a value, found " + quote(t.text));
    case Token::Kind::End:
      fail(at, "expected a value, found the end of the file");
    case Token::Kind::Directive:
      break;
    case Token::Kind::Word:
      // In a function's body x, y and z are its parameters.
      if (!t.keyword || (frames_.back().kind == Frame::Kind::Tokens && find(t.text))) {
        return identifierValue(t, at);
      }
      break;
  }
  const std::string_view w = t.text;
  if (t.startsValue && !t.colourWord) {
    next();
    return builtin(w, t.builtin, at);
  }
  if (t.colourWord || w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit") {
    return colour(at);
  }
  if (frames_.back().kind == Frame::Kind::Tokens) fail(at, "'" + std::string(w) + "' in a function is not supported yet");
  fail(at, "expected a value, found '" + std::string(w) + "'");
}

Value Interpreter::vectorLiteral(const SourceLoc& at) {
  const Nested nested(*this, at);
  next();
  std::array<double, 5> c{};
  int n = 0;
  for (;;) {
    // A lone number, as sum() would read it, without making a Value.
    const Token& t = peek();
    const Frame& f = frames_.back();
    double x = 0;
    if (t.kind == Token::Kind::Number && !continuesOperand(f.file->tokens[f.pos + 1])) {
      x = next().number;
    } else {
      const SourceLoc cAt = locOf(t);
      const Value v = expression();
      if (v.type != Value::Type::Float) fail(cAt, std::string("a vector's component must be a float, found a ") + typeName(v));
      x = v.v[0];
    }
    // Longer lists (a matrix, a polynomial's coefficients) keep their first five: only blocks take them.
    if (n < 5) c[size_t(n)] = x;
    ++n;
    if (peekOperator(",")) next();  // the commas may be left out, and one may end the list
    if (peekOperator(">")) break;
  }
  expect(">", "to close the vector");
  if (n < 2) fail(at, "a vector needs at least 2 components");
  return Value::vector(c, n);
}

// `<c1, c2, …>` of any length, a CoefficientList: a polynomial's coefficients, where a block reads them.
Value Interpreter::coefficientList(const SourceLoc& at) {
  const Nested nested(*this, at);
  next();
  auto list = std::make_shared<CoefficientList>();
  for (;;) {
    const SourceLoc cAt = here();
    const Value v = expression();
    if (v.type != Value::Type::Float) fail(cAt, std::string("a coefficient must be a float, found a ") + typeName(v));
    list->values.push_back(v.v[0]);
    if (peekOperator(",")) next();
    if (peekOperator(">")) break;
  }
  expect(">", "to close the coefficients");
  std::array<double, 5> first{};
  std::copy_n(list->values.begin(), std::min<size_t>(5, list->values.size()), first.begin());
  Value r = Value::vector(first, int(list->values.size()));
  r.ref = std::move(list);
  return r;
}

// `color`/`colour`, then any of rgb/rgbf/rgbt/rgbft (and srgb…), red/green/blue/filter/transmit, or a
// colour or vector expression, in sequence. A second rgb… starts the next colour (`checker rgb A rgb B` is two).
Value Interpreter::colour(const SourceLoc& at) {
  std::array<double, 5> c{};
  bool any = false;
  if (peek().isWord("color") || peek().isWord("colour")) next();
  for (;;) {
    const Token& t = peek();
    const std::string_view w = t.kind == Token::Kind::Word ? t.text : std::string_view();
    const bool srgb = w.substr(0, 4) == "srgb";
    const std::string_view kind = srgb ? w.substr(1) : w;
    if (kind == "rgb" || kind == "rgbf" || kind == "rgbt" || kind == "rgbft") {
      if (any) break;
      next();
      const SourceLoc vAt = here();
      const Value v = expression();
      if (!v.numeric()) fail(vAt, "expected a colour value, found a " + std::string(typeName(v)));
      // The components the value fills: red, green, blue, then filter and/or transmit.
      std::array<size_t, 5> slots{0, 1, 2, 3, 4};
      size_t count = 3;
      if (kind == "rgbf") count = 4;
      if (kind == "rgbt") slots[count++] = 4;
      if (kind == "rgbft") count = 5;
      for (size_t k = 0; k < count; ++k) {
        const double x = v.type == Value::Type::Float ? v.v[0] : (int(k) < v.size ? v.v[k] : 0);
        c[slots[k]] = srgb && k < 3 ? fromSrgb(x) : x;
      }
      if (kind == "rgbt" && v.type == Value::Type::Colour) c[4] = v.v[4];
      any = true;
    } else if (w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit") {
      next();
      const size_t i = w == "red" ? 0 : w == "green" ? 1 : w == "blue" ? 2 : w == "filter" ? 3 : 4;
      c[i] = number("as a colour component");
      any = true;
    } else if (!any) {
      const SourceLoc vAt = here();
      const Value v = expression();
      if (v.type == Value::Type::Float) {
        c.fill(v.v[0]);
      } else if (v.type == Value::Type::Vector || v.type == Value::Type::Colour) {
        for (int i = 0; i < std::min(v.size, 5); ++i) c[size_t(i)] = v.v[size_t(i)];
      } else {
        fail(vAt, "expected a colour, found a " + std::string(typeName(v)));
      }
      any = true;
    } else {
      break;
    }
  }
  (void)at;
  return Value::colour(c);
}

Value Interpreter::identifierValue(const Token& t, const SourceLoc& at) {
  Slot* slot = find(t.text);
  if (!slot) fail(at, "undeclared identifier '" + std::string(t.text) + "'");
  const std::string_view name = t.text;
  // A copy: reading what follows may end the identifier's scope (a macro's #end after its returned value).
  Value held = slot->value;
  next();
  // A number, vector or colour is the value itself: nothing after it can index or call it.
  if (held.type == Value::Type::Float || held.type == Value::Type::Vector || held.type == Value::Type::Colour) return held;
  const Value* v = &held;
  while (v->type == Value::Type::Array && peekOperator("[")) {
    const auto& a = static_cast<const ArrayValue&>(*v->ref);
    size_t flat = 0;
    for (size_t k = 0; k < a.dims.size(); ++k) {
      expect("[", "for the array's next index");
      const SourceLoc iAt = here();
      const double i = std::floor(number("as an array index") + kEpsilon);
      expect("]", "after the index");
      if (!(i >= 0 && i < a.dims[k])) {
        fail(iAt, "index " + std::to_string(long(i)) + " is out of range for '" + std::string(name) + "' (size " +
                      std::to_string(a.dims[k]) + ")");
      }
      flat = flat * size_t(a.dims[k]) + size_t(i);
    }
    v = &a.elements[flat];
    if (v->type == Value::Type::None) fail(at, "element of '" + std::string(name) + "' used before it was set");
  }
  if (v->type == Value::Type::Function) {
    const auto f = std::static_pointer_cast<const FunctionDef>(v->ref);
    if (peekOperator("(")) return callFunction(*f, name, at);
  }
  if (v->type == Value::Type::Node && static_cast<const Node&>(*v->ref).keyword == "spline" && peekOperator("(")) {
    return callSpline(static_cast<const Node&>(*v->ref));
  }
  if (v->type == Value::Type::None) fail(at, "'" + std::string(name) + "' has no value");
  return *v;
}

Value Interpreter::callSpline(const Node& spline) {
  expect("(", "before the spline's parameter");
  const SourceLoc tAt = here();
  const Value t = expression();
  if (t.type != Value::Type::Float) fail(tAt, std::string("a spline's parameter must be a float, found a ") + typeName(t));
  const SplinePoints points = splinePoints(spline);
  SplineKind kind = points.kind;
  if (peekOperator(",")) {
    next();
    SourceLoc kindAt;
    const Token word = next(&kindAt);
    const std::optional<SplineKind> named = splineKindNamed(word.text);
    if (!named) fail(kindAt, "expected a spline type, found " + quote(word.text));
    kind = *named;
  }
  expect(")", "after the spline's parameter");
  const std::array<double, 5> p = splineAt(points, t.v[0], kind);
  return points.size == 1 ? Value::number(p[0]) : Value::vector(p, points.size);
}

Value Interpreter::callFunction(const FunctionDef& f, std::string_view name, const SourceLoc& at) {
  // A spline function's value is its spline's at the first argument.
  if (f.spline) {
    const SourceLoc tAt = here();
    std::vector<Value> args;
    readArguments(args);
    if (args.empty() || args.size() > 3 || args[0].type != Value::Type::Float) {
      fail(tAt, "function '" + std::string(name) + "' takes the spline's parameter");
    }
    const SplinePoints points = splinePoints(*f.spline);
    const std::array<double, 5> p = splineAt(points, args[0].v[0], points.kind);
    return points.size == 1 ? Value::number(p[0]) : Value::vector(p, points.size);
  }
  const Arguments arguments(*this);
  const std::vector<Value>& args = arguments.values;
  // A pigment or transform function reads a point: up to three floats, the missing ones 0.
  const auto point = [&] {
    if (args.size() > 3) {
      fail(at, "function '" + std::string(name) + "' takes 3 arguments, found " + std::to_string(args.size()));
    }
    double p[3] = {0, 0, 0};
    for (size_t i = 0; i < args.size(); ++i) {
      if (args[i].type != Value::Type::Float) fail(at, "function arguments must be floats");
      p[i] = args[i].v[0];
    }
    return glm::dvec3(p[0], p[1], p[2]);
  };
  // A pigment function's value is its colour at the point.
  if (f.pigment) {
    const Rgbft c = f.pigment->at(point());
    return Value::colour({c.rgb.r, c.rgb.g, c.rgb.b, c.filter, c.transmit});
  }
  // A transform function's value is the point moved (POV-Ray's vtransform in transforms.inc calls one).
  if (f.transform) {
    const glm::dvec3 p = point();
    const std::array<double, 12>& m = *f.transform;
    std::array<double, 5> moved{};
    for (size_t j = 0; j < 3; ++j) moved[j] = p[0] * m[j] + p[1] * m[3 + j] + p[2] * m[6 + j] + m[9 + j];
    return Value::vector(moved, 3);
  }
  const size_t params = f.compiled ? f.compiled->params() : f.params.size();
  if (args.size() > params) {
    fail(at, "function '" + std::string(name) + "' takes " + std::to_string(params) + " arguments, found " +
                 std::to_string(args.size()));
  }
  if (f.compiled) {
    double a[Function::kMaxParams];
    for (size_t i = 0; i < args.size(); ++i) {
      if (args[i].type != Value::Type::Float) fail(at, "function arguments must be floats");
      a[i] = args[i].v[0];
    }
    return Value::number((*f.compiled)(a, args.size()));
  }
  if (f.body.tokens.size() == 1) fail(f.whyAt, "'" + f.why + "' is not supported yet");  // nothing to read again
  if (macroDepth_ >= 400) fail(at, "function calls nested too deep");
  Scope scope;
  // Parameters without an argument are 0, as POV-Ray's x, y and z are for a one-argument call.
  for (size_t i = 0; i < f.params.size(); ++i) {
    if (i < args.size() && args[i].type != Value::Type::Float) fail(at, "function arguments must be floats");
    auto slot = std::make_shared<Slot>();
    slot->value = i < args.size() ? args[i] : Value::number(0);
    scope.symbols[f.params[i]] = slot;
  }
  ++macroDepth_;
  frames_.push_back({Frame::Kind::Tokens, &f.body, 0, at, name});
  scopes_.push_back(std::move(scope));
  Value v = fullExpression();
  const Token& rest = rawPeek();
  if (rest.kind != Token::Kind::End) fail(locOf(rest), "unexpected " + quote(rest.text) + " in function '" + std::string(name) + "'");
  frames_.pop_back();
  scopes_.pop_back();
  --macroDepth_;
  return v;
}

}  // namespace rt::povray
