// libFuzzer target for the POV-Ray 3.7 language. Any bytes must either parse or throw rt::ParseError: any other
// exception, a crash, a sanitizer report, a hang or a blown memory limit is a finding. A budget of tokens read
// stands in for the Ctrl-C a user would give an endless #while.
#include <cstddef>
#include <cstdint>
#include <string>

#include "cast_rays.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  rt::povray::PovRayOptions options;
  options.debugOutput = false;
  options.maxTokens = 1000000;
  try {
    rt::fuzz::castRays(rt::povray::parsePovRay(std::string(reinterpret_cast<const char*>(data), size), "fuzz.pov", options));
  } catch (const rt::ParseError&) {
  }
  return 0;
}
