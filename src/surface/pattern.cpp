#include "raytrace/surface/pattern.hpp"

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {
thread_local glm::dvec3 theSurfaceNormal{0, 0, 1};
}  // namespace

void setSurfaceNormal(const glm::dvec3& n) { theSurfaceNormal = n; }
const glm::dvec3& surfaceNormal() { return theSurfaceNormal; }

const PatternKind* patternKind(std::string_view name) {
  constexpr Wave kTriangle = Wave::Triangle;
  static constexpr PatternKind kKinds[] = {
      {"agate", false, makeAgate, Wave::Ramp, false, true, &kAgateMap},
      {"boxed", false, makeBoxed},
      {"bozo", false, makeBozo, Wave::Ramp, false, true, &kBozoMap},
      {"brick", false, makeBrick},
      {"bumps", false, makeBozo},  // as a pigment; as a normal it bends the surface
      {"cells", false, makeCells},
      {"checker", false, makeChecker},
      {"crackle", false, makeCrackle},
      {"cylindrical", false, makeCylindrical},
      {"density_file", false, makeDensityFile},  // its file read by surface_reader.cpp
      {"dents", false, makeDents},
      {"function", false, makeFunctionPattern},
      {"gradient", true, makeGradient},
      {"granite", false, makeGranite},
      {"hexagon", false, makeHexagon},
      {"julia", false, makeFractal},  // these three read their own numbers (surface_reader.cpp)
      {"leopard", false, makeLeopard},
      {"magnet", false, makeFractal},
      {"mandel", false, makeFractal, Wave::Ramp, false, true, &kMandelMap},
      {"marble", false, makeMarble, kTriangle, true, true, &kMarbleMap},
      {"onion", false, makeOnion},
      {"pigment_pattern", false, makePigmentPattern},  // its pigment read by surface_reader.cpp
      {"planar", false, makePlanar},
      {"quilted", false, makeQuilted},
      {"radial", false, makeRadial, Wave::Ramp, false, true, &kRadialMap},
      {"ripples", false, makeRipples},
      {"slope", false, makeSlope},  // its block read by surface_reader.cpp
      {"spherical", false, makeSpherical},
      {"spiral1", true, makeSpiral1, kTriangle, true, false},  // `spiral1 N`: N arms
      {"spiral2", true, makeSpiral2, kTriangle, true, false},  // `spiral2 N`: N arms
      {"spotted", false, makeBozo},
      {"tiling", true, makeTiling},  // `tiling N`: its number checked by surface_reader.cpp
      {"waves", false, makeWaves},
      {"wood", false, makeWood, kTriangle, true, true, &kWoodMap},
      {"wrinkles", false, makeWrinkles},
  };
  for (const PatternKind& k : kKinds) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

const PatternKind* normalPatternKind(std::string_view name) {
  static constexpr PatternKind kKinds[] = {
      {"bumps", false, makeBumpsNormal},     {"dents", false, makeDentsNormal},
      {"ripples", false, makeRipplesNormal}, {"waves", false, makeWavesNormal},
      {"wrinkles", false, makeWrinklesNormal},
  };
  for (const PatternKind& k : kKinds) {
    if (k.name == name) return &k;
  }
  return nullptr;
}

namespace {

// Turbulence as most patterns take it: the point displaced by the turbulent offset, scaled per axis.
class Turbulent final : public Pattern {
 public:
  Turbulent(std::unique_ptr<Pattern> base, const Turbulence& t) : base_(std::move(base)), turbulence_(t) {}
  double value(const glm::dvec3& p) const override {
    return base_->value(p + turbulentOffset(p, turbulence_) * turbulence_.amount);
  }
  int blocks() const override { return base_->blocks(); }
  Color defaultBlock(int i) const override { return base_->defaultBlock(i); }
  bool hasBump() const override { return base_->hasBump(); }
  bool readsNormal() const override { return base_->readsNormal(); }
  glm::dvec3 bump(const glm::dvec3& p) const override {
    return base_->bump(p + turbulentOffset(p, turbulence_) * turbulence_.amount);
  }

 private:
  std::unique_ptr<Pattern> base_;
  Turbulence turbulence_;
};

}  // namespace

std::unique_ptr<Pattern> makePattern(const PatternKind& kind, const PatternArgs& args) {
  std::unique_ptr<Pattern> p = kind.make(args);
  if (!args.turbulence.on() || kind.ownTurbulence) return p;
  return std::make_unique<Turbulent>(std::move(p), args.turbulence);
}

}  // namespace rt
