// #fopen, #fclose, #read and #write. Written text stays in memory (dataFiles_) until the scene has parsed, so a
// scene that fails leaves no file behind; a file written earlier in the parse is read from there.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>

#include <sys/stat.h>

#include "interpreter_state.hpp"
#include "raytrace/util/limits.hpp"
#include "raytrace/util/path.hpp"

namespace rt::povray {

namespace {

// POV-Ray writes floats with printf's %g, and vectors as <x,y,z> followed by a space.
std::string formatG(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

// The binary words of #write: `uint8` … `sint32le`, their size in bytes, signedness and byte order.
struct BinaryWord {
  std::string_view name;
  int bytes;
  bool sign, big;
};
constexpr BinaryWord kBinaryWords[] = {{"uint8", 1, false, false},    {"sint8", 1, true, false},
                                       {"uint16be", 2, false, true},  {"uint16le", 2, false, false},
                                       {"sint16be", 2, true, true},   {"sint16le", 2, true, false},
                                       {"sint32be", 4, true, true},   {"sint32le", 4, true, false}};

// x rounded to the nearest integer the word holds, in its bytes.
std::string binaryWord(double x, const BinaryWord& w) {
  const double range = std::pow(2.0, 8.0 * w.bytes);
  const double low = w.sign ? -range / 2 : 0, high = (w.sign ? range / 2 : range) - 1;
  const auto n = std::uint32_t(std::int64_t(std::fmin(std::fmax(std::round(x), low), high)));
  std::string out;
  for (int i = 0; i < w.bytes; ++i) out += char((n >> (8 * (w.big ? w.bytes - 1 - i : i))) & 0xFF);
  return out;
}

}  // namespace

// Where a file the scene names for writing goes: into the output image's folder.
std::string Interpreter::writePath(const std::string& name) const {
  return options_.writeFolder.empty() || name[0] == '/' ? name : options_.writeFolder + "/" + name;
}

// The file the scene has written under that name so far, if any.
const DataFileDesc* Interpreter::written(const std::string& name) const {
  if (name.empty()) return nullptr;
  const std::string path = writePath(name);
  for (const DataFileDesc& d : dataFiles_) {
    if (d.path == path) return &d;
  }
  return nullptr;
}

void Interpreter::fopenDirective(const SourceLoc& at) {
  SourceLoc idAt;
  const std::string_view id = expectWord("a file identifier after #fopen", &idAt);
  if (isKeyword(id)) fail(idAt, "'" + std::string(id) + "' is a keyword and cannot be declared");
  const SourceLoc nameAt = here();
  const Value name = expression();
  if (name.type != Value::Type::String) fail(nameAt, "#fopen needs a file name, found a " + std::string(typeName(name)));
  if (name.str().empty()) fail(nameAt, "#fopen needs a file name, found an empty string");
  SourceLoc modeAt;
  const std::string_view mode = expectWord("read, write or append after the file name", &modeAt);
  auto file = std::make_shared<OpenFile>();
  if (mode == "read") {
    file->reading = true;
    if (const DataFileDesc* data = written(name.str())) {
      file->text = data->text;
    } else {
      const std::string path = findFile(name.str());
      if (path.empty()) fail(nameAt, "cannot find the file " + quote(name.str()) + " to read");
      if (!readBytes(path, file->text)) fail(nameAt, "cannot read the file " + quote(name.str()));
    }
    file->tokens.name = name.str();
    try {
      lex(file->text, file->tokens);
    } catch (const ParseError& e) {
      const std::string what = e.what();
      failInData(e.loc(), what.substr(what.find(": error: ") + 9), at);
    }
  } else if (mode == "write" || mode == "append") {
    // A scene from someone else must not create or replace files elsewhere unless the user says so.
    const std::string folder = options_.writeFolder.empty() ? "." : options_.writeFolder;
    if (!options_.writeAnywhere && !staysInFolder(name.str())) {
      fail(nameAt, "#fopen may only write a file in the folder of the output image and below, found " + quote(name.str()) +
                       " (--allow-write-anywhere allows it)");
    }
    if (!options_.writeAnywhere && linksOut(folder, name.str())) {
      fail(nameAt, "#fopen names " + quote(name.str()) + ", but a folder on its way is a symbolic link out of the folder "
                   "of the output image (--allow-write-anywhere allows it)");
    }
    const DataFileDesc* data = written(name.str());
    file->data = data ? size_t(data - dataFiles_.data()) : dataFiles_.size();
    if (!data) {
      dataFiles_.push_back({writePath(name.str()), at, {}});
      // Appending keeps what the file held: it is read now and written back whole with the new text.
      struct stat st;
      const std::string& path = dataFiles_.back().path;
      if (mode == "append" && stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
        if (bytesWritten_ + std::uint64_t(st.st_size) > kMaxSceneWriteBytes) {
          fail(nameAt, "the file " + quote(name.str()) + " to append to is larger than the " +
                           std::to_string(kMaxSceneWriteBytes >> 20) + " MiB a scene may write");
        }
        if (!readBytes(path, dataFiles_.back().text)) fail(nameAt, "cannot read " + quote(name.str()) + " to append to it");
        bytesWritten_ += dataFiles_.back().text.size();
      }
    } else if (mode == "write") {
      dataFiles_[file->data].text.clear();
    }
  } else {
    fail(modeAt, "expected read, write or append after the file name, found " + quote(mode));
  }
  // The file identifier is always global, as in POV-Ray.
  Value handle;
  handle.type = Value::Type::File;
  handle.ref = file;
  assign(id, std::move(handle), 0);
}

void Interpreter::fcloseDirective() {
  SourceLoc idAt;
  const std::string_view id = expectWord("a file identifier after #fclose", &idAt);
  const Slot* slot = find(id);
  if (!slot) return;  // POV-Ray closes a file that is not open without a word
  if (slot->value.type != Value::Type::File) {
    fail(idAt, "'" + std::string(id) + "' is a " + typeName(slot->value) + ", not a file #fopen opened");
  }
  undefine(id);
}

// `( Id` at the start of #read or #write: the open file the identifier names, in the mode the directive needs.
std::shared_ptr<Interpreter::OpenFile> Interpreter::fileHandle(const char* directive, bool reading,
                                                               std::string_view* id) {
  expect("(", (std::string("after ") + directive).c_str());
  SourceLoc idAt;
  *id = expectWord("a file identifier", &idAt);
  const Slot* slot = find(*id);
  if (!slot) fail(idAt, "undeclared identifier '" + std::string(*id) + "'");
  if (slot->value.type != Value::Type::File) {
    fail(idAt, "'" + std::string(*id) + "' is a " + typeName(slot->value) + ", not a file #fopen opened");
  }
  auto file = std::static_pointer_cast<OpenFile>(slot->value.ref);
  if (file->reading != reading) {
    fail(idAt, std::string(directive) + " needs a file opened for " + (reading ? "read" : "write or append") +
                   ", but '" + std::string(*id) + "' is opened for " + (reading ? "writing" : "reading"));
  }
  return file;
}

void Interpreter::readDirective(const SourceLoc& at) {
  std::string_view id;
  const std::shared_ptr<OpenFile> file = fileHandle("#read", true, &id);
  const auto atEnd = [&] { return file->tokens.tokens[file->pos].kind == Token::Kind::End; };
  // Past the end of the file it is closed and its identifier undefined (defined(Id) tells), and the identifiers
  // still to read keep what they held, as in POV-Ray.
  bool open = true;
  if (atEnd()) {
    undefine(id);
    open = false;
  }
  for (;;) {
    if (rawPeek().is(",")) ++frames_.back().pos;
    if (rawPeek().is(")")) break;
    SourceLoc varAt;
    const std::string_view var = expectWord("an identifier to read into", &varAt);
    if (isKeyword(var)) fail(varAt, "'" + std::string(var) + "' is a keyword and cannot be declared");
    if (!open) continue;
    Value value = dataValue(*file, at);
    if (Slot* slot = find(var)) {
      slot->value = std::move(value);
    } else {
      assign(var, std::move(value), 0);
    }
    if (file->tokens.tokens[file->pos].is(",")) ++file->pos;
    if (atEnd()) {
      undefine(id);
      open = false;
    }
  }
  ++frames_.back().pos;
}

// A float, vector or string of a data file: literals only, with signs on the numbers.
Value Interpreter::dataValue(OpenFile& file, const SourceLoc& at) {
  const auto token = [&]() -> const Token& { return file.tokens.tokens[file.pos]; };
  const auto expected = [&](const std::string& what) {
    const Token& t = token();
    const std::string found = t.kind == Token::Kind::End ? "the end of the file" : quote(t.text);
    failInData(file.tokens.loc(t), "expected " + what + ", found " + found, at);
  };
  const auto signedNumber = [&](const std::string& what) {
    double sign = 1;
    for (; token().is("-") || token().is("+"); ++file.pos) sign = token().is("-") ? -sign : sign;
    if (token().kind != Token::Kind::Number) expected(what);
    return sign * file.tokens.tokens[file.pos++].number;
  };
  if (token().kind == Token::Kind::String) return Value::string(std::string(file.tokens.tokens[file.pos++].text));
  if (!token().is("<")) return Value::number(signedNumber("a float, a vector or a string"));
  ++file.pos;
  std::array<double, 5> c{};
  int n = 0;
  for (;;) {
    c[n++] = signedNumber("a number in the vector");
    if (token().is(",")) ++file.pos;
    if (token().is(">")) break;
    if (n == 5) expected("'>' after the vector's fifth component");
  }
  ++file.pos;
  if (n < 2) failInData(file.tokens.loc(token()), "a vector has 2 to 5 components, found 1", at);
  return Value::vector(c, n);
}

// An error at `loc` in a file #read reads, with the #read or #fopen at `at` and how the scene got there.
void Interpreter::failInData(const SourceLoc& loc, const std::string& message, const SourceLoc& at) const {
  const std::string more = chain();
  throw ParseError(loc, message + " (read at " + at.str() + (more.empty() ? ")" : ", " + more.substr(2)));
}

void Interpreter::writeDirective(const SourceLoc& at) {
  std::string_view id;
  const std::shared_ptr<OpenFile> file = fileHandle("#write", false, &id);
  const BinaryWord* word = nullptr;  // a binary word applies up to the next comma
  for (;;) {
    const Token& t = peek();
    if (t.is(")")) break;
    if (t.is(",")) {
      next();
      word = nullptr;
      continue;
    }
    if (t.kind == Token::Kind::Word) {
      const auto w = std::find_if(std::begin(kBinaryWords), std::end(kBinaryWords),
                                  [&](const BinaryWord& b) { return b.name == t.text; });
      if (w != std::end(kBinaryWords)) {
        next();
        word = w;
        continue;
      }
    }
    const SourceLoc itemAt = here();
    const Value v = expression();
    std::string text;
    if (v.type == Value::Type::String && !word) {
      text = v.str();
    } else if (v.type == Value::Type::Float || v.type == Value::Type::Vector) {
      const int n = v.type == Value::Type::Float ? 1 : v.size;
      for (int i = 0; i < n; ++i) {
        text += word ? binaryWord(v.v[i], *word) : (i == 0 ? "" : ",") + formatG(v.v[i]);
      }
      if (v.type == Value::Type::Vector && !word) text = "<" + text + "> ";
    } else {
      const char* what = word ? "floats and vectors as binary words" : "floats, vectors and strings";
      fail(itemAt, std::string("#write writes ") + what + ", found a " + typeName(v));
    }
    if (bytesWritten_ + text.size() > kMaxSceneWriteBytes) {
      fail(at, "#write writes more than the " + std::to_string(kMaxSceneWriteBytes >> 20) + " MiB a scene may write");
    }
    bytesWritten_ += text.size();
    dataFiles_[file->data].text += text;
  }
  next();
}

}  // namespace rt::povray
