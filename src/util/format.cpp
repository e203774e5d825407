#include "raytrace/util/format.hpp"

#include <cstdio>

namespace rt {

std::string fixed4(double v) {
  // The longest: a sign, DBL_MAX's 309 integer digits, the point, 4 decimals and the terminating zero.
  char buf[316];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

std::string shortest(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string bare(const glm::dvec3& v) { return fixed4(v.x) + " " + fixed4(v.y) + " " + fixed4(v.z); }
std::string braces(const glm::dvec3& v) { return "{" + bare(v) + "}"; }

}  // namespace rt
