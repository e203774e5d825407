// The interpreter's inner records, shared by its source files and by no one else.
#pragma once

#include "raytrace/parse/povray/interpreter.hpp"
#include "raytrace/surface/function.hpp"

namespace rt::povray {

// Reads a whole file into `bytes`; false if it cannot be read.
bool readBytes(const std::string& path, std::string& bytes);

struct Interpreter::Slot {
  Value value;
};

// The identifiers of one level: the global one, an include file's, or a macro call's. Parameters passed as a
// bare identifier share the caller's slot, so `#declare` on them changes the caller's identifier.
struct Interpreter::Scope {
  // Names compared byte by byte inline: a level's few names are searched one by one, and for a name of the
  // same length the library's comparison would call memcmp each time, most of a loop's lookups' time.
  struct SameName {
    bool operator()(std::string_view a, std::string_view b) const {
      if (a.size() != b.size()) return false;
      for (size_t i = 0; i < a.size(); ++i) {
        if (a[i] != b[i]) return false;
      }
      return true;
    }
  };
  std::unordered_map<std::string_view, std::shared_ptr<Slot>, std::hash<std::string_view>, SameName> symbols;
};

// An open #if, #switch, #while, #for or macro call, closed by its #end.
struct Interpreter::Cond {
  enum class Kind { If, Switch, While, For, Macro } kind;
  size_t frame;        // frames_ depth it belongs to
  size_t pos = 0;      // While: the #while directive; For: the first token of the body
  std::string_view var;  // For
  double end = 0, step = 1;
};

struct Interpreter::MacroDef : Shared {
  std::string_view name;
  const TokenFile* file;
  size_t body;  // the first token after the parameter list
  std::vector<std::string_view> params;
};

struct Interpreter::FunctionDef : FunctionValue {
  std::vector<std::string_view> params;  // x, y, z when none are written
  TokenFile body;                        // the tokens between the braces, then End
};

// Compiles a function's body (function_compiler.cpp) into `into.compiled`, or says in `into.why` what it could
// not compile. `lookup` finds the identifiers declared where the function is: their values are taken now.
void compileFunction(const std::vector<std::string_view>& params, const TokenFile& body,
                     const std::function<const Value*(std::string_view)>& lookup, FunctionValue& into);

// A file #fopen opened: to read, its text, tokens and the next one's place (all freed when it is closed, so a
// loop that reopens a file takes no more memory); to write, its index in dataFiles_.
struct Interpreter::OpenFile : Shared {
  bool reading = false;
  std::string text;
  TokenFile tokens;
  size_t pos = 0;
  size_t data = 0;
};

}  // namespace rt::povray
