// The words of a POV-Ray 3.7 scene file: numbers, strings, names, symbols and `#` directives, each with its place.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/util/error.hpp"

namespace rt::povray {

// The directives, which the lexer names once (directiveId) so that the interpreter picks each by a switch
// rather than comparing its name with every directive's in turn.
enum class DirectiveId : std::uint8_t {
  Unknown, Version, Declare, Local, Undef, Default, If, Ifdef, Ifndef, Else, Elseif, End, Switch, Case, Range,
  Break, While, For, Macro, Include, Debug, Warning, Render, Statistics, Error, Fopen, Fclose, Read, Write
};

struct Token {
  enum class Kind : std::uint8_t { Number, String, Word, Symbol, Directive, End } kind = Kind::End;
  std::string_view text;  // a word, symbol or directive name; a string's contents with escapes resolved
  double number = 0;
  std::int32_t line = 0, col = 0;
  // Found once here rather than at every use: a word reserved by POV-Ray 3.7, one that begins a value, one
  // that begins a colour (isColourWord), and which built-in constant or function a word is (builtinIndex).
  bool keyword = false;
  bool startsValue = false;
  bool colourWord = false;
  std::uint8_t builtin = 0;
  DirectiveId directiveId = DirectiveId::Unknown;  // a directive's; Unknown for any other token

  // Symbols have one or two characters: compared directly, this is most of the parser's time otherwise.
  bool is(std::string_view symbol) const {
    return kind == Kind::Symbol && text.size() == symbol.size() && text[0] == symbol[0] &&
           (symbol.size() == 1 || text[1] == symbol[1]);
  }
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

// Whether a word is one of the 3.7 keywords (which an identifier may not be), or a word that begins a colour
// (color, colour, rgb … srgbft).
bool isKeyword(std::string_view word);
bool isColourWord(std::string_view word);
// A built-in constant or function's place among them sorted by name, from 1; 0 for any other word.
std::uint8_t builtinIndex(std::string_view word);
// The directive a name after '#' is; Unknown for any other name.
DirectiveId directiveIdOf(std::string_view name);

// Splits `text` into tokens. Throws ParseError for an unterminated string or comment or a stray character.
void lex(std::string_view text, TokenFile& out);

}  // namespace rt::povray
