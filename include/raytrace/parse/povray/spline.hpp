// POV-Ray's `spline { … }` (manual, "Spline"), called as `S(t)` or `S(t, TYPE)` and read by
// `function { spline { … } }`: points at parameter values, joined by one of four kinds of curve.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "raytrace/parse/povray/value.hpp"

namespace rt::povray {

enum class SplineKind { Linear, Quadratic, Cubic, Natural };

// The kind a keyword names (linear_spline …), or nothing.
std::optional<SplineKind> splineKindNamed(std::string_view word);

struct SplinePoints {
  SplineKind kind = SplineKind::Linear;
  std::vector<double> t;                    // increasing
  std::vector<std::array<double, 5>> p;     // the point at each t
  int size = 1;                             // the most components of any point: the size of the value
};

// A spline block's points: a spline identifier's first, then a kind and `t, <point>` pairs (a later point at
// the same t replaces the earlier one). A located error for anything else.
SplinePoints splinePoints(const Node& spline);

// The spline's point at t, interpolated as `kind`.
std::array<double, 5> splineAt(const SplinePoints& s, double t, SplineKind kind);

}  // namespace rt::povray
