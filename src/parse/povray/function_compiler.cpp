// A function's body compiled into surface/function.hpp's operations, once, where it is declared: the
// identifiers it names (floats, vectors' components, other functions) are taken as they are there, as POV-Ray
// does. The grammar is the manual's for functions ("User-Defined Functions"): floats only, with the
// precedence of the interpreter's expressions inside parentheses.
#include <algorithm>
#include <cmath>
#include <optional>

#include "interpreter_state.hpp"

namespace rt::povray {

namespace {

// As deep as the interpreter nests parentheses and unary operators.
constexpr size_t kMaxNesting = 256;

// A construct the compiler does not take: what it is, for the message.
struct NotCompiled {
  std::string what;
  const Token* at;
  std::optional<SourceLoc> where;  // the place instead of `at`'s, when it is in another function
};

class Compiler {
 public:
  Compiler(const std::vector<std::string_view>& params, const TokenFile& body,
           const std::function<const Value*(std::string_view)>& lookup)
      : params_(params), body_(body), lookup_(lookup) {}

  std::shared_ptr<const Function> compile() {
    if (params_.size() > Function::kMaxParams) fail("a function of more than 32 parameters", &peek());
    size_t nParams = params_.size();
    // `internal(N)` alone: one of functions.inc's built-in functions, with its own parameters.
    if (peek().isWord("internal")) {
      const Token& at = next();
      expect("(");
      const Token& n = next();
      expect(")");
      if (n.kind != Token::Kind::Number) fail("internal", &at);
      const int count = Function::internalParams(int(n.number));
      if (count < 0) fail("internal(" + std::to_string(int(n.number)) + ")", &at);
      for (int i = 0; i < count; ++i) code_.push_back({Function::Op::Param, unsigned(i)});
      code_.push_back({Function::Op::Internal, unsigned(count), n.number});
      nParams = size_t(count);
    } else {
      choice();
    }
    if (peek().kind != Token::Kind::End) fail(std::string(peek().text) + " here in a function", &peek());
    return std::make_shared<Function>(std::move(code_), nParams, depth());
  }

 private:
  [[noreturn]] static void fail(const std::string& what, const Token* at) { throw NotCompiled{what, at, std::nullopt}; }
  const Token& peek() const { return body_.tokens[pos_]; }
  const Token& next() {
    const Token& t = body_.tokens[pos_];
    if (t.kind != Token::Kind::End) ++pos_;
    return t;
  }
  bool at(std::string_view symbol) const { return body_.tokens[pos_].is(symbol); }
  void expect(std::string_view symbol) {
    if (!at(symbol)) fail(std::string(peek().text) + " here in a function", &peek());
    next();
  }
  void emit(Function::Op op, unsigned index = 0, double value = 0) { code_.push_back({op, index, value}); }

  // The operand stack's greatest depth.
  size_t depth() const {
    size_t d = 0, most = 0;
    for (const Function::Instr& i : code_) {
      switch (i.op) {
        case Function::Op::Const: case Function::Op::Param: ++d; break;
        case Function::Op::Neg: case Function::Op::Not: case Function::Op::Math1: break;
        case Function::Op::Choose: case Function::Op::Select3: d -= 2; break;
        case Function::Op::Select4: d -= 3; break;
        case Function::Op::Pattern: case Function::Op::Colour: d -= 2; break;
        case Function::Op::Call: case Function::Op::Internal: d = d + 1 - i.index; break;
        default: --d; break;
      }
      most = std::max(most, d);
    }
    return most;
  }

