// An open parameter interval (min, max) along a ray. Intersection routines accept a root only if the interval
// surrounds it; written as `min < t && t < max` so that a NaN t is always rejected.
#pragma once

#include <limits>

namespace rt {

template <class T> struct Interval {
  T min = T(0);
  T max = std::numeric_limits<T>::infinity();

  bool surrounds(T t) const { return min < t && t < max; }
};

}  // namespace rt
