// What a POV-Ray identifier or expression holds: a float, a vector or colour, a string, an array, or a piece
// of scene syntax (an object, texture, pigment, camera …) kept as the tree it was written as.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "raytrace/util/error.hpp"

namespace rt {
class Function;
struct Pigment;
}

namespace rt::povray {

struct Token;
struct TokenFile;

// A value that is shared rather than copied: arrays, syntax trees, functions, macros, open files.
struct Shared {
  virtual ~Shared() = default;
};

// A string's text, shared rather than held in each Value: most values are numbers, which then carry no string
// to make, move and destroy at every step of an expression.
struct StringValue : Shared {
  std::string text;
  explicit StringValue(std::string t) : text(std::move(t)) {}
};

struct Value {
  enum class Type : unsigned char { None, Float, Vector, Colour, String, Array, Node, Function, Macro, File };
  Type type = Type::None;
  int size = 1;  // components of a vector (2–5); a colour always has 5: red, green, blue, filter, transmit
  std::array<double, 5> v{};
  std::shared_ptr<Shared> ref;  // a string's StringValue, or what an array, a node, a function … shares

  static Value number(double x) {
    Value r;
    r.type = Type::Float;
    r.v[0] = x;
    return r;
  }
  static Value vector(std::array<double, 5> c, int n) {
    Value r;
    r.type = Type::Vector;
    r.size = n;
    r.v = c;
    return r;
  }
  static Value colour(std::array<double, 5> c) {
    Value r;
    r.type = Type::Colour;
    r.size = 5;
    r.v = c;
    return r;
  }
  static Value string(std::string text) {
    Value r;
    r.type = Type::String;
    r.ref = std::make_shared<StringValue>(std::move(text));
    return r;
  }
  // A String's text.
  const std::string& str() const { return static_cast<const StringValue&>(*ref).text; }
  bool numeric() const { return type == Type::Float || type == Type::Vector || type == Type::Colour; }
};

// A polynomial's coefficients `<c1, …, cn>`, a list of any length that POV-Ray reads only in a cubic, a quartic
// or a poly: a Vector Value of size n (its first five in v) whose ref holds them all.
struct CoefficientList : Shared {
  std::vector<double> values;
};

// The name POV-Ray's messages give a type: "float", "vector", "colour", "string", …
const char* typeName(const Value& v);
// The component `.x` `.u` `.red` (0), `.y` `.v` `.green` (1), `.z` `.blue` (2), `.t` `.filter` (3) or
// `.transmit` (4) names; −1 for any other word.
int componentIndex(std::string_view c);

// An element of a syntax tree: a keyword, a value, or a nested block.
struct Node;
struct Item {
  enum class Kind : unsigned char { Keyword, Value, Node } kind;
  std::string_view word;  // the keyword (points into a file's text, which lives as long as the interpreter)
  SourceLoc loc;
  Value value;                 // for Value
  std::shared_ptr<const Node> node;  // for Node
};

// `keyword { items }` as written (with identifiers replaced by what they held), e.g. a sphere, a pigment, or
// a `[0.5 color Red]` entry of a map, whose keyword is "[".
struct Node : Shared {
  std::string_view keyword;
  SourceLoc loc;
  std::vector<Item> items;
  int depth = 1;  // 1 + the deepest node among the items, bounded so that walking a tree cannot overflow the stack
};

// A `function { … }` value: compiled when its body is in what raytrace compiles (surface/function.hpp), else
// `why` names what stopped it, for the "… is not supported yet" of a shape or pattern that draws it.
struct FunctionValue : Shared {
  std::shared_ptr<const Function> compiled;
  // A pigment function, `function { pigment { … } }`: a vector function whose colour other functions read a
  // component of (`F(x, y, z).red`); `compiled` is then null, and so is `pigment` if the pigment was refused.
  bool colour = false;
  std::shared_ptr<const Pigment> pigment;
  // A transform function, `function { transform { … } }`: a vector function, the image of the point (x, y, z),
  // x·row 0 + y·row 1 + z·row 2 + row 3 of these 12 numbers (as `matrix` writes them); null if it was refused.
  bool transforms = false;
  std::shared_ptr<const std::array<double, 12>> transform;
  // A spline function, `function { spline { … } }`: the spline, whose value at the first argument it gives.
  std::shared_ptr<const Node> spline;
  std::string why;
  SourceLoc whyAt;
  double width = 0, height = 0;  // an image function's size, `function W, H { … }` (a height field's); else 0
};

// `array[N][M]…`: elements in row-major order, unset ones of type None.
struct ArrayValue : Shared {
  std::vector<int> dims;
  std::vector<Value> elements;
};

}  // namespace rt::povray
