// The course's text number formats.
#include <catch2/catch.hpp>

#include "raytrace/util/format.hpp"

using namespace rt;

// Any finite double in fixed notation with 4 decimals, exactly: 1e59 has 59 digits before the point and the
// largest double 309 (a 64-byte buffer cut them at 63 characters).
TEST_CASE("format: fixed4 prints every finite value exactly, however large") {
  CHECK(fixed4(1e59) == "99999999999999997168788049560464200849936328366177157906432.0000");
  const std::string most = fixed4(-1.7976931348623157e308);
  CHECK(most.size() == 315);
  CHECK(most.rfind("-1797693134862315708145274237317043567980705675258449965989174768031572607800285387605895586327668781", 0) == 0);
  CHECK(most.substr(309) == "8.0000");
  CHECK(fixed4(4.9e-324) == "0.0000");
  CHECK(fixed4(-0.00005) == "-0.0001");
}
