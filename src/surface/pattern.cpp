#include "raytrace/surface/pattern.hpp"

#include <iterator>

#include "raytrace/surface/patterns.hpp"

namespace rt {

const PatternKind* patternKind(std::string_view name) {
  static constexpr PatternKind kKinds[] = {
      {"boxed", false, makeBoxed},       {"checker", false, makeChecker},         {"cylindrical", false, makeCylindrical},
      {"gradient", true, makeGradient},  {"onion", false, makeOnion},             {"planar", false, makePlanar},
      {"quilted", false, makeQuilted},   {"radial", false, makeRadial},           {"spherical", false, makeSpherical},
  };
  for (const PatternKind& k : kKinds) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

}  // namespace rt
