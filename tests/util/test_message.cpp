// How messages show input: escaped, cut, and repeated lines counted once.
#include <catch2/catch.hpp>

#include "raytrace/util/message.hpp"

using namespace rt;

TEST_CASE("message: control characters are escaped, so a message stays one line") {
  CHECK(printable("a.pov") == "a.pov");
  CHECK(printable("a\nb\tc\rd") == "a\\nb\\tc\\rd");
  CHECK(printable(std::string("x\0y\x1b\x7f", 5)) == "x\\x00y\\x1B\\x7F");
  CHECK(printable("caf\xC3\xA9") == "caf\xC3\xA9");  // UTF-8 is shown as it is
  CHECK(quote("it's") == "'it's'");
}

TEST_CASE("message: long input is cut with an ellipsis") {
  const std::string exact(kMaxQuoted, 'a');
  CHECK(quote(exact) == "'" + exact + "'");
  CHECK(quote(exact + "b") == "'" + exact + "...'");
  CHECK(printable(std::string(10'000'000, 'x')).size() == kMaxQuoted + 3);
  CHECK(printable(std::string(300, 'p'), kMaxQuotedPath) == std::string(256, 'p') + "...");
}

TEST_CASE("message: thousands separators") {
  CHECK(thousands(0) == "0");
  CHECK(thousands(999) == "999");
  CHECK(thousands(1000) == "1,000");
  CHECK(thousands(299999) == "299,999");
  CHECK(thousands(1234567890) == "1,234,567,890");
}

TEST_CASE("message: repeated messages are counted once, at their first place") {
  std::vector<std::string> lines;
  for (int i = 1; i <= 300000; ++i) lines.push_back("s.pov:" + std::to_string(i) + ":5: warning: same");
  lines.insert(lines.begin() + 2, "s.pov:7:1: warning: other");
  CHECK(collapseRepeats(lines) == std::vector<std::string>{"s.pov:1:5: warning: same (and 299,999 more like it)",
                                                           "s.pov:7:1: warning: other"});
  CHECK(collapseRepeats({"a.pov:1:1: warning: x", "b.pov:2:2: warning: y"}) ==
        std::vector<std::string>{"a.pov:1:1: warning: x", "b.pov:2:2: warning: y"});
  CHECK(collapseRepeats({"a: 1.pov:1:1: warning: x", "a: 1.pov:9:3: warning: x"}) ==
        std::vector<std::string>{"a: 1.pov:1:1: warning: x (and 1 more like it)"});
  CHECK(collapseRepeats({}).empty());
}
