// The # directives: identifiers, conditions, loops, macros, includes and messages.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

#include "interpreter_state.hpp"

namespace rt::povray {

namespace {

// POV-Ray's own limits are of the same order; deeper nesting is a runaway recursion in practice.
constexpr size_t kMaxIncludeDepth = 64;
constexpr size_t kMaxMacroDepth = 400;
constexpr double kEpsilon = 1e-10;  // POV-Ray's tolerance for = and #case

bool isFile(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

}  // namespace

bool readBytes(const std::string& path, std::string& bytes) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  bytes = text.str();
  return bool(in);
}

void Interpreter::pushFile(const std::string& path, std::string_view text, const SourceLoc* from) {
  size_t files = 0;
  for (const Frame& f : frames_) files += f.kind == Frame::Kind::File;
  if (files >= kMaxIncludeDepth) fail(*from, "include files nested more than " + std::to_string(kMaxIncludeDepth) + " deep");
  files_.push_back(std::make_unique<TokenFile>());
  TokenFile& file = *files_.back();
  file.name = path;
  Frame frame{Frame::Kind::File, &file, 0, from ? *from : SourceLoc{}, {}};
  frames_.push_back(frame);
  if (from) scopes_.emplace_back();
  try {
    lex(text, file);
  } catch (const ParseError& e) {
    const std::string what = e.what();
    throw ParseError(e.loc(), what.substr(what.find(": error: ") + 9) + chain());
  }
}

void Interpreter::directive() {
  SourceLoc at;
  const Token& d = rawPeek();
  at = locOf(d);
  const std::string_view name = d.text;
  const DirectiveId id = d.directiveId;
  ++frames_.back().pos;
  const size_t base = condBase_;
  using D = DirectiveId;
  const bool conditional = id == D::If || id == D::Elseif || id == D::While || id == D::Switch || id == D::Case ||
                           id == D::Range || id == D::For;
  if (conditional) condBase_ = conds_.size();
  directive(id, name, at);
  condBase_ = base;
}

void Interpreter::directive(DirectiveId id, std::string_view name, const SourceLoc& at) {
  using D = DirectiveId;
  switch (id) {
    case D::Version:
      version_ = number("after #version");
      if (rawPeek().is(";")) ++frames_.back().pos;
      return;
    case D::Declare:
    case D::Local:
      declareDirective(id == D::Local);
      return;
    case D::Undef:
      undefine(expectWord("an identifier after #undef"));
      return;
    case D::Default:
      expect("{", "after #default");
      defaults_(block("default", at, "}"));
      return;
    case D::If:
      ifDirective(truth(expression(), at) != 0);
      return;
    case D::Ifdef:
    case D::Ifndef: {
      expect("(", "after #ifdef");
      const std::string_view ident = expectWord("an identifier");
      bool defined = find(ident) != nullptr;
      if (defined && rawPeek().is("[")) {
        const Value& a = find(ident)->value;
        next();
        const double i = number("as an array index");
        expect("]", "after the index");
        const auto* arr = a.type == Value::Type::Array ? static_cast<const ArrayValue*>(a.ref.get()) : nullptr;
        defined = arr && i >= 0 && size_t(i) < arr->elements.size() && arr->elements[size_t(i)].type != Value::Type::None;
      }
      expect(")", "after the identifier");
      ifDirective(defined == (id == D::Ifdef));
      return;
    }
    case D::Else:
    case D::Elseif:
      if (conds_.empty() || conds_.back().frame != frames_.size()) fail(at, "#" + std::string(name) + " without #if");
      if (conds_.back().kind == Cond::Kind::Switch) return;  // falls through, like a #case
      if (conds_.back().kind != Cond::Kind::If) fail(at, "#" + std::string(name) + " without #if");
      conds_.pop_back();
      skipTo(false, false);
      return;
    case D::End:
      endDirective(at);
      return;
    case D::Switch:
      switchDirective();
      return;
    case D::Case:
    case D::Range:
      if (conds_.empty() || conds_.back().kind != Cond::Kind::Switch || conds_.back().frame != frames_.size()) {
        fail(at, "#" + std::string(name) + " without #switch");
      }
      // A case after the one that matched: its condition is read and the tokens run on until #break.
      if (id == D::Case) {
        expression();
      } else {
        expect("(", "after #range");
        number("as the range's low end");
        expect(",", "between the range's ends");
        number("as the range's high end");
        expect(")", "after the range");
      }
      return;
    case D::Break:
      breakDirective(at);
      return;
    case D::While: {
      const size_t start = frames_.back().pos - 1;
      if (truth(expression(), at) != 0) {
        conds_.push_back({Cond::Kind::While, frames_.size(), start, {}, 0, 1});
      } else {
        skipTo(false, false);
      }
      return;
    }
    case D::For:
      forDirective(at);
      return;
    case D::Macro:
      macroDefinition(at);
      return;
    case D::Include:
      includeDirective(at);
      return;
    case D::Debug:
    case D::Warning:
    case D::Render:
    case D::Statistics: {
      const Value text = expression();
      if (text.type != Value::Type::String) fail(at, "#" + std::string(name) + " needs a string, found a " + typeName(text));
      if (options_.debug) {
        if (id == D::Warning) {
          *options_.debug << at.str() << ": warning: " << text.str() << "\n";
        } else {
          *options_.debug << text.str();
        }
      }
      return;
    }
    case D::Error: {
      const Value text = expression();
      fail(at, text.type == Value::Type::String ? text.str() : std::string("#error"));
    }
    case D::Fopen:
      fopenDirective(at);
      return;
    case D::Fclose:
      fcloseDirective();
      return;
    case D::Read:
      readDirective(at);
      return;
    case D::Write:
      writeDirective(at);
      return;
    case D::Unknown:
      break;
  }
  fail(at, "unknown directive '#" + std::string(name) + "'");
}

void Interpreter::declareDirective(bool local) {
  SourceLoc idAt;
  // The lexer has marked the keywords: no search of the keyword list for each #declare.
  bool keyword = rawPeek().keyword;
  std::string_view id = expectWord("an identifier after #declare", &idAt);
  // `#declare deprecated once "message" Name = …` warns when Name is used; the warning is not kept.
  if (id == "deprecated") {
    if (rawPeek().isWord("once")) ++frames_.back().pos;
    if (rawPeek().kind == Token::Kind::String) ++frames_.back().pos;
    keyword = rawPeek().keyword;
    id = expectWord("an identifier after #declare deprecated", &idAt);
  }
  if (keyword) fail(idAt, "'" + std::string(id) + "' is a keyword and cannot be declared");
  std::vector<double> index;
  while (rawPeek().is("[")) {
    next();
    index.push_back(number("as an array index"));
    expect("]", "after the index");
  }
  expect("=", "after the identifier");
  // #local sets the current level's identifier; #declare the innermost one of that name (a macro's parameter
  // passed by reference is the caller's identifier), or else a global one, as POV-Ray 3.7 does. The level is
  // chosen before the value is read: reading past the end of an include file leaves that file's level.
  size_t level = scopes_.size() - 1;
  if (!local) {
    while (level > 0 && !scopes_[level].symbols.count(id)) --level;
  }
  Value value = declarable();
  if (rawPeek().is(";")) ++frames_.back().pos;
  if (index.empty()) {
    if (level < scopes_.size()) assign(id, std::move(value), level);
    return;
  }
  Slot* slot = find(id);
  if (!slot || slot->value.type != Value::Type::Array) fail(idAt, "'" + std::string(id) + "' is not an array");
  auto& a = static_cast<ArrayValue&>(*slot->value.ref);
  if (index.size() != a.dims.size()) fail(idAt, "'" + std::string(id) + "' has " + std::to_string(a.dims.size()) + " dimensions");
  size_t flat = 0;
  for (size_t k = 0; k < index.size(); ++k) {
    const double i = std::floor(index[k] + kEpsilon);
    if (!(i >= 0 && i < a.dims[k])) fail(idAt, "index " + std::to_string(long(i)) + " is out of range for '" + std::string(id) + "'");
    flat = flat * size_t(a.dims[k]) + size_t(i);
  }
  a.elements[flat] = std::move(value);
}

void Interpreter::includeDirective(const SourceLoc& at) {
  holdFile_ = true;
  const Value name = expression();
  holdFile_ = false;
  if (name.type != Value::Type::String) fail(at, "#include needs a file name, found a " + std::string(typeName(name)));
  // A file the scene wrote earlier is what POV-Ray, which writes at once, would find.
  if (const DataFileDesc* data = written(name.str())) {
    texts_.push_back(std::make_unique<std::string>(data->text));
  } else {
    const std::string path = findFile(name.str());
    if (path.empty()) fail(at, "cannot find the include file " + quote(name.str()));
    texts_.push_back(std::make_unique<std::string>());
    if (!readBytes(path, *texts_.back())) fail(at, "cannot read the include file " + quote(name.str()));
  }
  pushFile(name.str(), *texts_.back(), &at);
}

std::string Interpreter::findFile(const std::string& name) {
  std::vector<std::string> candidates;
  if (!name.empty() && name[0] == '/') {
    candidates.push_back(name);
  } else {
    candidates.push_back(sceneFolder_ + name);
    for (const std::string& l : options_.libraryPaths) candidates.push_back(l + "/" + name);
    candidates.push_back(options_.standardLibrary + "/" + name);
  }
  for (const std::string& path : candidates) {
    if (isFile(path)) return found(path);
  }
  return "";
}

std::string Interpreter::findFont(const std::string& name) {
  for (const std::string& file : {name, name + ".ttf"}) {
    const std::string path = findFile(file), debian = "/usr/share/fonts/truetype/povray/" + file;
    if (!path.empty()) return path;
    if (file[0] != '/' && isFile(debian)) return found(debian);
  }
  return "";
}

std::string Interpreter::found(const std::string& path) {
  if (std::find(filesFound_.begin(), filesFound_.end(), path) == filesFound_.end()) filesFound_.push_back(path);
  return path;
}

// Removes the innermost identifier of that name, if any.
void Interpreter::undefine(std::string_view id) {
  for (size_t i = scopes_.size(); i-- > 0;) {
    if (scopes_[i].symbols.erase(id)) break;
  }
}

void Interpreter::macroDefinition(const SourceLoc& at) {
  auto def = std::make_shared<MacroDef>();
  def->name = expectWord("a name after #macro");
  if (isKeyword(def->name)) fail(at, "'" + std::string(def->name) + "' is a keyword and cannot name a macro");
  def->file = frames_.back().file;
  macroInitial_[static_cast<unsigned char>(def->name[0])] = true;
  if (!rawPeek().is("(")) fail(locOf(rawPeek()), "expected '(' after the macro's name");
  ++frames_.back().pos;
  while (!rawPeek().is(")")) {
    def->params.push_back(expectWord("a parameter name"));
    if (rawPeek().is(",")) ++frames_.back().pos;  // POV-Ray lets a comma be left out or end the list
  }
  ++frames_.back().pos;
  def->body = frames_.back().pos;
  skipTo(false, false);
  Value v;
  v.type = Value::Type::Macro;
  v.ref = def;
  auto& slot = scopes_.front().symbols[def->name];
  if (!slot) slot = std::make_shared<Slot>();
  slot->value = std::move(v);
}

void Interpreter::invokeMacro(const std::shared_ptr<MacroDef>& macro) {
  SourceLoc at = locOf(rawPeek());
  ++frames_.back().pos;
  expect("(", "after the macro's name");
  Scope scope;
  size_t n = 0;
  bool more = !peek().is(")");
  while (more) {
    const Frame& f = frames_.back();
    const Token& t = rawPeek();
    std::shared_ptr<Slot> slot;
    if (t.kind == Token::Kind::Word && !t.keyword &&
        (f.file->tokens[f.pos + 1].is(",") || f.file->tokens[f.pos + 1].is(")"))) {
      for (size_t i = scopes_.size(); i-- > 0 && !slot;) {
        const auto it = scopes_[i].symbols.find(t.text);
        if (it != scopes_[i].symbols.end()) slot = it->second;
      }
    }
    if (slot) {
      ++frames_.back().pos;
    } else {
      slot = std::make_shared<Slot>();
      slot->value = declarable();
    }
    if (n < macro->params.size()) {
      scope.symbols[macro->params[n]] = slot;
    }
    ++n;
    // As POV-Ray, a comma left out before an argument that starts a value is not missed.
    const SourceLoc sepAt = here();
    const Token& sep = peek();
    if (sep.is(")")) {
      next();
      break;
    }
    if (sep.is(",")) {
      next();
    } else if (!startsExpression(sep)) {
      fail(sepAt, "expected ',' or ')' in the arguments of macro '" + std::string(macro->name) + "'");
    }
  }
  if (!more) next();
  if (n != macro->params.size()) {
    fail(at, "macro '" + std::string(macro->name) + "' takes " + std::to_string(macro->params.size()) +
                 " arguments, found " + std::to_string(n));
  }
  if (macroDepth_ >= kMaxMacroDepth) fail(at, "macro calls nested more than " + std::to_string(kMaxMacroDepth) + " deep");
  ++macroDepth_;
  frames_.push_back({Frame::Kind::Macro, macro->file, macro->body, at, macro->name});
  scopes_.push_back(std::move(scope));
  conds_.push_back({Cond::Kind::Macro, frames_.size(), 0, {}, 0, 1});
}

void Interpreter::ifDirective(bool truth) {
  for (;;) {
    if (truth) {
      conds_.push_back({Cond::Kind::If, frames_.size(), 0, {}, 0, 1});
      return;
    }
    const std::string_view stop = skipTo(true, false);
    if (stop == "end") return;
    if (stop == "else") {
      truth = true;
    } else {
      const SourceLoc at = here();
      truth = this->truth(expression(), at) != 0;
    }
  }
}

void Interpreter::switchDirective() {
  const double value = number("after #switch");
  for (;;) {
    const std::string_view stop = skipTo(false, true);
    if (stop == "end") return;
    bool match = stop == "else";
    if (stop == "case") {
      match = std::abs(number("after #case") - value) < kEpsilon;
    } else if (stop == "range") {
      expect("(", "after #range");
      const double low = number("as the range's low end");
      expect(",", "between the range's ends");
      const double high = number("as the range's high end");
      expect(")", "after the range");
      match = value >= low && value <= high;
    }
    if (match) {
      conds_.push_back({Cond::Kind::Switch, frames_.size(), 0, {}, 0, 1});
      return;
    }
  }
}

void Interpreter::forDirective(const SourceLoc& at) {
  expect("(", "after #for");
  SourceLoc varAt;
  const std::string_view var = expectWord("the loop's identifier", &varAt);
  if (isKeyword(var)) fail(varAt, "'" + std::string(var) + "' is a keyword and cannot be declared");
  expect(",", "after the loop's identifier");
  const double start = number("as the loop's start");
  expect(",", "after the loop's start");
  const double end = number("as the loop's end");
  double step = 1;
  if (peekOperator(",")) {
    next();
    step = number("as the loop's step");
  }
  expect(")", "after the loop's range");
  if (step == 0) fail(at, "the #for loop's step is 0");
  assign(var, Value::number(start), scopes_.size() - 1);
  if (step > 0 ? start <= end + kEpsilon : start >= end - kEpsilon) {
    conds_.push_back({Cond::Kind::For, frames_.size(), frames_.back().pos, var, end, step});
  } else {
    skipTo(false, false);
  }
}

void Interpreter::endDirective(const SourceLoc& at) {
  if (conds_.empty() || conds_.back().frame != frames_.size()) fail(at, "#end without a directive to end");
  Cond& c = conds_.back();
  switch (c.kind) {
    case Cond::Kind::If:
    case Cond::Kind::Switch:
      conds_.pop_back();
      break;
    case Cond::Kind::While:
      frames_.back().pos = c.pos;
      conds_.pop_back();
      break;
    case Cond::Kind::For: {
      Slot* s = find(c.var);
      if (!s || s->value.type != Value::Type::Float) fail(at, "the #for loop's identifier is no longer a float");
      const double i = s->value.v[0] + c.step;
      s->value.v[0] = i;
      if (c.step > 0 ? i <= c.end + kEpsilon : i >= c.end - kEpsilon) {
        frames_.back().pos = c.pos;
      } else {
        conds_.pop_back();
      }
      break;
    }
    case Cond::Kind::Macro:
      conds_.pop_back();
      frames_.pop_back();
      scopes_.pop_back();
      --macroDepth_;
      break;
  }
}

void Interpreter::breakDirective(const SourceLoc& at) {
  size_t levels = 0;
  for (size_t i = conds_.size(); i-- > 0;) {
    const Cond& c = conds_[i];
    if (c.frame != frames_.size() || c.kind == Cond::Kind::Macro) break;
    ++levels;
    if (c.kind == Cond::Kind::Switch || c.kind == Cond::Kind::While || c.kind == Cond::Kind::For) {
      conds_.resize(i);
      for (size_t k = 0; k < levels; ++k) skipTo(false, false);
      return;
    }
  }
  fail(at, "#break outside #switch, #while or #for");
}

// Skips tokens, nested directives whole, up to the #end of the current level (returning "end"), or to an
// #else or #elseif, or to a #case, #range or #else, when asked. The position is then just after that directive.
std::string_view Interpreter::skipTo(bool stopAtElse, bool stopAtCase) {
  Frame& f = frames_.back();
  const SourceLoc start = locOf(f.file->tokens[f.pos == 0 ? 0 : f.pos - 1]);
  int depth = 0;
  for (;;) {
    const Token& t = f.file->tokens[f.pos];
    if (t.kind == Token::Kind::End) {
      if (f.kind == Frame::Kind::Macro) fail(f.from, "macro '" + std::string(f.name) + "' has no #end");
      fail(start, "this directive has no #end");
    }
    ++f.pos;
    if (t.kind != Token::Kind::Directive) continue;
    const std::string_view n = t.text;
    using D = DirectiveId;
    const D id = t.directiveId;
    if (id == D::If || id == D::Ifdef || id == D::Ifndef || id == D::Switch || id == D::While || id == D::For ||
        id == D::Macro) {
      ++depth;
    } else if (id == D::End) {
      if (depth == 0) return n;
      --depth;
    } else if (depth == 0 && stopAtElse && (id == D::Else || id == D::Elseif)) {
      return n;
    } else if (depth == 0 && stopAtCase && (id == D::Case || id == D::Range || id == D::Else)) {
      return n;
    }
  }
}

}  // namespace rt::povray
