#include "raytrace/tokenizer.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rt {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isWordStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isWordChar(char c) { return isWordStart(c) || isDigit(c); }

class Lexer {
 public:
  Lexer(const std::string& text, const std::string& file) : s_(text), file_(file) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    for (;;) {
      skipSpaceAndComments();
      Token t;
      t.loc = here();
      if (i_ >= s_.size()) {
        tokens.push_back(t);
        return tokens;
      }
      const char c = s_[i_];
      if (startsNumber()) {
        lexNumber(t);
      } else if (isWordStart(c)) {
        t.kind = Token::Kind::Word;
        while (i_ < s_.size() && isWordChar(s_[i_])) t.text += s_[i_], advance();
      } else if (std::isprint(static_cast<unsigned char>(c))) {
        t.kind = Token::Kind::Punct;
        t.text = c;
        advance();
      } else {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(c));
        throw ParseError(t.loc, std::string("unexpected byte ") + hex + " (is this a text scene file?)");
      }
      tokens.push_back(t);
    }
  }

 private:
  SourceLoc here() const { return SourceLoc{file_, line_, col_}; }
  char peek(size_t k = 0) const { return i_ + k < s_.size() ? s_[i_ + k] : '\0'; }
  // A line ends at LF, CRLF or a lone CR (old Mac files, which POV-Ray reads too).
  bool endsLine() const { return s_[i_] == '\n' || (s_[i_] == '\r' && peek(1) != '\n'); }
  void advance() {
    if (endsLine()) {
      ++line_;
      col_ = 1;
    } else {
      ++col_;
    }
    ++i_;
  }

  void skipSpaceAndComments() {
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
        advance();
      } else if (c == '/' && peek(1) == '/') {
        while (i_ < s_.size() && !endsLine()) advance();
      } else if (c == '/' && peek(1) == '*') {
        const SourceLoc start = here();
        advance(), advance();
        while (i_ < s_.size() && !(s_[i_] == '*' && peek(1) == '/')) advance();
        if (i_ >= s_.size()) throw ParseError(start, "comment '/*' is never closed");
        advance(), advance();
      } else {
        return;
      }
    }
  }

  // A number starts with a digit, or a '.' followed by one, optionally after one sign.
  bool startsNumber() const {
    size_t k = 0;
    if (peek() == '-' || peek() == '+') k = 1;
    return isDigit(peek(k)) || (peek(k) == '.' && isDigit(peek(k + 1)));
  }

  void lexNumber(Token& t) {
    t.kind = Token::Kind::Number;
    auto take = [&] { t.text += s_[i_], advance(); };
    if (peek() == '-' || peek() == '+') take();
    while (isDigit(peek())) take();
    if (peek() == '.') take();
    while (isDigit(peek())) take();
    // An exponent only if digits follow, so that `1e` stays a number and a word.
    if ((peek() == 'e' || peek() == 'E') &&
        (isDigit(peek(1)) || ((peek(1) == '-' || peek(1) == '+') && isDigit(peek(2))))) {
      take(), take();
      while (isDigit(peek())) take();
    }
    t.number = std::strtod(t.text.c_str(), nullptr);
    if (!std::isfinite(t.number)) throw ParseError(t.loc, "number '" + t.text + "' is out of range");
  }

  const std::string& s_;
  FileName file_;  // shared by the location of every token
  size_t i_ = 0;
  int line_ = 1, col_ = 1;
};

}  // namespace

std::vector<Token> tokenize(const std::string& text, const std::string& file) {
  return Lexer(text, file).run();
}

}  // namespace rt
