// The POV-Ray 3.7 scene language as POV-Ray reads it: one pass over the tokens, with the directives (#declare,
// #if, #while, #macro, #include …) carried out as they are met, so a macro's body or a loop's body simply
// continues the token stream wherever it is used, inside an expression as much as between objects. What is
// left after the directives, the scene statements, is handed on one by one as syntax trees (value.hpp).
#pragma once

#include <optional>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "raytrace/parse/povray/clock.hpp"
#include "raytrace/parse/povray/lexer.hpp"
#include "raytrace/parse/povray/value.hpp"
#include "raytrace/scene/description.hpp"

namespace rt::povray {

struct InterpreterOptions {
  std::vector<std::string> libraryPaths;  // -L folders, searched after the scene's own folder
  std::string standardLibrary = "/usr/share/povray-3.7/include";
  int imageWidth = 320, imageHeight = 240;  // image_width, image_height
  std::ostream* debug = nullptr;            // #debug and #warning text; none if null
  size_t maxTokens = 0;                     // stop after reading this many tokens (0: no limit), for fuzzing
  std::string writeFolder;                  // where #write's files go: the image's folder ("": the current one)
  bool writeAnywhere = false;               // --allow-write-anywhere: #fopen may write outside writeFolder
  Clock clock;                              // clock, frame_number … of this frame
  // What the scene builder knows of an object, for the functions that ask it: its bounding box as min x, y, z
  // then max x, y, z (nothing if unbounded) for min_extent and max_extent; for trace, the first point where
  // the ray from `start` along `dir` meets it, then the outward normal there (nothing if it misses); for inside,
  // whether a point is inside it.
  using Vec = std::array<double, 3>;
  std::function<std::optional<std::array<double, 6>>(const std::shared_ptr<const Node>&)> extent;
  std::function<std::optional<std::array<Vec, 2>>(const std::shared_ptr<const Node>&, const Vec& start, const Vec& dir)>
      trace;
  std::function<bool(const std::shared_ptr<const Node>&, const Vec& point)> inside;
  // A pattern function, `function { pattern { … } }`: the compiled function of its `pattern` block, or null with
  // `into.why` saying what in it is not supported.
  std::function<void(const Node& pattern, FunctionValue& into)> patternFunction;
  // A pigment function, `function { pigment { … } }`: its pigment in `into.pigment`, or null with `into.why`.
  std::function<void(const Node& pigment, FunctionValue& into)> pigmentFunction;
  // A transform function, `function { transform { … } }`: its matrix in `into.transform`, or null with `into.why`.
  std::function<void(const Node& transform, FunctionValue& into)> transformFunction;
};

class Interpreter {
 public:
  // `statement` receives every top-level scene statement (camera, light_source, an object, global_settings …);
  // `defaults` every `#default { … }` block, at its place in the file.
  using NodeSink = std::function<void(const std::shared_ptr<const Node>&)>;

  explicit Interpreter(InterpreterOptions options);
  ~Interpreter();

  // Runs a whole scene. Throws ParseError with the include and macro chain of the place.
  void run(const std::string& path, std::string_view text, const NodeSink& statement, const NodeSink& defaults);

  // `name=value` from the command line (-D), a number or else a string, visible to #ifdef.
  void declare(const std::string& name, const std::string& value);

  // The language version #version last set (3.7 unless a scene says otherwise).
  double version() const { return version_; }

  // The files the scene wrote, in memory (DataFileDesc), for the caller to put on disk or not.
  std::vector<DataFileDesc> takeDataFiles() { return std::move(dataFiles_); }
  // Every file the scene found to read (includes, images, #read data, fonts), in the order first found.
  std::vector<std::string> takeFilesFound() { return std::move(filesFound_); }

  // Where a text object's font file is: where an include file would be, else in the folder Debian's
  // fonts-povray installs; as named, else with .ttf added (as POV-Ray does); "" if nowhere.
  std::string findFont(const std::string& name);
  // Where #include, #read and a height field's image find a file: as named if absolute, else in the scene's
  // folder, the -L folders and the standard include library, in that order; "" if nowhere. A file found is
  // one the picture depends on (takeFilesFound).
  std::string findFile(const std::string& name);

 private:
  struct Slot;
  struct Scope;
  // Where tokens come from: a file (the scene or an include), a macro body, or a function's captured tokens.
  struct Frame {
    enum class Kind { File, Macro, Tokens } kind;
    const TokenFile* file;
    size_t pos;
    SourceLoc from;         // the #include or the macro call
    std::string_view name;  // the macro's
  };
  struct Cond;
  struct MacroDef;
  struct FunctionDef;
  struct OpenFile;

