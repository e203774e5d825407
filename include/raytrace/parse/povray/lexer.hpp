// The words of a POV-Ray 3.7 scene file: numbers, strings, names, symbols and `#` directives, each with its place.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/util/error.hpp"

namespace rt::povray {

struct Token {
  enum class Kind : std::uint8_t { Number, String, Word, Symbol, Directive, End } kind = Kind::End;
  std::string_view text;  // a word, symbol or directive name; a string's contents with escapes resolved
  double number = 0;
  std::int32_t line = 0, col = 0;

  bool is(std::string_view symbol) const { return kind == Kind::Symbol && text == symbol; }
  bool isWord(std::string_view word) const { return kind == Kind::Word && text == word; }
};

// One file's tokens, ending with an End token. Strings with escapes own their text in `strings`, so a
// token stays valid as long as its file does; the others point into the file's text, kept alive elsewhere.
struct TokenFile {
  FileName name;
  std::vector<Token> tokens;
  std::vector<std::string> strings;

  SourceLoc loc(const Token& t) const { return {name, t.line, t.col}; }
};

// Splits `text` into tokens. Throws ParseError for an unterminated string or comment or a stray character.
void lex(std::string_view text, TokenFile& out);

}  // namespace rt::povray
