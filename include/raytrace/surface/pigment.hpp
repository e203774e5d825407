// A pigment: a solid colour, or a pattern whose value picks and blends colours or other pigments. Colours
// carry POV-Ray's filter and transmit channels.
#pragma once

#include <memory>
#include <vector>

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/pattern.hpp"
#include "raytrace/surface/warp.hpp"

namespace rt {

struct Rgbft {
  Color rgb{0};
  float filter = 0, transmit = 0;
};
Rgbft mix(const Rgbft& a, const Rgbft& b, float t);  // a at t = 0, b at t = 1

struct Pigment;
struct ImageMap;
// An image map's lowest and highest channels, each over all its pixels: what bounds its colours.
const Rgbft* imageExtremes(const ImageMap& image);

// `[value pigment]` of a color_map or pigment_map, in increasing values.
struct MapEntry {
  double value;
  std::shared_ptr<const Pigment> pigment;
};

// A continuous pattern's value after frequency and phase, wrapped into [0, 1] and shaped by the wave (POV-Ray
// 3.7 manual, "Waveform"): what a colour map or a slope map reads.
double waveValue(double raw, double frequency, double phase, Wave wave, double exponent);

// A warp where it stands among the pigment's transforms, those written after it undone first (as POV-Ray's
// values show: docs/povray-noise.md).
struct WarpStage {
  glm::dmat4 before{1};  // the inverse of the transforms written after this warp and before the next one
  std::shared_ptr<const Warp> warp;
};

// p (in texture space) through the warps, each after the transforms it undoes, and then afterWarps.
glm::dvec3 throughWarps(const std::vector<WarpStage>& warps, const glm::dmat4& afterWarps, const glm::dvec3& p);

struct Pigment {
  Rgbft solid;                              // the colour when there is no pattern
  std::shared_ptr<const Pattern> pattern;
  std::vector<MapEntry> map;                // for a continuous pattern
  std::vector<std::shared_ptr<const Pigment>> list;  // for a block pattern, one per block
  // Texture space to the pattern's own (the inverse of the pigment's transforms); a map's or list's pigments
  // start from the pattern's space, so that the pigment's transforms move them too.
  glm::dmat4 fromTexture{1};
  double frequency = 1, phase = 0, exponent = 1;
  Wave wave = Wave::Ramp;
  bool average = false;  // `average`: the map's pigments mixed, each weighted by its entry's value
  // Warps, the last written first; with any, the pattern reads its point through them and then afterWarps (the
  // inverse of the transforms written before the first warp), while the map's pigments still read fromTexture.
  std::vector<WarpStage> warps;
  glm::dmat4 afterWarps{1};
  std::shared_ptr<const ImageMap> image;  // an image_map, in place of the solid colour

  Rgbft at(const glm::dvec3& p) const;  // p in texture space
  // The pattern's value at p after frequency, phase, POV-Ray's wrapping and the wave: what the map reads, and
  // what a pattern function (`function { pattern { … } }`) returns; a block pattern's block. 0 without a pattern.
  double value(const glm::dvec3& p) const;
  // The point of texture space where the pattern is read: through the transforms and warps.
  glm::dvec3 patternPoint(const glm::dvec3& p) const;
};

// Whether the pigment's pattern, or a pattern of its map's or list's pigments, reads the surface's normal (slope).
bool readsNormal(const Pigment& p);

// Whether some colour the pigment can give (its solid colour, or any of its map's or list's) satisfies `pred`.
template <class F> bool anyColour(const Pigment& p, const F& pred) {
  if (p.image) return pred(imageExtremes(*p.image)[0]) || pred(imageExtremes(*p.image)[1]);
  if ((!(p.pattern || p.average) || (p.map.empty() && p.list.empty())) && pred(p.solid)) return true;
  for (const MapEntry& e : p.map) {
    if (anyColour(*e.pigment, pred)) return true;
  }
  for (const auto& q : p.list) {
    if (anyColour(*q, pred)) return true;
  }
  return false;
}

}  // namespace rt
