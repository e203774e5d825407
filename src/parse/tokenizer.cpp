#include "raytrace/parse/tokenizer.hpp"

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
    // from_chars reads the longest number written as strtod reads one: after a sign, digits with at most one
    // point and an exponent only if digits follow, so `1e` stays a number and a word. That is POV-Ray's form;
    // from_chars takes no leading '+', so one is stepped over. It is correctly rounded like strtod and several
    // times faster (a big scene is mostly numbers), but calls an underflow out of range: those few go to strtod.
    t.kind = Token::Kind::Number;
    const char* first = s_.data() + i_ + (c == '+');
    const auto [end, error] = std::from_chars(first, s_.data() + s_.size(), t.number);
    i_ = size_t(end - s_.data());
    t.text = s_.substr(start, i_ - start);
    if (error != std::errc()) t.number = std::strtod(std::string(t.text).c_str(), nullptr);
    if (!std::isfinite(t.number)) throw ParseError(t.loc, "number " + t.quoted() + " is out of range");
    return t;
  }
  if (isWordStart(c)) {
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
  t.text = s_.substr(start, i_ - start);
  return t;
}

void Tokenizer::lineBreak() {
  if (s_[i_] == '\r' && peek(1) == '\n') {
    ++i_;  // the LF after it ends the line
    return;
  }
  ++i_;
  ++line_;
  lineStart_ = i_;
}

void Tokenizer::skipSpaceAndComments() {
  const auto isBreak = [](char c) { return c == '\n' || c == '\r'; };
  while (i_ < s_.size()) {
    const char c = s_[i_];
    if (c == ' ' || c == '\t' || c == '\f' || c == '\v') {
      ++i_;
    } else if (isBreak(c)) {
      lineBreak();
    } else if (c == '/' && peek(1) == '/') {
      while (i_ < s_.size() && !isBreak(s_[i_])) ++i_;
    } else if (c == '/' && peek(1) == '*') {
      const SourceLoc start = here();
      for (i_ += 2; i_ < s_.size() && !(s_[i_] == '*' && peek(1) == '/');) {
        if (isBreak(s_[i_])) {
          lineBreak();
        } else {
          ++i_;
        }
      }
      if (i_ >= s_.size()) throw ParseError(start, "comment '/*' is never closed");
      i_ += 2;
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

}  // namespace rt