  // Tokens.
  const Token& rawPeek() {
    const Frame& f = frames_.back();
    const Token& t = f.file->tokens[f.pos];
    return t.kind != Token::Kind::End ? t : endOfFrame();
  }
  const Token& endOfFrame();
  // peek, next and peekSymbol run for every token, several times: what most tokens need is inline here, the
  // directives and macros in the out-of-line parts.
  const Token& peek() {
    const Token& t = rawPeek();
    if (t.kind == Token::Kind::Directive ||
        (t.kind == Token::Kind::Word && !t.keyword && macroInitial_[static_cast<unsigned char>(t.text[0])])) {
      return peekExpanding();
    }
    return t;
  }
  const Token& peekExpanding();
  Token next(SourceLoc* loc = nullptr) {
    const Token& t = peek();
    if (loc) *loc = locOf(t);
    if (t.kind != Token::Kind::End) ++frames_.back().pos;
    if (++tokensRead_ == options_.maxTokens) tooManyTokens(t);
    return t;
  }
  [[noreturn]] void tooManyTokens(const Token& t) const;
  SourceLoc here() { return locOf(peek()); }
  SourceLoc locOf(const Token& t) const { return frames_.back().file->loc(t); }
  bool peekOperator(std::string_view op) {
    peekSymbol();
    return rawPeek().is(op);
  }
  // The next token's first character if it is a symbol, else 0 (as peekOperator).
  char peekSymbol() {
    const Token& t = rawPeek();
    if (t.kind == Token::Kind::Symbol) return t.text[0];
    return t.kind == Token::Kind::Directive ? peekSymbolAfterDirectives() : 0;
  }
  char peekSymbolAfterDirectives();
  // The symbol read inline when it is the very next token (no directive or macro can be in the way of a
  // symbol), else by the out-of-line part, which carries out what comes first or fails.
  void expect(std::string_view symbol, const char* what) {
    Frame& f = frames_.back();
    const Token& t = f.file->tokens[f.pos];
    if (!t.is(symbol)) return expectExpanding(symbol, what);
    ++f.pos;
    if (++tokensRead_ == options_.maxTokens) tooManyTokens(t);
  }
  void expectExpanding(std::string_view symbol, const char* what);
  std::string_view expectWord(const char* what, SourceLoc* loc = nullptr);
  [[noreturn]] void fail(const SourceLoc& loc, const std::string& message) const;
  // One more level of nesting for as long as it lives; too deep a nesting is an error, not a stack overflow.
  // Each level takes several stack frames of the expression or block parser, up to 8 KiB in a sanitizer
  // build: 256 levels stay well inside the 8 MiB a thread has.
  static constexpr size_t kMaxNesting = 256;
  struct Nested {
    Interpreter& in;
    Nested(Interpreter& interpreter, const SourceLoc& at) : in(interpreter) {
      if (++in.nesting_ > kMaxNesting) in.nestedTooDeep(at);
    }
    ~Nested() { --in.nesting_; }
  };
  [[noreturn]] void nestedTooDeep(const SourceLoc& at);
  std::string chain() const;

  // Directives (directives.cpp).
  void directive();
  void directive(DirectiveId id, std::string_view name, const SourceLoc& at);
  void declareDirective(bool local);
  void includeDirective(const SourceLoc& at);
  void macroDefinition(const SourceLoc& at);
  void invokeMacro(const std::shared_ptr<MacroDef>& macro);
  void ifDirective(bool truth);
  void switchDirective();
  void forDirective(const SourceLoc& at);
  void endDirective(const SourceLoc& at);
  void breakDirective(const SourceLoc& at);
  std::string_view skipTo(bool stopAtElse, bool stopAtCase);
  void pushFile(const std::string& path, std::string_view text, const SourceLoc* from);
  void undefine(std::string_view id);

  // File input and output (file_io.cpp).
  void fopenDirective(const SourceLoc& at);
  void fcloseDirective();
  void readDirective(const SourceLoc& at);
  void writeDirective(const SourceLoc& at);
  std::shared_ptr<OpenFile> fileHandle(const char* directive, bool reading, std::string_view* id);
  Value dataValue(OpenFile& file, const SourceLoc& at);
  [[noreturn]] void failInData(const SourceLoc& loc, const std::string& message, const SourceLoc& at) const;
  const DataFileDesc* written(const std::string& name) const;
  // `path`, noted in filesFound_.
  std::string found(const std::string& path);
  std::string writePath(const std::string& name) const;