  void choice() {
    logical();
    if (!at("?")) return;
    next();
    choice();
    expect(":");
    choice();
    emit(Function::Op::Choose);
  }
  void logical() {
    relation();
    while (at("&") || at("|")) {
      const bool isAnd = next().is("&");
      relation();
      emit(isAnd ? Function::Op::And : Function::Op::Or);
    }
  }
  void relation() {
    sum();
    for (;;) {
      Function::Op op;
      if (at("<")) op = Function::Op::Lt;
      else if (at("<=")) op = Function::Op::Le;
      else if (at("=")) op = Function::Op::Eq;
      else if (at("!=")) op = Function::Op::Ne;
      else if (at(">=")) op = Function::Op::Ge;
      else if (at(">")) op = Function::Op::Gt;
      else return;
      next();
      sum();
      emit(op);
    }
  }
  void sum() {
    product();
    while (at("+") || at("-")) {
      const bool plus = next().is("+");
      product();
      emit(plus ? Function::Op::Add : Function::Op::Sub);
    }
  }
  void product() {
    unary();
    while (at("*") || at("/")) {
      const bool times = next().is("*");
      unary();
      emit(times ? Function::Op::Mul : Function::Op::Div);
    }
  }
  void unary() {
    if (at("-") || at("+") || at("!")) {
      const char op = next().text[0];
      if (++nesting_ > kMaxNesting) fail("a function nested this deep", &peek());
      unary();
      --nesting_;
      if (op == '-') emit(Function::Op::Neg);
      if (op == '!') emit(Function::Op::Not);
      return;
    }
    primary();
  }

  // `( e, e, … )`: the number of arguments, each pushed in order.
  size_t arguments() {
    expect("(");
    size_t n = 0;
    if (at(")")) {
      next();
      return 0;
    }
    for (;;) {
      choice();
      ++n;
      if (at(")")) break;
      expect(",");
    }
    next();
    return n;
  }

  void primary() {
    const Token& t = peek();
    if (t.kind == Token::Kind::Number) {
      emit(Function::Op::Const, 0, next().number);
      return;
    }
    if (t.is("(")) {
      if (++nesting_ > kMaxNesting) fail("a function nested this deep", &t);
      next();
      choice();
      expect(")");
      --nesting_;
      return;
    }
    if (t.kind != Token::Kind::Word) fail(std::string(t.text) + " in a function", &t);
    const std::string_view w = t.text;
    const auto param = std::find(params_.begin(), params_.end(), w);
    if (param != params_.end()) {
      next();
      emit(Function::Op::Param, unsigned(param - params_.begin()));
      return;
    }
    // u and v are x's and y's other names.
    if (w == "u" || w == "v") {
      const auto same = std::find(params_.begin(), params_.end(), w == "u" ? "x" : "y");
      if (same != params_.end()) {
        next();
        emit(Function::Op::Param, unsigned(same - params_.begin()));
        return;
      }
    }
    if (const Value* v = lookup_(w)) {
      identifier(*v, t);
      return;
    }
    next();
    if (w == "pi") return emit(Function::Op::Const, 0, 3.14159265358979323846);
    if (w == "tau") return emit(Function::Op::Const, 0, 2 * 3.14159265358979323846);
    if (w == "true" || w == "yes" || w == "on") return emit(Function::Op::Const, 0, 1);
    if (w == "false" || w == "no" || w == "off") return emit(Function::Op::Const, 0, 0);
    if (!at("(")) fail(std::string(w) + " in a function", &t);
    const size_t n = arguments();
    if (const int k = Function::math1(w); k >= 0) {
      if (n != 1) fail(std::string(w) + " of " + std::to_string(n) + " arguments", &t);
      return emit(Function::Op::Math1, unsigned(k));
    }
    if (const int k = Function::math2(w); k >= 0) {
      const bool list = w == "min" || w == "max";
      if (n != 2 && !(list && n > 2)) fail(std::string(w) + " of " + std::to_string(n) + " arguments", &t);
      for (size_t i = 1; i < n; ++i) emit(Function::Op::Math2, unsigned(k));
      return;
    }
    if (w == "select" && (n == 3 || n == 4)) return emit(n == 3 ? Function::Op::Select3 : Function::Op::Select4);
    fail(std::string(w) + " in a function", &t);
  }

