// The POV-subset tokenizer: token kinds, exact source locations, the number forms POV-Ray accepts, and the
// located errors for text it cannot read.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "raytrace/parse/tokenizer.hpp"

using rt::Token;

namespace {

using Kind = Token::Kind;

// Every token of `text`, up to and including the End token.
std::vector<Token> tokenize(const std::string& text, const std::string& file) {
  rt::Tokenizer tokenizer(text, file);
  std::vector<Token> tokens;
  do tokens.push_back(tokenizer.next());
  while (tokens.back().kind != Kind::End);
  return tokens;
}

// "kind:text@line:col" for each token, so one comparison checks kind, text and location together.
std::vector<std::string> describe(const std::string& text) {
  std::vector<std::string> out;
  for (const Token& t : tokenize(text, "t.pov")) {
    const char* kind = t.kind == Kind::Number ? "N" : t.kind == Kind::Word ? "W" : t.kind == Kind::Punct ? "P" : "E";
    out.push_back(std::string(kind) + ":" + std::string(t.text) + "@" + std::to_string(t.loc.line) + ":" +
                  std::to_string(t.loc.col));
  }
  return out;
}

double onlyNumber(const std::string& text) {
  const auto tokens = tokenize(text, "t.pov");
  REQUIRE(tokens.size() == 2);
  REQUIRE(tokens[0].kind == Kind::Number);
  CHECK(tokens[0].text == text);
  return tokens[0].number;
}

}  // namespace

TEST_CASE("tokenizer: kinds, text and the line:column of every token") {
  CHECK(describe("sphere { <0, 1.5,-2>, 3 }") ==
        std::vector<std::string>{"W:sphere@1:1", "P:{@1:8", "P:<@1:10", "N:0@1:11", "P:,@1:12", "N:1.5@1:14",
                                 "P:,@1:17", "N:-2@1:18", "P:>@1:20", "P:,@1:21", "N:3@1:23", "P:}@1:25",
                                 "E:@1:26"});
  CHECK(describe("look_at rgbf x_1") == std::vector<std::string>{"W:look_at@1:1", "W:rgbf@1:9", "W:x_1@1:14",
                                                                    "E:@1:17"});
}

TEST_CASE("tokenizer: an empty file, or one of only whitespace and comments, is one End token") {
  CHECK(describe("") == std::vector<std::string>{"E:@1:1"});
  CHECK(describe(" \n\t// c\n/* x\n */ ") == std::vector<std::string>{"E:@4:5"});
  const auto end = tokenize("", "t.pov").back();
  CHECK(end.quoted() == "end of file");
  CHECK(end.loc.file == "t.pov");
}

TEST_CASE("tokenizer: newlines anywhere, tabs count one column, CRLF and lone CR end lines") {
  CHECK(describe("sphere\n{\n  <0,\n0,0>") ==
        std::vector<std::string>{"W:sphere@1:1", "P:{@2:1", "P:<@3:3", "N:0@3:4", "P:,@3:5", "N:0@4:1", "P:,@4:2",
                                 "N:0@4:3", "P:>@4:4", "E:@4:5"});
  CHECK(describe("\ta\t\tb") == std::vector<std::string>{"W:a@1:2", "W:b@1:5", "E:@1:6"});
  CHECK(describe("a\r\nb\r\n  c") == std::vector<std::string>{"W:a@1:1", "W:b@2:1", "W:c@3:3", "E:@3:4"});
  CHECK(describe("a\rb\r\rc") == std::vector<std::string>{"W:a@1:1", "W:b@2:1", "W:c@4:1", "E:@4:2"});
  CHECK(describe("a\f\vb") == std::vector<std::string>{"W:a@1:1", "W:b@1:4", "E:@1:5"});
}

TEST_CASE("tokenizer: comments separate tokens and keep line numbers") {
  CHECK(describe("a// x { <\nb") == std::vector<std::string>{"W:a@1:1", "W:b@2:1", "E:@2:2"});
  CHECK(describe("a/* x\n y */b") == std::vector<std::string>{"W:a@1:1", "W:b@2:6", "E:@2:7"});
  CHECK(describe("a/**/b") == std::vector<std::string>{"W:a@1:1", "W:b@1:6", "E:@1:7"});
  CHECK(describe("a /* // */ b") == std::vector<std::string>{"W:a@1:1", "W:b@1:12", "E:@1:13"});
  // A `//` comment in a file with old Mac (CR-only) line endings ends at the CR, not at the file's end.
  CHECK(describe("// c\ra\r") == std::vector<std::string>{"W:a@2:1", "E:@3:1"});
  CHECK(describe("// c\r\na") == std::vector<std::string>{"W:a@2:1", "E:@2:2"});
  // A lone slash is an ordinary punctuation token; the parser rejects it in context.
  CHECK(describe("a / b") == std::vector<std::string>{"W:a@1:1", "P:/@1:3", "W:b@1:5", "E:@1:6"});
}

TEST_CASE("tokenizer: numbers in every form the course files and POV-Ray use") {
  CHECK(onlyNumber("0") == 0.0);
  CHECK(onlyNumber(".94") == 0.94);
  CHECK(onlyNumber("-.001") == -0.001);
  CHECK(onlyNumber("1.") == 1.0);
  CHECK(onlyNumber("+2") == 2.0);
  CHECK(onlyNumber("1.33333") == 1.33333);
  CHECK(onlyNumber("1e-05") == 1e-05);
  CHECK(onlyNumber("2E3") == 2000.0);
  CHECK(onlyNumber("-1.5e+2") == -150.0);
  const double negZero = onlyNumber("-0");
  CHECK(negZero == 0.0);
  CHECK(std::signbit(negZero));
}