  // Symbols.
  Slot* find(std::string_view name);
  void assign(std::string_view name, Value value, size_t level);

  // Expressions (expression.cpp).
  Value expression() { return sum(); }  // arithmetic: + - * / and unary operators
  Value fullExpression();  // inside parentheses: also relations, & | and ?:
  Value logical();
  Value relation();
  Value sum();
  // Forced inline into sum and unary: a scene's operands go down every level, and each call costs more than
  // the level's own work.
  [[gnu::always_inline]] Value product();
  Value unary();
  [[gnu::always_inline]] Value postfix();
  Value primary();
  Value vectorLiteral(const SourceLoc& at);
  Value coefficientList(const SourceLoc& at);
  Value colour(const SourceLoc& at);
  Value identifierValue(const Token& t, const SourceLoc& at);
  double number(const char* what);
  double truth(const Value& v, const SourceLoc& at);
  Value binary(char op, Value a, Value b, const SourceLoc& at);
  Value callFunction(const FunctionDef& f, std::string_view name, const SourceLoc& at);
  // A spline's value, `S(t)` or `S(t, TYPE)`: the arguments read here.
  Value callSpline(const Node& spline);

  // Built-in functions (builtins.cpp).
  // `index` is the name's builtinIndex.
  Value builtin(std::string_view name, std::uint8_t index, const SourceLoc& at);
  // A call's `(a, b …)`, read into a vector an earlier call has given back: calls in a loop allocate none.
  struct Arguments {
    Interpreter& in;
    std::vector<Value> values;
    explicit Arguments(Interpreter& interpreter);
    ~Arguments();
    Arguments(const Arguments&) = delete;
    Arguments& operator=(const Arguments&) = delete;
  };
  void readArguments(std::vector<Value>& args);

  // Values that are more than an expression (blocks.cpp).
  Value declarable();
  Value arrayValue(const SourceLoc& at);
  void arrayInitialiser(ArrayValue& a, size_t dim, size_t& index);
  Value functionValue(const SourceLoc& at);
  std::shared_ptr<const Node> block(std::string_view keyword, const SourceLoc& at, std::string_view close);
  // A statement's tree once the builder has read it: its nodes no one else holds are emptied and kept for the
  // next blocks (spareNodes_), so that a loop's statements allocate no node and no item list each.
  void recycle(std::shared_ptr<const Node> node);
  bool startsExpression(const Token& t);

  InterpreterOptions options_;
  std::vector<std::unique_ptr<TokenFile>> files_;
  std::vector<std::unique_ptr<std::string>> texts_;  // include files' bytes, which the tokens point into
  std::vector<std::unique_ptr<std::string>> names_;  // names declared from the command line
  std::vector<Frame> frames_;
  std::vector<Cond> conds_;
  std::vector<Scope> scopes_;
  std::vector<std::uint32_t> randStates_;
  // Arguments' vectors, given back: a few (one per call nested in another's arguments), at most kSpareArguments,
  // room for which is made at the start so that giving one back never allocates.
  static constexpr size_t kSpareArguments = 16;
  std::vector<std::vector<Value>> spareArguments_;
  // Nodes given back (recycle), empty, with room for items: at most kSpareNodes, each with room for at most
  // kSpareItems (a long list is freed rather than kept).
  static constexpr size_t kSpareNodes = 64, kSpareItems = 64;
  std::vector<std::shared_ptr<Node>> spareNodes_;
  std::vector<DataFileDesc> dataFiles_;  // what #write wrote, kept until the scene has parsed
  std::vector<std::string> filesFound_;
  size_t bytesWritten_ = 0;
  NodeSink defaults_;
  std::string sceneFolder_;
  double version_ = 3.7;
  size_t macroDepth_ = 0;
  size_t tokensRead_ = 0;
  size_t nesting_ = 0;
  // While a directive's own condition is read, the directives its expression may end at belong to levels
  // opened before it and must wait: only those opened since (a macro called in it) are carried out.
  size_t condBase_ = 0;
  // While an #include's file name is read, the end of the current file is not left: an include file that
  // includes itself must nest, and stop at the depth limit.
  bool holdFile_ = false;  // parentheses, vectors, unary operators and blocks open, each a level of recursion
  // The first letters of the macros' names: most words are no macro, and this spares them a look-up.
  std::array<bool, 256> macroInitial_{};
};

}  // namespace rt::povray
