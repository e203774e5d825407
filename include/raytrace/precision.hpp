// "Model no more than a scene needs": pick the cheapest arithmetic that keeps the scene's pixels exact.
#pragma once

#include <utility>

#include "raytrace/scene_desc.hpp"

namespace rt {

enum class Precision { Auto, Float, Double };
enum class SphereMethod { Auto, Textbook, Robust };

struct Arithmetic {
  Precision precision = Precision::Auto;
  SphereMethod sphere = SphereMethod::Auto;
};

// The scene's precision budget R = (largest coordinate or ray length) ÷ smallest feature (stability.md §1.1);
// ray lengths are bounded by the diagonal of the box around the camera and the objects.
double precisionBudget(const SceneDesc& scene);

// The cheapest arithmetic that keeps a scene's pixels exact (stability.md §1.1): no ray may flip between hit
// and miss, and no sphere t error may exceed 1e-2 of the smallest feature. Measured over 20k rays per cell
// (tests/test_stability_sphere.cpp), |Δt|/r at p99 / max:
//   textbook float  R = 20: 1.8e-4 / 7e-4;  R = 50: 1.1–1.3e-3 / 4–6e-3 (rays at 0.999·r);  R = 100: 5e-3 / 2e-2
//   robust float    R = 1e3: 1.5e-4 / 5e-4;  R = 2e3: 2.9e-4 / 1.3e-3;  R = 1e4: 1.8e-3 / 6e-3
// with no flipped hit up to R = 100 (textbook) and R = 1e4 (robust). Both float tiers stop where their worst
// rays reach ≈ 6e-3·r: the textbook quadratic while R ≤ 50 (its digits are also the ones the course's expected
// outputs encode), the robust test while R ≤ 1e4; the robust test in double beyond. Such errors sit on grazing
// rays at the rim, and the re-projected hit point turns them into a normal error below 1/255 of shading.
// Explicit requests in `requested` win.
Arithmetic chooseArithmetic(const SceneDesc& scene, Arithmetic requested = {});

// Calls f(T{}) with T = float or double as chosen, so one generic lambda serves both precisions.
template <class F> decltype(auto) withPrecision(Precision p, F&& f) {
  if (p == Precision::Double) return std::forward<F>(f)(double{});
  return std::forward<F>(f)(float{});
}

}  // namespace rt
