// libFuzzer target for the POV parser. Any bytes must either parse or throw rt::ParseError: any other
// exception, a crash, a sanitizer report, a hang or a blown memory limit is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "cast_rays.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/parse/pov_parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    rt::fuzz::castRays(rt::parsePov(std::string(reinterpret_cast<const char*>(data), size), "fuzz.pov"));
  } catch (const rt::ParseError&) {
  }
  return 0;
}
