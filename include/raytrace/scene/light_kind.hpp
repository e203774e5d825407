// POV-Ray's emitter kinds (docs/povray-language.md, "Lights"): how a light's strength falls off around the axis
// from its position toward its point_at. A kind is one file in src/scene/lights/ (its preparation and factor,
// declared below) and one row of lightKinds() (src/scene/light_kind.cpp); the POV-Ray light reader and
// LightShape reach it through that row. A light with no kind is a point light, the same all around.
#pragma once

#include <string_view>
#include <vector>

#include "raytrace/geometry/math.hpp"

namespace rt {

// What a kind's factor reads: the unit axis and its radius, falloff and tightness as its preparation left them.
struct Emitter {
  glm::dvec3 axis{0, -1, 0};
  double radius = 0, falloff = 0, tightness = 0;
};

struct LightKind {
  std::string_view keyword;  // POV-Ray's word in a light_source
  // radius and falloff when the light_source gives none (the manual's defaults for the kind).
  double defaultRadius = 0, defaultFalloff = 0;
  bool tightness = false;  // whether it takes a tightness other than 0; refused where it does not
  // From the values as written (degrees or lengths) to what `factor` reads, once per light.
  void (*prepare)(Emitter&) = nullptr;
  // The factor on the light's colour at `distance` from the light along the unit `toPoint`.
  double (*factor)(const Emitter&, const glm::dvec3& toPoint, double distance) = nullptr;
};

const std::vector<LightKind>& lightKinds();
// The row of a keyword, or null.
const LightKind* lightKindNamed(std::string_view keyword);
const LightKind& spotlightKind();

// The kinds' preparations and factors, one file each in src/scene/lights/.
void prepareSpotlight(Emitter&);
double spotlightFactor(const Emitter&, const glm::dvec3& toPoint, double distance);
void prepareCylinderLight(Emitter&);
double cylinderLightFactor(const Emitter&, const glm::dvec3& toPoint, double distance);

}  // namespace rt
