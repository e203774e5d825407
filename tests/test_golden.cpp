// Golden outputs of the diagnostic commands on our own scenes (scenes/), listed in resources/golden/cases.txt.
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>

#include "raytrace/cli.hpp"

namespace {

std::string sourceDir() {
  const std::string file = __FILE__;
  return file.substr(0, file.rfind("/tests/"));
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("Diagnostic commands reproduce their golden outputs", "[golden]") {
  const std::string dir = sourceDir() + "/resources/golden/";
  std::ifstream cases(dir + "cases.txt");
  REQUIRE(cases);
  std::string line;
  int count = 0;
  while (std::getline(cases, line)) {
    if (line.empty() || line[0] == '#') continue;
    // "<golden file> <command> <scene relative to the repository> <arguments…>"
    std::istringstream words(line);
    std::string golden, word;
    words >> golden;
    std::vector<std::string> args;
    while (words >> word) args.push_back(args.size() == 1 ? sourceDir() + "/" + word : word);
    CAPTURE(line);
    const std::string expected = slurp(dir + golden);
    REQUIRE_FALSE(expected.empty());
    std::ostringstream out, err;
    CHECK(rt::runCommand(args, out, err) == 0);
    CHECK(out.str() == expected);
    CHECK(err.str().empty());
    ++count;
  }
  CHECK(count > 0);
}
