// Surface appearance as shading reads it, whichever scene language described it.
#pragma once

#include <optional>

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/iridescence.hpp"
#include "raytrace/surface/media.hpp"

namespace rt {

// A POV-Ray `finish` block as written (docs/reference/csc473.md §b): what `sceneinfo` prints, and what the POV parser
// makes a Material of.
struct Finish {
  double ambient = 0, diffuse = 0, specular = 0;
  double roughness = 1;  // course default; Blinn-Phong exponent 2/roughness² − 2 (§c.1)
  double reflection = 0;
  double refraction = 0;  // parsed and ignored, as in the course: the pigment's filter drives refraction (§c.4)
  double ior = 1;
};

// What POV-Ray adds to a surface beyond the course's terms, seldom used: a Material points to it, so that the
// Materials of other surfaces (a textured one is made at every hit) stay as small and quick to make as before.
struct SurfaceExtras {
  // The interior's fade: light that travelled d inside is multiplied by a + (1 − a)·fadeColor with
  // a = 1 / (1 + (d / fadeDistance)^fadePower) (POV-Ray 3.7 manual, "Attenuation"); fadeDistance 0: none.
  float fadeDistance = 0, fadePower = 0;
  Color fadeColor{0};
  // The interior's faked caustics (POV-Ray 3.7 manual, "Simulated Caustics"): a shadow ray crossing the surface
  // takes fakedCaustics() of the light it lets through; 0: none.
  float caustics = 0;
  // Variable reflection (`reflection { min, max falloff F fresnel }`): reflectionMin facing the viewer up to
  // the Material's `reflection` at grazing angles, by (1 − cos θ)^reflectionFalloff or by Fresnel's reflectance
  // at its `ior` (variableReflection(), shading.hpp). reflectionFalloff 0: a constant `reflection`.
  float reflectionMin = 0, reflectionFalloff = 0;
  // crand: each light's diffuse term loses crand·u·C·light, u uniform in [0, 1) at each point (fitted to
  // POV-Ray's pictures; its own u is random at each render, ours keyed by the point, the same at each).
  float crand = 0;
  // `reflection { … metallic M }`: reflected light tinted by the pigment, less so toward grazing angles
  // (metallicTint(), shading.hpp); 0: not tinted.
  float reflectionMetallic = 0;
  // A colour `reflection`: reflected light tinted by the colour over its largest channel, the Material's
  // `reflection` (POV-Ray 3.7 manual, "Specular Reflection": the reflection may be a colour); white: not tinted.
  // The same for a variable reflection's minimum colour, over reflectionMin.
  Color reflectionTint{1}, reflectionMinTint{1};
  bool reflectionFresnel = false;
  // conserve_energy: light through the surface is what its reflection leaves (Weights, shading.hpp).
  bool conserveEnergy = false;
  // A finish's `irid`: each light's colour multiplied by Iridescence::factor(); none: no film.
  std::shared_ptr<const Iridescence> irid;
  // The object's double_illuminate: a light behind the surface, as the viewer sees it, lights it as if it
  // were in front (POV-Ray 3.7 manual, "Double Illuminate Object Modifier").
  bool doubleIlluminate = false;
  // The interior's media, which a ray that enters the object crosses up to its next hit; several add up (the
  // manual, "Multiple Media").
  std::vector<Media> media;
  // POV-Ray's `hollow`: media are seen only inside hollow objects (the manual, "Empty and Solid Objects").
  bool hollow = false;
  // The interior a CSG's parts share, numbered from 1 in the scene; 0 for an object's own (Path::interiors).
  size_t interior = 0;

  // Whether any of them changes a picture.
  bool any() const {
    return fadeDistance > 0 || caustics != 0 || reflectionFalloff > 0 || reflectionFresnel || crand != 0 || reflectionMetallic != 0 ||
           reflectionTint != Color(1) || reflectionMinTint != Color(1) || conserveEnergy || irid || doubleIlluminate || !media.empty() || hollow ||
           interior != 0;
  }
};

// The extras of a surface that has none, which every Material points to until given others.
inline const SurfaceExtras kNoExtras{};

// A lasting copy of `extras` for Materials to point to (kept for the rest of the run; safe on any thread).
const SurfaceExtras* keptExtras(const SurfaceExtras& extras);

// What shading reads of a surface, in either scene language. Every object carries one, so it holds nothing
// else: the finish as written stays in the scene's description (ObjectDesc).
struct Material {
  Color pigment{0};   // C
  float filter = 0;   // f, the fraction of light transmitted (rgbf's fourth component)
  Color ambient{0};   // per-term colours: POV ka·C, kd·C, ks·C; .cli Ca, Cd, Cs
  Color diffuse{0};
  Color specular{0};
  float exponent = 0;    // Blinn-Phong exponent: POV 2/roughness² − 2, .cli P
  float roughness = 1;   // Cook-Torrance α = roughness² (§c.2)
  float reflection = 0;  // POV `reflection`, .cli Krefl
  float ior = 1;
  float brilliance = 1;  // POV-Ray's brilliance: the diffuse term takes (n·l) to this power
  const SurfaceExtras* extras = &kNoExtras;  // POV-Ray's interior fade, variable reflection and crand
  // The highlight's lobe: about the half vector (course, .cli, POV-Ray's `specular`) or about the mirror
  // direction (POV-Ray's `phong`).
  enum class Lobe : unsigned char { HalfVector, Mirror } lobe = Lobe::HalfVector;
};

}  // namespace rt
