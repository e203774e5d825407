// The POV-subset tokenizer: numbers, words and single punctuation characters, each with its source location.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"

namespace rt {

struct Token {
  enum class Kind { Number, Word, Punct, End } kind = Kind::End;
  std::string_view text;  // as written, inside the text the tokenizer reads
  double number = 0;      // the value of a Number
  SourceLoc loc;

  // How a message quotes it: 'abc' (a long one cut, message.hpp), or "end of file".
  std::string quoted() const { return kind == Kind::End ? "end of file" : quote(text); }
};

// Splits POV text into tokens, one at a time, so that a huge scene never holds more than one token in memory
// (a million-sphere file would otherwise need gigabytes of tokens). Whitespace (including tabs and form feeds)
// and `//` and `/* */` comments separate tokens. Numbers are written as POV-Ray reads them: `.94`, `-.001`,
// `1.`, `-0`, `1e-05`, `+2`. Lines end at LF, CRLF or a lone CR; a tab counts as one column. next() throws
// ParseError for an unterminated comment, a number out of range or a byte that cannot be in a text file.
class Tokenizer {
 public:
  // `text` must outlive the tokenizer and its tokens, so a temporary string is refused at compile time.
  // `firstLine` is the line `text` starts on, when it is a part of a file that starts a line.
  Tokenizer(std::string_view text, const std::string& file, int firstLine = 1)
      : s_(text), file_(file), line_(firstLine) {}
  Tokenizer(std::string&& text, const std::string& file, int firstLine = 1) = delete;

  // The next token; at the end of the text an End token, as often as asked.
  Token next();

 private:
  // No token holds a line end, so a column is the distance from the start of the line: it is worked out when
  // a location is made, not counted character by character.
  SourceLoc here() const { return SourceLoc{file_, line_, int(i_ - lineStart_) + 1}; }
  char peek(size_t k = 0) const { return i_ + k < s_.size() ? s_[i_ + k] : '\0'; }
  // Steps over the CR or LF at i_. A line ends at LF, CRLF or a lone CR (old Mac files, which POV-Ray reads too).
  void lineBreak();
  void skipSpaceAndComments();
  bool startsNumber() const;

  std::string_view s_;
  FileName file_;  // shared by the location of every token
  size_t i_ = 0;
  size_t lineStart_ = 0;  // where the current line starts in s_
  int line_;
};

}  // namespace rt