  // A declared identifier: a float, a vector's or colour's component, or a call of another function.
  void identifier(const Value& v, const Token& t) {
    const std::string_view name = next().text;
    if (v.type == Value::Type::Float) return emit(Function::Op::Const, 0, v.v[0]);
    if ((v.type == Value::Type::Vector || v.type == Value::Type::Colour) && at(".")) {
      next();
      const std::string_view c = next().text;
      const int i = componentIndex(c);
      if (i < 0 || (v.type == Value::Type::Vector && i >= v.size)) fail("." + std::string(c) + " in a function", &t);
      return emit(Function::Op::Const, 0, v.v[size_t(i)]);
    }
    if (v.type == Value::Type::Function && at("(") && static_cast<const FunctionValue&>(*v.ref).colour) {
      const auto& f = static_cast<const FunctionValue&>(*v.ref);
      // A refused pigment is reported where it is.
      if (!f.pigment) throw NotCompiled{f.why, &t, f.whyAt};
      return colour(f, t);
    }
    if (v.type == Value::Type::Function && at("(")) {
      const auto& callee = static_cast<const FunctionValue&>(*v.ref);
      if (!callee.compiled && (callee.spline || callee.transforms)) throw NotCompiled{callee.why, &t, callee.whyAt};
      if (!callee.compiled) fail(std::string(name), &t);
      const size_t n = arguments();
      if (n > callee.compiled->params()) fail(std::string(name) + " with too many arguments", &t);
      code_.push_back({Function::Op::Call, unsigned(n), 0, callee.compiled});
      return;
    }
    fail("a " + std::string(typeName(v)) + " in a function", &t);
  }

  // A pigment function's call and the component read of its colour, `F(x, y, z).red`: the point's missing
  // coordinates are 0.
  void colour(const FunctionValue& f, const Token& t) {
    const size_t n = arguments();
    if (n > 3) fail(std::string(t.text) + " with too many arguments", &t);
    for (size_t i = n; i < 3; ++i) emit(Function::Op::Const);
    // A function's value is a float: POV-Ray stops at the call without a component, as at a bad one.
    if (!at(".")) throw ParseError(body_.loc(peek()), "expected '.' and a component after the pigment function's call");
    next();
    const Token& ct = next();
    const std::string_view c = ct.text;
    Function::Component which;
    if (c == "x" || c == "u" || c == "red") which = Function::Red;
    else if (c == "y" || c == "v" || c == "green") which = Function::Green;
    else if (c == "z" || c == "blue") which = Function::Blue;
    else if (c == "t" || c == "filter") which = Function::Filter;
    else if (c == "transmit") which = Function::Transmit;
    else if (c == "gray" || c == "grey") which = Function::Gray;
    else throw ParseError(body_.loc(ct), "unknown component '." + std::string(c) + "' of a colour");
    code_.push_back({Function::Op::Colour, unsigned(which), 0, nullptr, f.pigment});
  }

  const std::vector<std::string_view>& params_;
  const TokenFile& body_;
  const std::function<const Value*(std::string_view)>& lookup_;
  std::vector<Function::Instr> code_;
  size_t pos_ = 0;
  size_t nesting_ = 0;
};

}  // namespace

void compileFunction(const std::vector<std::string_view>& params, const TokenFile& body,
                     const std::function<const Value*(std::string_view)>& lookup, FunctionValue& into) {
  try {
    into.compiled = Compiler(params, body, lookup).compile();
    if (into.compiled->stackDepth() > Function::kMaxStack) {
      into.compiled = nullptr;
      into.why = "a function nested this deep";
      into.whyAt = body.loc(body.tokens.front());
    }
  } catch (const NotCompiled& e) {
    into.why = e.what;
    into.whyAt = e.where ? *e.where : body.loc(*e.at);
  }
}

}  // namespace rt::povray
