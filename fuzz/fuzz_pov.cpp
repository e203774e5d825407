// libFuzzer target for the POV parser. Any bytes must either parse or throw rt::ParseError: any other
// exception, a crash, a sanitizer report, a hang or a blown memory limit is a finding. A parsed scene is
// also built and a few eye rays are cast, so that the numbers a file can smuggle in (huge, tiny, degenerate)
// reach the geometry under the sanitizers too.
#include <cstddef>
#include <cstdint>
#include <string>

#include "raytrace/camera.hpp"
#include "raytrace/error.hpp"
#include "raytrace/pov_parser.hpp"
#include "raytrace/precision.hpp"
#include "raytrace/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const rt::SceneDesc desc = rt::parsePov(std::string(reinterpret_cast<const char*>(data), size), "fuzz.pov");
    const rt::Arithmetic arithmetic = rt::chooseArithmetic(desc);
    rt::withPrecision(arithmetic.precision, [&](auto tag) {
      using T = decltype(tag);
      const rt::Scene<T> scene(desc, arithmetic);
      const rt::Camera<T> camera(desc.camera, 3, 3);
      for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 3; ++x) scene.closestHit(camera.pixelRay(x, y), {});
      }
    });
  } catch (const rt::ParseError&) {
  }
  return 0;
}
