// A pattern: a number at each point of texture space, which a colour map or a list of pigments turns into a
// colour (surface/pigment.hpp). One kind a file in src/surface/patterns/, one row in patternKinds().
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/noise.hpp"

namespace rt {

class Function;
struct DensityGrid;
struct Pigment;

class Pattern {
 public:
  virtual ~Pattern() = default;
  // The pattern's value at `p`: in [0, 1] for a continuous pattern, which a wave and a map then read; the
  // index of the entry for a block pattern (blocks() > 0).
  virtual double value(const glm::dvec3& p) const = 0;
  // How many pigments a block pattern chooses among (checker 2, hexagon 3); 0 for a continuous one.
  virtual int blocks() const { return 0; }
  // A block pattern's colour for block i when the file gives none (as r, g, b).
  virtual Color defaultBlock(int) const { return Color(0); }
  // Whether the pattern bends a normal by a formula of its own (quilted; bumps and dents as normals) rather
  // than by its value's slope; bump(p) is then the vector, in the pattern's space, that the normal is bent
  // against per unit of the normal's amount (surface/normal.hpp).
  virtual bool hasBump() const { return false; }
  virtual glm::dvec3 bump(const glm::dvec3&) const { return glm::dvec3(0); }
  // Whether the value reads the surface's normal at the hit (slope) besides the point: a texture holding such
  // a pattern sets surfaceNormal() before it is read (Texture::readsNormal).
  virtual bool readsNormal() const { return false; }
};

// The world-space unit normal, facing the viewer, of the surface being shaded on this thread: what slope reads
// (POV-Ray 3.7 manual, "Slope Pattern"). Set only for a texture that reads it, so other textures pay nothing.
void setSurfaceNormal(const glm::dvec3& n);
const glm::dvec3& surfaceNormal();

// How a continuous pattern's value is shaped before the map reads it (POV-Ray's wave modifiers).
enum class Wave { Ramp, Triangle, Sine, Scallop, Cubic, Poly };

// The noise generator a pattern uses: its own `noise_generator`, else global_settings', which may come later
// in the file than the pattern and so is read when the scene is drawn.
struct NoiseChoice {
  std::shared_ptr<const NoiseGenerator> scene;
  std::optional<NoiseGenerator> own;
  NoiseGenerator get() const { return own ? *own : scene ? *scene : NoiseGenerator::RangeCorrected; }
};

// crackle's modifiers: the distances to the nearest three cell points weighted by `form`, each measured with
// `metric` and lifted by `offset` along a fourth axis; `solid` gives each cell one value.
struct CrackleArgs {
  glm::dvec3 form{-1, 1, 0};
  double metric = 2, offset = 0;
  bool solid = false;
};

// The fractal patterns' settings (POV-Ray 3.7 manual, "Fractal Pattern"): which set, its iterations, julia's
// constant, the exponent of mandel and julia, and what the value is outside and inside the set.
struct FractalArgs {
  enum class Set { Mandel, Julia, Magnet1Mandel, Magnet1Julia, Magnet2Mandel, Magnet2Julia } set = Set::Mandel;
  int iterations = 0;
  glm::dvec2 constant{0};
  int exponent = 2;
  int exteriorType = 1, interiorType = 0;
  double exteriorFactor = 1, interiorFactor = 1;
};

// slope's `<direction>, lo, hi` and `altitude <altitude>, lo, hi`: the slope value s in [0, 1] and the
// altitude along the vector, each mapped from [lo, hi] to [0, 1] and weighted by its vector's length.
struct SlopeArgs {
  glm::dvec3 direction{0, 1, 0};
  double lo = 0, hi = 1;
  glm::dvec3 altitude{0};
  double altitudeLo = 0, altitudeHi = 1;
};

// What makes a pattern: the vector after its keyword (`gradient <1, 0, 0>`) and the pigment's modifiers that
// change the pattern itself.
struct PatternArgs {
  glm::dvec3 vector{0};
  bool hasVector = false;
  Turbulence turbulence;  // the pigment's turbulence, octaves, omega and lambda
  NoiseChoice noise;
  double agateTurbulence = 1;
  CrackleArgs crackle;
  double control0 = 1, control1 = 1;  // quilted's, written among the pattern's modifiers
  std::shared_ptr<const Function> function;  // the function pattern's
  std::shared_ptr<const Pigment> pigment;    // pigment_pattern's
  glm::dvec3 brickSize{8, 3, 4.5};  // brick's brick_size and mortar
  double mortar = 0.5;
  FractalArgs fractal;
  SlopeArgs slope;
  std::shared_ptr<const DensityGrid> densityFile;  // density_file's voxels and its interpolate 0, 1 or 2
  int densityInterpolation = 0;
  double frequency = 1, phase = 0;  // a normal's, which ripples and waves read themselves
};

// An entry of a pattern's own colour map: the colour at a value, in increasing values (two at one value: a step).
struct ColourStop {
  double value;
  Color colour;
};
struct DefaultMap {
  const ColourStop* stops;
  size_t count;
};

struct PatternKind {
  std::string_view name;
  bool needsVector;
  std::unique_ptr<Pattern> (*make)(const PatternArgs&);
  Wave wave = Wave::Ramp;       // its wave when the pigment names none
  bool ownTurbulence = false;   // it reads the turbulence itself, instead of being displaced by it
  bool turbulenceDrawn = true;  // false: its own way with turbulence is not drawn yet, and is refused
  // The colour map a pigment of it has without one (POV-Ray 3.7 manual, "Patterns": agate, bozo, mandel, marble,
  // radial and wood have their own); none: black at 0 to white at 1.
  const DefaultMap* defaultMap = nullptr;
};

// The pattern kinds raytrace draws; nothing for any other name.
const PatternKind* patternKind(std::string_view name);
// The kinds that bend a normal by a formula of their own (bumps, dents, ripples, waves, wrinkles): in a normal
// they stand for the pattern of the same name; nothing for any other name.
const PatternKind* normalPatternKind(std::string_view name);

// A pattern of the kind, displaced by the turbulence unless the kind reads it itself.
std::unique_ptr<Pattern> makePattern(const PatternKind& kind, const PatternArgs& args);

}  // namespace rt
