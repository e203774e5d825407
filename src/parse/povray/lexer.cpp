#include "raytrace/parse/povray/lexer.hpp"

#include <cctype>
#include <cstdlib>

namespace rt::povray {

namespace {

bool wordStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool wordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return c >= '0' && c <= '9'; }

class Lexer {
 public:
  Lexer(std::string_view text, TokenFile& out) : s_(text), out_(out) {}

  void run() {
    // Pointers into `strings` must not move: reserve once, sized by the quotes of the file.
    size_t quotes = 0;
    for (char c : s_) quotes += c == '"';
    out_.strings.reserve(quotes / 2 + 1);
    for (;;) {
      skipBlank();
      Token t;
      t.line = line_;
      t.col = col();
      if (i_ >= s_.size()) {
        out_.tokens.push_back(t);
        return;
      }
      const char c = s_[i_];
      if (wordStart(c)) {
        t.kind = Token::Kind::Word;
        t.text = word();
        t.keyword = isKeyword(t.text);
        t.builtin = t.keyword ? builtinIndex(t.text) : 0;
        t.colourWord = isColourWord(t.text);
        t.startsValue = !t.keyword || t.builtin != 0 || t.colourWord;
      } else if (digit(c) || (c == '.' && i_ + 1 < s_.size() && digit(s_[i_ + 1]))) {
        t.kind = Token::Kind::Number;
        t.number = number();
      } else if (c == '"') {
        t.kind = Token::Kind::String;
        t.text = string(t);
      } else if (c == '#') {
        ++i_;
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t')) ++i_;
        if (i_ >= s_.size() || !wordStart(s_[i_])) continue;  // a lone '#', which POV-Ray passes over
        t.kind = Token::Kind::Directive;
        t.text = word();
        t.directiveId = directiveIdOf(t.text);
      } else {
        t.kind = Token::Kind::Symbol;
        const std::string_view two = s_.substr(i_, 2);
        if (two == "<=" || two == ">=" || two == "!=") {
          t.text = two;
          i_ += 2;
        } else if (std::string_view("{}()[]<>,;+-*/=!?:.&|").find(c) != std::string_view::npos) {
          t.text = s_.substr(i_++, 1);
        } else {
          fail(t, "unexpected character " + quote(s_.substr(i_, 1)));
        }
      }
      out_.tokens.push_back(t);
    }
  }

 private:
  int col() const { return int(i_ - lineStart_) + 1; }

  [[noreturn]] void fail(const Token& at, const std::string& message) {
    throw ParseError({out_.name, at.line, at.col}, message);
  }

  void newline() {
    ++line_;
    lineStart_ = i_ + 1;
  }

  // Spaces and comments; block comments nest, as POV-Ray's do.
  void skipBlank() {
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '\n') {
        newline();
        ++i_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++i_;
      } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '/') {
        while (i_ < s_.size() && s_[i_] != '\n') ++i_;
      } else if (c == '/' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
        Token at;
        at.line = line_;
        at.col = col();
        int depth = 0;
        do {
          if (i_ + 1 >= s_.size()) fail(at, "this comment is not closed");
          if (s_[i_] == '/' && s_[i_ + 1] == '*') {
            ++depth;
            i_ += 2;
          } else if (s_[i_] == '*' && s_[i_ + 1] == '/') {
            --depth;
            i_ += 2;
          } else {
            if (s_[i_] == '\n') newline();
            ++i_;
          }
        } while (depth > 0);
      } else {
        return;
      }
    }
  }

  std::string_view word() {
    const size_t start = i_;
    while (i_ < s_.size() && wordChar(s_[i_])) ++i_;
    return s_.substr(start, i_ - start);
  }

  double number() {
    const size_t start = i_;
    while (i_ < s_.size() && digit(s_[i_])) ++i_;
    if (i_ < s_.size() && s_[i_] == '.') {
      ++i_;
      while (i_ < s_.size() && digit(s_[i_])) ++i_;
    }
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      size_t j = i_ + 1;
      if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
      if (j < s_.size() && digit(s_[j])) {
        i_ = j;
        while (i_ < s_.size() && digit(s_[i_])) ++i_;
      }
    }
    return std::strtod(std::string(s_.substr(start, i_ - start)).c_str(), nullptr);
  }

  std::string_view string(const Token& at) {
    ++i_;
    const size_t start = i_;
    bool escapes = false;
    while (i_ < s_.size() && s_[i_] != '"') {
      if (s_[i_] == '\n') newline();  // a string may go on over lines
      if (s_[i_] == '\\' && i_ + 1 < s_.size()) {
        escapes = true;
        ++i_;
      }
      ++i_;
    }
    if (i_ >= s_.size()) fail(at, "this string is not closed");
    const std::string_view raw = s_.substr(start, i_ - start);
    ++i_;
    if (!escapes) return raw;
    std::string text;
    for (size_t k = 0; k < raw.size(); ++k) {
      if (raw[k] != '\\' || k + 1 == raw.size()) {
        text += raw[k];
        continue;
      }
      const char e = raw[++k];
      switch (e) {
        case 'n': text += '\n'; break;
        case 't': text += '\t'; break;
        case 'r': text += '\r'; break;
        case 'a': text += '\a'; break;
        case 'b': text += '\b'; break;
        case 'f': text += '\f'; break;
        case 'v': text += '\v'; break;
        case '0': text += '\0'; break;
        case '\\': case '"': case '\'': text += e; break;
        default: text += '\\'; text += e; break;  // kept as written, as POV-Ray does (a Windows path)
      }
    }
    out_.strings.push_back(std::move(text));
    return out_.strings.back();
  }

  std::string_view s_;
  TokenFile& out_;
  size_t i_ = 0, lineStart_ = 0;
  int line_ = 1;
};

}  // namespace

void lex(std::string_view text, TokenFile& out) { Lexer(text, out).run(); }

}  // namespace rt::povray
