#include "raytrace/tokenizer.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rt {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isWordStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isWordChar(char c) { return isWordStart(c) || isDigit(c); }

}  // namespace

Token Tokenizer::next() {
  skipSpaceAndComments();
  Token t;
  t.loc = here();
  if (i_ >= s_.size()) return t;
  const size_t start = i_;
  const char c = s_[i_];
  if (startsNumber()) {
    t.kind = Token::Kind::Number;
    lexNumber();
  } else if (isWordStart(c)) {
    t.kind = Token::Kind::Word;
    while (i_ < s_.size() && isWordChar(s_[i_])) ++i_;
  } else if (std::isprint(static_cast<unsigned char>(c))) {
    t.kind = Token::Kind::Punct;
    ++i_;
  } else {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(c));
    throw ParseError(t.loc, std::string("unexpected byte ") + hex + " (is this a text scene file?)");
  }
  // No token holds a line end, so its characters all stand on the line it starts.
  col_ += int(i_ - start);
  t.text = s_.substr(start, i_ - start);
  if (t.kind == Token::Kind::Number) {
    // from_chars is correctly rounded like strtod and several times faster (a big scene is mostly numbers); it
    // takes no '+' and calls an underflow out of range, so those few go to strtod.
    const char* first = t.text.data() + (t.text[0] == '+');
    const char* last = t.text.data() + t.text.size();
    const auto [end, error] = std::from_chars(first, last, t.number);
    if (error != std::errc() || end != last) t.number = std::strtod(std::string(t.text).c_str(), nullptr);
    if (!std::isfinite(t.number)) throw ParseError(t.loc, "number " + t.quoted() + " is out of range");
  }
  return t;
}

// Only ever called inside the text.
void Tokenizer::advance() {
  if (endsLine()) {
    ++line_;
    col_ = 1;
  } else {
    ++col_;
  }
  ++i_;
}

void Tokenizer::skipSpaceAndComments() {
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
bool Tokenizer::startsNumber() const {
  size_t k = 0;
  if (peek() == '-' || peek() == '+') k = 1;
  return isDigit(peek(k)) || (peek(k) == '.' && isDigit(peek(k + 1)));
}

void Tokenizer::lexNumber() {
  if (peek() == '-' || peek() == '+') ++i_;
  while (isDigit(peek())) ++i_;
  if (peek() == '.') ++i_;
  while (isDigit(peek())) ++i_;
  // An exponent only if digits follow, so that `1e` stays a number and a word.
  if ((peek() == 'e' || peek() == 'E') &&
      (isDigit(peek(1)) || ((peek(1) == '-' || peek(1) == '+') && isDigit(peek(2))))) {
    i_ += 2;
    while (isDigit(peek())) ++i_;
  }
}

}  // namespace rt
