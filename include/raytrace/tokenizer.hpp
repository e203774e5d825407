// The POV-subset tokenizer: numbers, words and single punctuation characters, each with its source location.
#pragma once

#include <string>
#include <vector>

#include "raytrace/error.hpp"

namespace rt {

struct Token {
  enum class Kind { Number, Word, Punct, End } kind = Kind::End;
  std::string text;    // as written in the file
  double number = 0;   // the value of a Number
  SourceLoc loc;

  // How a message quotes it: 'abc', or "end of file".
  std::string quoted() const { return kind == Kind::End ? "end of file" : "'" + text + "'"; }
};

// Splits POV text into tokens ending with one End token. Whitespace (including tabs and form feeds) and
// `//` and `/* */` comments separate tokens. Numbers are written as POV-Ray reads them: `.94`, `-.001`, `1.`,
// `-0`, `1e-05`, `+2`. Lines end at LF, CRLF or a lone CR; a tab counts as one column. Throws ParseError for an
// unterminated comment, a number out of range or a control byte.
std::vector<Token> tokenize(const std::string& text, const std::string& file);

}  // namespace rt
