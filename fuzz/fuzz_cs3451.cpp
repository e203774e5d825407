// libFuzzer target for the .cli parser. Any bytes must either parse or throw rt::ParseError: any other
// exception, a crash, a sanitizer report, a hang or a blown memory limit is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "cast_rays.hpp"
#include "raytrace/parse/cs3451_parser.hpp"
#include "raytrace/util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const rt::SceneDesc scene = rt::parseCs3451(std::string(reinterpret_cast<const char*>(data), size), "fuzz.cli");
    rt::fuzz::castRays(scene);
    for (const rt::WriteDesc& w : scene.writes) rt::fuzz::castRays(w.scene);
  } catch (const rt::ParseError&) {
  }
  return 0;
}
