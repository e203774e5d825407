#include "raytrace/parse/povray/interpreter.hpp"

#include <cstdlib>

#include "interpreter_state.hpp"

namespace rt::povray {

Interpreter::Interpreter(InterpreterOptions options) : options_(std::move(options)) {
  scopes_.emplace_back();
  spareArguments_.reserve(kSpareArguments);
  spareNodes_.reserve(kSpareNodes);
}

Interpreter::~Interpreter() = default;

void Interpreter::run(const std::string& path, std::string_view text, const NodeSink& statement,
                      const NodeSink& defaults) {
  defaults_ = defaults;
  const size_t slash = path.rfind('/');
  sceneFolder_ = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  pushFile(path, text, nullptr);
  for (;;) {
    SourceLoc at;
    const Token& t = peek();
    if (t.kind == Token::Kind::End) break;
    const Token word = next(&at);
    if (word.kind != Token::Kind::Word || !word.keyword || !peek().is("{")) {
      if (word.kind == Token::Kind::Word && !word.keyword && !find(word.text)) {
        fail(at, "undeclared identifier '" + std::string(word.text) + "'");
      }
      fail(at, "expected an object or a directive, found " + quote(word.text));
    }
    next();
    std::shared_ptr<const Node> node = block(word.text, at, "}");
    statement(node);
    recycle(std::move(node));
  }
  if (!conds_.empty()) fail(here(), "a directive is still open at the end of the file: #end is missing");
}

void Interpreter::declare(const std::string& name, const std::string& value) {
  names_.push_back(std::make_unique<std::string>(name));
  char* end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  const bool isNumber = !value.empty() && end == value.c_str() + value.size();
  auto slot = std::make_shared<Slot>();
  slot->value = isNumber ? Value::number(x) : Value::string(value);
  scopes_.front().symbols[*names_.back()] = slot;
}

// The next token as it is in the current frame, directives and all; the end of an include file or of a
// function body leaves it for the next frame's tokens.
const Token& Interpreter::endOfFrame() {
  for (;;) {
    Frame& f = frames_.back();
    const Token& t = f.file->tokens[f.pos];
    if (t.kind != Token::Kind::End || frames_.size() == 1 || f.kind == Frame::Kind::Tokens) return t;
    if (holdFile_ && f.kind == Frame::Kind::File) return t;
    if (f.kind == Frame::Kind::Macro) fail(f.from, "macro '" + std::string(f.name) + "' has no #end");
    for (const Cond& c : conds_) {
      if (c.frame == frames_.size()) fail(locOf(t), "a directive is still open at the end of the file: #end is missing");
    }
    frames_.pop_back();
    scopes_.pop_back();
  }
}

// The next token once the directives before it have been carried out and macros expanded.
const Token& Interpreter::peekExpanding() {
  for (;;) {
    const Token& t = rawPeek();
    if (t.kind == Token::Kind::Directive) {
      directive();
    } else if (t.kind == Token::Kind::Word && !t.keyword && macroInitial_[static_cast<unsigned char>(t.text[0])]) {
      Slot* s = find(t.text);
      if (!s || s->value.type != Value::Type::Macro) return t;
      invokeMacro(std::static_pointer_cast<MacroDef>(s->value.ref));
    } else {
      return t;
    }
  }
}

void Interpreter::tooManyTokens(const Token& t) const {
  fail(locOf(t), "the scene reads more than " + std::to_string(options_.maxTokens) + " tokens");
}

// Whether the next token is an operator (peekOperator, peekSymbol). Directives that only move on (#end, #else …)
// are carried out first, so that a macro used in an expression returns into it; any other directive ends the
// expression, as it would be carried out before the value it follows is stored.
char Interpreter::peekSymbolAfterDirectives() {
  for (;;) {
    const Token& t = rawPeek();
    if (t.kind == Token::Kind::Symbol) return t.text[0];
    if (t.kind != Token::Kind::Directive || conds_.size() <= condBase_) return 0;
    if (t.text != "end" && t.text != "else" && t.text != "elseif" && t.text != "break") return 0;
    directive();
  }
}

void Interpreter::expectExpanding(std::string_view symbol, const char* what) {
  if (peek().is(symbol)) {
    next();
    return;
  }
  SourceLoc at;
  const Token t = next(&at);
  fail(at, "expected '" + std::string(symbol) + "' " + what + ", found " +
               (t.kind == Token::Kind::End ? std::string("the end of the file") : quote(t.text)));
}

std::string_view Interpreter::expectWord(const char* what, SourceLoc* loc) {
  SourceLoc at;
  const Token& t = rawPeek();
  at = locOf(t);
  if (t.kind != Token::Kind::Word) fail(at, std::string("expected ") + what + ", found " + quote(t.text));
  if (loc) *loc = at;
  ++frames_.back().pos;
  return t.text;
}

std::string Interpreter::chain() const {
  std::string text;
  for (size_t i = frames_.size(); i-- > 1;) {
    const Frame& f = frames_[i];
    if (f.kind == Frame::Kind::Tokens) continue;
    text += text.empty() ? " (" : ", ";
    text += f.kind == Frame::Kind::Macro ? "in macro '" + std::string(f.name) + "' called from " + f.from.str()
                                         : "included from " + f.from.str();
  }
  return text.empty() ? text : text + ")";
}

void Interpreter::fail(const SourceLoc& loc, const std::string& message) const {
  throw ParseError(loc, message + chain());
}

void Interpreter::nestedTooDeep(const SourceLoc& at) {
  --nesting_;
  fail(at, "expressions or blocks nested more than " + std::to_string(kMaxNesting) + " deep");
}

Interpreter::Slot* Interpreter::find(std::string_view name) {
  for (size_t i = scopes_.size(); i-- > 0;) {
    const auto it = scopes_[i].symbols.find(name);
    if (it != scopes_[i].symbols.end()) return it->second.get();
  }
  return nullptr;
}

// Sets an identifier of scope level `level` (the callers have refused keywords).
void Interpreter::assign(std::string_view name, Value value, size_t level) {
  auto& slot = scopes_[level].symbols[name];
  if (!slot) slot = std::make_shared<Slot>();
  slot->value = std::move(value);
}

}  // namespace rt::povray