TEST_CASE("tokenizer: where numbers end") {
  // `1e` without exponent digits is the number 1 then the word e.
  CHECK(describe("1e") == std::vector<std::string>{"N:1@1:1", "W:e@1:2", "E:@1:3"});
  CHECK(describe("1.2.3") == std::vector<std::string>{"N:1.2@1:1", "N:.3@1:4", "E:@1:6"});
  CHECK(describe("<1,-2>") == std::vector<std::string>{"P:<@1:1", "N:1@1:2", "P:,@1:3", "N:-2@1:4", "P:>@1:6",
                                                         "E:@1:7"});
  // A sign or dot that no digit follows is punctuation.
  CHECK(describe("- .x") == std::vector<std::string>{"P:-@1:1", "P:.@1:3", "W:x@1:4", "E:@1:5"});
  CHECK(describe("2x") == std::vector<std::string>{"N:2@1:1", "W:x@1:2", "E:@1:3"});
}

TEST_CASE("tokenizer: located errors") {
  CHECK_THROWS_WITH(tokenize("a\n  /* never\n closed", "s.pov"), "s.pov:2:3: error: comment '/*' is never closed");
  CHECK_THROWS_WITH(tokenize("a /*/", "s.pov"), "s.pov:1:3: error: comment '/*' is never closed");
  CHECK_THROWS_WITH(tokenize("x 1e999", "s.pov"), "s.pov:1:3: error: number '1e999' is out of range");
  CHECK_THROWS_WITH(tokenize("x -1e999", "s.pov"), "s.pov:1:3: error: number '-1e999' is out of range");
  CHECK_THROWS_WITH(tokenize("a\n b\x01", "s.pov"),
                    "s.pov:2:3: error: unexpected byte 0x01 (is this a text scene file?)");
  CHECK_THROWS_WITH(tokenize(std::string("a\0b", 3), "s.pov"),
                    "s.pov:1:2: error: unexpected byte 0x00 (is this a text scene file?)");
  CHECK_THROWS_WITH(tokenize("\x89PNG", "s.pov"), "s.pov:1:1: error: unexpected byte 0x89 (is this a text scene file?)");
  CHECK_THROWS_AS(tokenize("\x7f", "s.pov"), rt::ParseError);
  const std::string digits = "1" + std::string(400, '0') + ".5";
  // Quoted cut, as every long piece of input is (message.hpp).
  CHECK_THROWS_WITH(tokenize(digits, "s.pov"),
                    "s.pov:1:1: error: number '" + digits.substr(0, 60) + "...' is out of range");
}

TEST_CASE("tokenizer: bytes inside comments are never inspected") {
  CHECK(describe("// \x01\x89\xff\na") == std::vector<std::string>{"W:a@2:1", "E:@2:2"});
  CHECK(describe(std::string("/* \0 */a", 8)) == std::vector<std::string>{"W:a@1:8", "E:@1:9"});
}

TEST_CASE("tokenizer: nan and inf are words, never numbers; an underflow reads as zero, as in POV-Ray") {
  CHECK(describe("nan inf NaN infinity") ==
        std::vector<std::string>{"W:nan@1:1", "W:inf@1:5", "W:NaN@1:9", "W:infinity@1:13", "E:@1:21"});
  CHECK(onlyNumber("1e-999") == 0.0);
}

TEST_CASE("tokenizer: after the text, End again as often as asked, at the same place") {
  const std::string text = "x\n";
  rt::Tokenizer tokenizer(text, "t.pov");
  CHECK(tokenizer.next().text == "x");
  for (int i = 0; i < 3; ++i) {
    const Token end = tokenizer.next();
    CHECK(end.kind == Kind::End);
    CHECK(end.loc.str() == "t.pov:2:1");
  }
}

TEST_CASE("tokenizer: a seeded sweep of number-like text reads each number as strtod does, to where it stops") {
  // strtod is an independent reader of the same form: an optional sign, then digits with at most one point and
  // an exponent only if digits follow. On these characters it converts exactly where a number token starts.
  const std::string alphabet = "0123456789.eE+-";
  std::mt19937 rng(473);
  for (int k = 0; k < 20000; ++k) {
    std::string text(size_t(1 + rng() % 12), ' ');
    for (char& c : text) c = alphabet[rng() % alphabet.size()];
    CAPTURE(text);
    char* end = nullptr;
    const double expected = std::strtod(text.c_str(), &end);
    const size_t length = size_t(end - text.c_str());
    rt::Tokenizer tokenizer(text, "t.pov");
    if (length == 0) {
      CHECK(tokenizer.next().kind != Kind::Number);
    } else if (!std::isfinite(expected)) {
      CHECK_THROWS_WITH(tokenizer.next(),
                        "t.pov:1:1: error: number '" + text.substr(0, length) + "' is out of range");
    } else {
      const Token t = tokenizer.next();
      CHECK(t.kind == Kind::Number);
      CHECK(t.text == text.substr(0, length));
      CHECK(t.number == expected);
      CHECK(std::signbit(t.number) == std::signbit(expected));
    }
  }
}
