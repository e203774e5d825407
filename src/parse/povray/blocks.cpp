// What a #declare may hold beyond an expression: arrays, functions, and blocks of scene syntax kept as trees.
#include <algorithm>
#include <cmath>

#include "interpreter_state.hpp"
#include "raytrace/util/limits.hpp"
#include "raytrace/util/message.hpp"

namespace rt::povray {

namespace {

// The most elements an array may have: a typo in a size should be a message, not an exhausted memory.
constexpr double kMaxArrayElements = 1e8;

// Where POV-Ray reads a list longer than a vector: a polynomial's coefficients, first in a cubic or a quartic, after
// the order in a poly; and the twelve numbers after `matrix`.
bool coefficientsHere(std::string_view keyword, const std::vector<Item>& before) {
  const size_t n = before.size();
  if (n > 0 && before.back().kind == Item::Kind::Keyword && before.back().word == "matrix") return true;
  return ((keyword == "cubic" || keyword == "quartic") && n == 0) || (keyword == "poly" && n == 1);
}

// The functions a julia_fractal names as keywords (manual, "Julia Fractal") that are also built-in functions.
bool juliaFunction(const Token& t) {
  static constexpr std::string_view kWords[] = {"exp",  "sin",  "asin", "sinh", "asinh", "cos", "acos", "cosh",
                                                "acosh", "tan", "atan", "tanh", "atanh", "ln",  "pwr"};
  return t.kind == Token::Kind::Word && std::find(std::begin(kWords), std::end(kWords), t.text) != std::end(kWords);
}

}  // namespace

// Whether `t` begins a value rather than being a keyword of the block it is in.
bool Interpreter::startsExpression(const Token& t) {
  switch (t.kind) {
    case Token::Kind::Number:
    case Token::Kind::String:
      return true;
    case Token::Kind::Symbol:
      return t.is("<") || t.is("(") || t.is("-") || t.is("+") || t.is("!");
    case Token::Kind::Word:
      return t.startsValue;
    default:
      return false;
  }
}

Value Interpreter::declarable() {
  SourceLoc at;
  const Token& t = peek();
  at = locOf(t);
  if (t.isWord("array")) {
    next();
    return arrayValue(at);
  }
  if (t.isWord("function")) {
    next();
    return functionValue(at);
  }
  if (t.kind == Token::Kind::Word && !t.startsValue) {
    const std::string_view keyword = next().text;
    expect("{", "after the keyword");
    Value v;
    v.type = Value::Type::Node;
    v.ref = std::const_pointer_cast<Node>(block(keyword, at, "}"));
    // `texture { … } texture { … }`: a layered texture, its layers in order.
    auto layer = [this] {
      const Frame& f = frames_.back();
      return rawPeek().isWord("texture") && f.file->tokens[f.pos + 1].is("{");
    };
    if (keyword == "texture" && layer()) {
      auto layers = std::make_shared<Node>();
      layers->keyword = "layered texture";
      layers->loc = at;
      layers->items.push_back({Item::Kind::Node, {}, at, {}, std::static_pointer_cast<const Node>(v.ref)});
      while (layer()) {
        SourceLoc layerAt;
        next(&layerAt);
        next();
        layers->items.push_back({Item::Kind::Node, {}, layerAt, {}, block("texture", layerAt, "}")});
      }
      v.ref = layers;
    }
    return v;
  }
  return expression();
}

Value Interpreter::arrayValue(const SourceLoc& at) {
  auto a = std::make_shared<ArrayValue>();
  double total = 1;
  while (peekOperator("[")) {
    next();
    const SourceLoc nAt = here();
    const double n = std::floor(number("as the array's size") + 1e-10);
    expect("]", "after the array's size");
    if (!(n >= 1)) fail(nAt, "an array's size must be at least 1");
    total *= n;
    if (total > kMaxArrayElements) fail(nAt, "an array of more than " + std::to_string(long(kMaxArrayElements)) + " elements");
    a->dims.push_back(int(n));
  }
  if (a->dims.empty()) fail(at, "expected '[' and a size after 'array'");
  const std::string shortage = memoryShortage("an array of " + thousands(size_t(total)) + " elements",
                                              std::uint64_t(total) * sizeof(Value), availableMemory());
  if (!shortage.empty()) fail(at, shortage);
  a->elements.resize(size_t(total));
  if (peekOperator("{")) {
    size_t index = 0;
    arrayInitialiser(*a, 0, index);
  }
  Value v;
  v.type = Value::Type::Array;
  v.ref = a;
  return v;
}

// `{ e, e, … }` for the last dimension, `{ { … }, { … } }` for the ones before it.
void Interpreter::arrayInitialiser(ArrayValue& a, size_t dim, size_t& index) {
  SourceLoc at;
  next(&at);
  const Nested nested(*this, at);
  for (int i = 0; i < a.dims[dim]; ++i) {
    if (i > 0 && peek().is(",")) next();  // the commas may be left out
    if (dim + 1 < a.dims.size()) {
      if (!peek().is("{")) fail(here(), "expected '{' for the next dimension of the array");
      arrayInitialiser(a, dim + 1, index);
    } else {
      a.elements[index++] = declarable();
    }
  }
  if (peekOperator(",")) next();
  if (!peek().is("}")) fail(here(), "the array has " + std::to_string(a.dims[dim]) + " elements here, not more");
  next();
}

// `function { … }` or `function(a, b) { … }`: compiled, and its tokens kept, to be read again when called if
// it did not compile.
Value Interpreter::functionValue(const SourceLoc& at) {
  auto f = std::make_shared<FunctionDef>();
  if (peek().is("(")) {
    next();
    while (!peek().is(")")) {
      f->params.push_back(expectWord("a parameter name"));
      if (peek().is(",")) next();
    }
    next();
  } else {
    f->params = {"x", "y", "z"};
    // An image function's size, `function 256, 256 { … }`.
    for (int n = 0; !peek().is("{") && peek().kind != Token::Kind::End; ++n) {
      const Value size = expression();
      if (size.numeric() && n < 2) (n == 0 ? f->width : f->height) = size.v[0];
      if (peek().is(",")) next();
    }
  }
  expect("{", "to begin the function");
  f->body.name = frames_.back().file->name;
  const bool pattern = peek().isWord("pattern"), pigment = peek().isWord("pigment"),
             transform = peek().isWord("transform"), spline = peek().isWord("spline");
  const Frame& frame = frames_.back();
  if ((pattern || pigment || transform || spline) && frame.file->tokens[frame.pos + 1].is("{")) {
    SourceLoc patternAt;
    next(&patternAt);
    next();
    const std::string_view word = pattern ? "pattern" : pigment ? "pigment" : transform ? "transform" : "spline";
    const std::shared_ptr<const Node> node = block(word, patternAt, "}");
    expect("}", "to end the function");
    f->body.tokens.push_back(Token{});
    f->why = std::string(word) + " in a function";
    if (spline) f->spline = node;
    f->whyAt = patternAt;
    f->colour = pigment;
    f->transforms = transform;
    if (pattern && options_.patternFunction) options_.patternFunction(*node, *f);
    if (pigment && options_.pigmentFunction) options_.pigmentFunction(*node, *f);
    if (transform && options_.transformFunction) options_.transformFunction(*node, *f);
    Value v;
    v.type = Value::Type::Function;
    v.ref = f;
    return v;
  }
  int depth = 1;
  for (;;) {
    const Token& t = peek();
    if (t.kind == Token::Kind::End) fail(at, "this function has no closing '}'");
    if (t.is("{")) ++depth;
    if (t.is("}") && --depth == 0) break;
    f->body.tokens.push_back(next());
  }
  next();
  f->body.tokens.push_back(Token{});
  // The frame's constants (clock, image_width …) are the function's too.
  Value constant;
  compileFunction(f->params, f->body, [this, &at, &constant](std::string_view name) -> const Value* {
    static constexpr std::string_view kConstants[] = {"clock", "clock_delta", "clock_on", "frame_number",
                                                      "initial_clock", "final_clock", "initial_frame", "final_frame",
                                                      "image_width", "image_height", "version"};
    if (std::find(std::begin(kConstants), std::end(kConstants), name) != std::end(kConstants)) {
      constant = builtin(name, builtinIndex(name), at);
      return &constant;
    }
    const Slot* slot = find(name);
    return slot ? &slot->value : nullptr;
  }, *f);
  Value v;
  v.type = Value::Type::Function;
  v.ref = f;
  return v;
}

// The items of a block up to `close`: values, keywords, and nested blocks (`keyword { … }` or `[ … ]`).
std::shared_ptr<const Node> Interpreter::block(std::string_view keyword, const SourceLoc& at, std::string_view close) {
  const Nested nested(*this, at);
  std::shared_ptr<Node> node;
  if (!spareNodes_.empty()) {
    node = std::move(spareNodes_.back());
    spareNodes_.pop_back();
    node->depth = 1;
  } else {
    node = std::make_shared<Node>();
    node->items.reserve(4);  // most blocks hold a few items: one allocation rather than growing 1, 2, 4
  }
  node->keyword = keyword;
  node->loc = at;
  for (;;) {
    const Token& t = peek();
    if (t.is(close)) {
      next();
      return node;
    }
    if (t.kind == Token::Kind::End) fail(at, "this '" + std::string(keyword) + "' has no closing '" + std::string(close) + "'");
    if (t.is(",") || t.is(";")) {
      next();
      continue;
    }
    const bool coefficients = t.is("<") && coefficientsHere(keyword, node->items);
    // Made in place: an item (a Value and more) is too large to build and then move for every value of a scene.
    Item& item = node->items.emplace_back();
    item.loc = locOf(t);
    if (t.is("[")) {
      next();
      item.kind = Item::Kind::Node;
      item.node = block("[", item.loc, "]");
    } else if (t.isWord("function")) {
      next();
      item.kind = Item::Kind::Value;
      item.value = functionValue(item.loc);
    } else if (keyword == "text" && t.isWord("internal")) {
      // A text's font selector (`internal 1`), not the built-in function of that name.
      item.word = next().text;
      item.kind = Item::Kind::Keyword;
    } else if (keyword == "julia_fractal" && juliaFunction(t)) {
      // A julia_fractal's function (`sin`, `pwr(X, Y)`), not the built-in function of that name; pwr's numbers
      // are read here, and the julia_fractal refuses the functions it does not draw.
      item.word = next().text;
      item.kind = Item::Kind::Keyword;
      if (item.word == "pwr") {
        expect("(", "before pwr's numbers");
        expression();
        expect(",", "between pwr's numbers");
        expression();
        expect(")", "after pwr's numbers");
      }
    } else if (coefficients) {
      item.kind = Item::Kind::Value;
      item.value = coefficientList(item.loc);
    } else if (startsExpression(t)) {
      item.kind = Item::Kind::Value;
      item.value = expression();
      if (item.value.type == Value::Type::Node) {
        item.kind = Item::Kind::Node;
        item.node = std::static_pointer_cast<const Node>(item.value.ref);
        item.value = Value();
      }
    } else if (t.kind == Token::Kind::Word) {
      item.word = next().text;
      if (peek().is("{")) {
        next();
        item.kind = Item::Kind::Node;
        item.node = block(item.word, item.loc, "}");
      } else {
        item.kind = Item::Kind::Keyword;
      }
    } else {
      fail(item.loc, "unexpected " + quote(t.text) + " in '" + std::string(keyword) + "'");
    }
    if (item.kind == Item::Kind::Node) {
      node->depth = std::max(node->depth, item.node->depth + 1);
      if (size_t(node->depth) > kMaxNesting) {
        fail(item.loc, "objects or blocks nested more than " + std::to_string(kMaxNesting) + " deep");
      }
    }
  }
}

void Interpreter::recycle(std::shared_ptr<const Node> tree) {
  // Held elsewhere too (a declared identifier's value, the builder's list of meshes): left as it is.
  if (tree.use_count() != 1) return;
  // Every node is made as a Node by block() or declarable(): no const object is changed here.
  std::shared_ptr<Node> node = std::const_pointer_cast<Node>(std::move(tree));
  for (Item& item : node->items) {
    if (item.node) recycle(std::move(item.node));
  }
  if (spareNodes_.size() == kSpareNodes || node->items.capacity() > kSpareItems) return;
  node->items.clear();
  spareNodes_.push_back(std::move(node));
}

}  // namespace rt::povray
