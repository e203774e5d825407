#include "raytrace/tokenizer.hpp"

#include <string>
#include <vector>

#include <catch2/catch.hpp>

using rt::Token;

namespace {

std::vector<Token> all(const std::string& text) {
  rt::Tokenizer tokenizer(text, "t.pov");
  std::vector<Token> tokens;
  do tokens.push_back(tokenizer.next());
  while (tokens.back().kind != Token::Kind::End);
  return tokens;
}

std::string errorOf(const std::string& text) {
  try {
    all(text);
  } catch (const rt::ParseError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("numbers are read as POV-Ray writes them", "[tokenizer]") {
  const auto t = all(".94 -.001 1. -0 1e-05 +2 2.5E+3");
  const std::vector<double> want{0.94, -0.001, 1.0, -0.0, 1e-05, 2.0, 2500.0};
  REQUIRE(t.size() == want.size() + 1);
  for (size_t i = 0; i < want.size(); ++i) {
    CAPTURE(i);
    CHECK(t[i].kind == Token::Kind::Number);
    CHECK(t[i].number == want[i]);
  }
  CHECK(t[1].text == "-.001");
}

TEST_CASE("an exponent needs digits, so `1e` is a number then a word", "[tokenizer]") {
  const auto t = all("1e x");
  REQUIRE(t.size() == 4);
  CHECK(t[0].number == 1.0);
  CHECK(t[1].kind == Token::Kind::Word);
  CHECK(t[1].text == "e");
  CHECK(t[1].loc.col == 2);
}

TEST_CASE("numbers beyond double range are located errors", "[tokenizer]") {
  CHECK(errorOf("<1, 1e999>") == "t.pov:1:5: error: number '1e999' is out of range");
  CHECK(errorOf("\n  -1e400") == "t.pov:2:3: error: number '-1e400' is out of range");
  const std::string digits = "1" + std::string(400, '0') + ".5";
  CHECK(errorOf(digits) == "t.pov:1:1: error: number '" + digits + "' is out of range");
}

TEST_CASE("an underflowing number reads as zero, as in POV-Ray", "[tokenizer]") {
  const auto t = all("1e-999");
  CHECK(t[0].number == 0.0);
}

TEST_CASE("nan and inf are words, never numbers", "[tokenizer]") {
  for (const char* text : {"nan", "inf", "NaN", "infinity"}) {
    CAPTURE(text);
    CHECK(all(text)[0].kind == Token::Kind::Word);
  }
}

TEST_CASE("a byte that cannot be in a text file is a located error", "[tokenizer]") {
  CHECK(errorOf("a\n b\x7F") == "t.pov:2:3: error: unexpected byte 0x7F (is this a text scene file?)");
  CHECK(errorOf(std::string("x \0", 3)) == "t.pov:1:3: error: unexpected byte 0x00 (is this a text scene file?)");
}

TEST_CASE("an unclosed block comment is located at its start", "[tokenizer]") {
  CHECK(errorOf("a /* b\n c") == "t.pov:1:3: error: comment '/*' is never closed");
}

TEST_CASE("comments and every kind of whitespace separate tokens", "[tokenizer]") {
  const auto t = all("a//x\r\n\tb/* y\n */c\f\vd");
  REQUIRE(t.size() == 5);
  CHECK(t[1].text == "b");
  CHECK(t[1].loc.line == 2);
  CHECK(t[1].loc.col == 2);
  CHECK(t[2].text == "c");
  CHECK(t[2].loc.line == 3);
  CHECK(t[3].text == "d");
}

TEST_CASE("the end of the text is an End token, as often as asked", "[tokenizer]") {
  const std::string text = "x";
  rt::Tokenizer tokenizer(text, "t.pov");
  tokenizer.next();
  for (int i = 0; i < 3; ++i) {
    const Token end = tokenizer.next();
    CHECK(end.kind == Token::Kind::End);
    CHECK(end.quoted() == "end of file");
    CHECK(end.loc.str() == "t.pov:1:2");
  }
}
