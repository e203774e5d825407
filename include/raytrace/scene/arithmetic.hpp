// "Model no more than a scene needs": pick the cheapest arithmetic that keeps the scene's pixels exact.
#pragma once

#include <optional>
#include <utility>

#include "raytrace/scene/description.hpp"
#include "raytrace/geometry/roots.hpp"
#include "raytrace/geometry/spawn.hpp"
#include "raytrace/scene/scene_scale.hpp"
#include "raytrace/scene/tier_domain.hpp"

namespace rt {

// What arithmetic a scene's geometry is computed in. Float and Double are precisions; Course is a
// compatibility mode: the 2018 CSC 473 reference renderer's own float arithmetic, which its expected images
// encode down to the rounding (docs/reference/csc473.md). Float, with the matrices composed in float as the
// reference composes them (composeTransforms<float>), every transformed object intersected on the
// transformed ray (no sphere folded into a world sphere), hit points o + t·d as the ray reaches them (not
// re-projected onto the surface), a transformed object's normal taken at M⁻¹·(o + t·d), and spawned rays
// offset 0.001 along the normal (OffsetPolicy::Course). Chosen only where it is sound: see chooseArithmetic().
enum class Tier {
  Auto,
  Float,
  Double,
  Course,
};

// What chooseArithmetic() is asked for (Auto and nothing: choose) and what it answers (all resolved).
struct Arithmetic {
  Tier tier = Tier::Auto;
  SphereMethod sphere = SphereMethod::Auto;
  std::optional<OffsetPolicy> offset;  // spawned-ray origins; nothing: the tier's own
};

// The course tier's domain, where its fixed 0.001 offset (kCourseEpsilon) is sound in float. An offset must
// stay below the smallest feature, or a spawned ray starts beyond a thin object: features of at least twice
// the offset. And it must dwarf the rounding of the coordinates it is added to: float's ulp at 1e3 is 6e-5,
// well below 0.001, while at 1e4 it is 1e-3 itself.
constexpr double kCourseMinFeature = 2 * kCourseEpsilon;
constexpr double kCourseMaxExtent = 1e3;

// The cheapest arithmetic whose answer cannot differ visibly from the exact one (docs/accuracy.md, "Choosing
// the arithmetic"), for eye rays on `view`'s grid:
// - the course tier (textbook quadratic, 0.001 offsets) for a POV scene (the course's language) inside its
//   domain: features of at least 2·0.001, coordinates up to 1e3, sphere errors below kVisiblePixels and a
//   quarter of the offset, no shadow edge or refracted image moved by the offset more than kVisiblePixels,
//   and no sphere within 2·0.001 of another or of a plane;
// - else float while R ≤ 1e4 and the robust sphere test's error stays below kVisiblePixels, with the
//   textbook quadratic while R ≤ 50 and its error does too (measured budgets: docs/reference/stability.md §1.1);
// - else double, robust.
// The offset is the tier's: Course for the course tier, Relative for the others. Explicit requests in
// `requested` win, each on its own.
Arithmetic chooseArithmetic(const SceneDesc& scene, Arithmetic requested = {}, View view = {});

// Calls f(T{}) with T = float or double as chosen, so one generic lambda serves both precisions.
// The course tier computes in float.
template <class F> decltype(auto) withPrecision(Tier p, F&& f) {
  if (p == Tier::Double) return std::forward<F>(f)(double{});
  return std::forward<F>(f)(float{});
}

}  // namespace rt
