// The makers of the pattern kinds, one file each in src/surface/patterns/, listed in patternKind().
#pragma once

#include <memory>

#include "raytrace/surface/pattern.hpp"

namespace rt {

std::unique_ptr<Pattern> makeAgate(const PatternArgs&);
// The colour maps of the patterns that have their own, each beside its pattern, as POV-Ray's pigment functions
// show them (docs/povray-noise.md, "Default colour maps").
extern const DefaultMap kAgateMap, kBozoMap, kMandelMap, kMarbleMap, kRadialMap, kWoodMap;
std::unique_ptr<Pattern> makeBoxed(const PatternArgs&);
std::unique_ptr<Pattern> makeBozo(const PatternArgs&);
std::unique_ptr<Pattern> makeBrick(const PatternArgs&);
std::unique_ptr<Pattern> makeCells(const PatternArgs&);
std::unique_ptr<Pattern> makeChecker(const PatternArgs&);
std::unique_ptr<Pattern> makeCrackle(const PatternArgs&);
std::unique_ptr<Pattern> makeCylindrical(const PatternArgs&);
std::unique_ptr<Pattern> makeDensityFile(const PatternArgs&);
std::unique_ptr<Pattern> makeDents(const PatternArgs&);
std::unique_ptr<Pattern> makeFractal(const PatternArgs&);
std::unique_ptr<Pattern> makeFunctionPattern(const PatternArgs&);
std::unique_ptr<Pattern> makeGradient(const PatternArgs&);
std::unique_ptr<Pattern> makeGranite(const PatternArgs&);
std::unique_ptr<Pattern> makeHexagon(const PatternArgs&);
std::unique_ptr<Pattern> makeLeopard(const PatternArgs&);
std::unique_ptr<Pattern> makeMarble(const PatternArgs&);
std::unique_ptr<Pattern> makeOnion(const PatternArgs&);
std::unique_ptr<Pattern> makePigmentPattern(const PatternArgs&);
std::unique_ptr<Pattern> makePlanar(const PatternArgs&);
std::unique_ptr<Pattern> makeQuilted(const PatternArgs&);
// Normals only (surface/normal.hpp): a bump_map's image, planar (map_type 0).
struct ImageMap;
std::unique_ptr<Pattern> makeBumpMap(const ImageMap& image);
// Normals only (surface/normal.hpp), in normalPatternKind(): bumps, dents, ripples, waves and wrinkles as
// POV-Ray bends normals by them.
std::unique_ptr<Pattern> makeBumpsNormal(const PatternArgs&);
std::unique_ptr<Pattern> makeDentsNormal(const PatternArgs&);
std::unique_ptr<Pattern> makeRipplesNormal(const PatternArgs&);
std::unique_ptr<Pattern> makeWavesNormal(const PatternArgs&);
std::unique_ptr<Pattern> makeWrinklesNormal(const PatternArgs&);
std::unique_ptr<Pattern> makeRadial(const PatternArgs&);
std::unique_ptr<Pattern> makeRipples(const PatternArgs&);
std::unique_ptr<Pattern> makeSlope(const PatternArgs&);
std::unique_ptr<Pattern> makeSpherical(const PatternArgs&);
std::unique_ptr<Pattern> makeSpiral1(const PatternArgs&);
std::unique_ptr<Pattern> makeSpiral2(const PatternArgs&);
// The spirals' angle about z from the −y axis, as a share of a turn in [0, 1); 0 on the axis itself, as
// POV-Ray counts it (docs/povray-noise.md).
double spiralTurn(const glm::dvec3& p);
// `tiling N`: whether tiling N is drawn yet (N in 1 … 27 is POV-Ray's range).
bool tilingDrawn(int n);
std::unique_ptr<Pattern> makeTiling(const PatternArgs&);
std::unique_ptr<Pattern> makeWaves(const PatternArgs&);
std::unique_ptr<Pattern> makeWood(const PatternArgs&);
std::unique_ptr<Pattern> makeWrinkles(const PatternArgs&);

}  // namespace rt
