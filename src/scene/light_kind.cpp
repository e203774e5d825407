#include "raytrace/scene/light_kind.hpp"

#include <algorithm>

namespace rt {

// The defaults are the manual's: a spotlight's 30° and 45° ("Spotlights"), a cylinder light's lengths 0.75 and
// 1 ("Cylindrical Lights"), which takes no tightness here.
const std::vector<LightKind>& lightKinds() {
  static const std::vector<LightKind> kinds = {
      {"spotlight", 30, 45, true, prepareSpotlight, spotlightFactor},
      {"cylinder", 0.75, 1, false, prepareCylinderLight, cylinderLightFactor},
  };
  return kinds;
}

const LightKind* lightKindNamed(std::string_view keyword) {
  const auto& kinds = lightKinds();
  const auto found = std::find_if(kinds.begin(), kinds.end(), [&](const LightKind& k) { return k.keyword == keyword; });
  return found == kinds.end() ? nullptr : &*found;
}

const LightKind& spotlightKind() { return lightKinds().front(); }

}  // namespace rt
