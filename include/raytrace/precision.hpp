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

// The scene's precision budget R = largest coordinate ÷ smallest feature (stability.md §1.1).
double precisionBudget(const SceneDesc& scene);

// The cheapest arithmetic whose sphere t error stays below 1e-3 of the smallest feature (stability.md §1.1):
// the textbook quadratic in float (error ≈ 3εR²) while R ≤ 50, the robust test in float (≈ 4.5εR) while
// R ≤ 1e3, the robust test in double beyond. Explicit requests in `requested` win.
Arithmetic chooseArithmetic(const SceneDesc& scene, Arithmetic requested = {});

// Calls f(T{}) with T = float or double as chosen, so one generic lambda serves both precisions.
template <class F> decltype(auto) withPrecision(Precision p, F&& f) {
  if (p == Precision::Double) return std::forward<F>(f)(double{});
  return std::forward<F>(f)(float{});
}

}  // namespace rt
