// The shading formulas of the course (docs/reference/csc473.md §c), each a pure function of unit vectors and the
// material, so each can be checked by hand. The tracer (tracer.hpp) decides where they are applied.
#pragma once

#include <optional>

#include "raytrace/scene/dialect.hpp"
#include "raytrace/surface/material.hpp"
#include "raytrace/geometry/math.hpp"

namespace rt {

enum class Brdf { BlinnPhong, CookTorrance };

// Vectors below are unit length: n the shading normal (on the viewer's side), v toward the viewer, l toward
// the light. Every factor is finite for any unit input.

// Blinn-Phong specular factor clamp(n·h, 0, 1)^p with h = normalize(l + v) (§c.1). A roughness above 1 makes
// p = 2/roughness² − 2 negative, and 0^p infinite; such exponents are treated as 0.
template <class T> float blinnPhongSpecular(const Vec3<T>& n, const Vec3<T>& v, const Vec3<T>& l, float exponent);

// Phong's own specular factor clamp(r·l, 0, 1)^p with r the mirror of v about n (Phong 1975), as POV-Ray's
// `phong` highlight; its `specular` is the half-vector form above.
template <class T> float phongSpecular(const Vec3<T>& n, const Vec3<T>& v, const Vec3<T>& l, float exponent);

// Cook-Torrance with the GGX distribution, Smith-GGX shadowing and Schlick's Fresnel (§c.2), as the factor
// D·G·F / (4·max(1/16, n·v)) that multiplies Lc·ks·C (the n·l of the sum cancels the one in the BRDF).
template <class T>
float cookTorranceSpecular(const Vec3<T>& n, const Vec3<T>& v, const Vec3<T>& l, float roughness, float ior);

// GGX's α = roughness² (§c.2), floored at kMinGgxAlpha: a perfect mirror has no finite D, and below this
// (roughness 3e-4) the highlight is a single over-exposed pixel anyway. The floor keeps D ≤ 1/(πα²) finite.
constexpr float kMinGgxAlpha = 1e-7f;
float ggxAlpha(float roughness);

// Schlick's approximation F0 + (1 − F0)(1 − cosθ)^5 with F0 = ((ior − 1)/(ior + 1))² (§c.5).
float schlick(float cosTheta, float ior);

// The mirror direction of incoming direction d about n (either orientation): d − 2(d·n)n (§c.3).
template <class T> Vec3<T> reflectDirection(const Vec3<T>& d, const Vec3<T>& n);

// POV-Ray's mirror direction about a normal n bent by a texture, the surface's own normal `side` facing the ray
// (measured on POV-Ray's pictures, docs/povray-language.md): where d reflected about n would go into the surface,
// it is mirrored back out by the surface (r − 2(r·side)·side) if n faces the ray, and d is reflected about
// `side` instead if n faces away from it.
template <class T> Vec3<T> reflectBent(const Vec3<T>& d, const Vec3<T>& n, const Vec3<T>& side);

// Snell's law for incoming direction d at a surface with OUTWARD normal n (§c.4). Entering (d·n ≤ 0) bends by
// 1/ior, leaving by ior about −n. Nothing on total internal reflection (negative radicand, docs/reference/stability.md
// F9).
template <class T> std::optional<Vec3<T>> refractDirection(const Vec3<T>& d, const Vec3<T>& n, float ior);

// Beer's law (§c.6): the fraction of each channel left after `distance` (possibly +∞) inside a medium of
// pigment C, exp(−(1 − C)·0.15·distance).
Color beerAttenuation(const Color& pigment, float distance);

// POV-Ray's interior fade (SurfaceExtras::fadeDistance, POV-Ray 3.7 manual "Attenuation"): the fraction of each
// channel left after `distance` inside, a + (1 − a)·fadeColor with a = 1/(1 + (distance/fadeDistance)^fadePower),
// or exp(−(1 − fadeColor)·distance/fadeDistance) for a fadePower of 1000 or more (the manual's exp(−d/fade_distance)
// tinted channel by channel, as POV-Ray's pictures show). An infinite path (a ray that hits nothing) is not faded.
Color interiorFade(const Material& m, float distance);

// POV-Ray's faked caustics (SurfaceExtras::caustics, POV-Ray 3.7 manual "Simulated Caustics"): a shadow ray that
// crosses the surface lets through 1 + |cos θ|^(45·caustics) times the light, θ between the (bent) normal and the
// ray. The exponent 45·caustics was measured on real POV-Ray (a tilted disc over a plane, docs/povray-language.md).
float fakedCaustics(float caustics, float cosTheta);

// Fresnel's reflectance of unpolarized light at a dielectric of relative index `ior`, cos θ = cosTheta (the
// exact formula, Cook and Torrance 1982, eq. 12 form): ½((g − c)/(g + c))²(1 + ((c(g + c) − 1)/(c(g − c) + 1))²)
// with g = √(ior² + c² − 1); 1 where g is not real (total internal reflection).
float fresnelReflectance(float cosTheta, float ior);

// POV-Ray's variable reflection at cos θ between the normal and the direction to the viewer (Material's
// reflection and SurfaceExtras' reflectionMin, reflectionFalloff, reflectionFresnel; POV-Ray 3.7 manual, "Specular Reflection").
Color variableReflection(const Material& m, float cosTheta);

// The tint of light reflected by a `reflection { … metallic M }` surface, cos θ = cosTheta from the normal:
// 1 + M·(1 − F)·(pigment − 1), with POV-Ray's empirical F(x) = 0.014567225/(x − 1.12)² − 0.011612903 in [0, 1]
// at x = θ/(π/2): the pigment's colour facing the viewer, the light's own at grazing angles (POV-Ray 3.7
// manual, "Specular Reflection"; the same function as its metallic highlights'; measured to 10⁻⁵ on its renders).
Color metallicTint(const Color& pigment, float metallic, float cosTheta);

// How a hit's colour is split between its local shading and its two secondary rays (§c.5): local
// (1−f)(1−k), reflection (1−f)k + fF, transmission f(1−F) for filter f, reflection k and Fresnel
// reflectance F. When reflection does not replace local light (Dialect::reflectionReplacesLocal: the .cli rule,
// cs3451 §A.4.5, and POV-Ray's) local keeps (1−f) whole. POV-Ray reflects k + fF whatever the transparency
// (Dialect::transparencyDimsReflection) and, with conserve_energy, transmits only what reflection leaves,
// f(1−F)(1−k) (manual, "Conserve Energy for Reflection").
struct Weights {
  float local = 1, reflection = 0, transmission = 0;
  Color reflectionTint{1};  // a colour reflection over `reflection` (SurfaceExtras::reflectionTint)
};
Weights weights(const Material& m, float fresnel, const Dialect& dialect);

}  // namespace rt
