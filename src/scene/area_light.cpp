#include "raytrace/scene/area_light.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

AreaLight::AreaLight(const AreaDesc& area)
    : axis1(area.axis1),
      axis2(area.axis2),
      size1(std::max(area.size1, 1)),
      size2(std::max(area.size2, 1)),
      adaptive(area.adaptive),
      jitter(area.jitter),
      circular(area.circular),
      orient(area.orient),
      illumination(area.illumination) {}

void AreaLight::axesToward(const glm::dvec3& center, const glm::dvec3& point, glm::dvec3& a1,
                           glm::dvec3& a2) const {
  a1 = axis1;
  a2 = axis2;
  if (!orient) return;
  const glm::dvec3 d = point - center;
  if (glm::length(d) == 0) return;
  const glm::dvec3 z = glm::normalize(d);
  // The first axis's part across the direction keeps its bearing; one along it takes any perpendicular.
  glm::dvec3 u = axis1 - glm::dot(axis1, z) * z;
  if (glm::length(u) < 1e-9 * glm::length(axis1)) u = glm::cross(z, std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
  u = glm::normalize(u);
  a1 = u * glm::length(axis1);
  a2 = glm::cross(z, u) * glm::length(axis2);
}

glm::dvec3 AreaLight::point(int i, int j, const glm::dvec3& center, const glm::dvec3& a1, const glm::dvec3& a2,
                            glm::vec2 offset) const {
  // Cell (i, j)'s point at u, v ∈ [−½, ½], jittered by up to half a cell either way.
  const auto along = [&](int k, int size, float o) {
    if (size == 1) return 0.0;
    const double cell = 1.0 / (size - 1);
    return k * cell - 0.5 + (jitter ? (double(o) - 0.5) * cell : 0.0);
  };
  double u = along(i, size1, offset.x), v = along(j, size2, offset.y);
  if (circular && (u != 0 || v != 0)) {
    const double f = std::max(std::abs(u), std::abs(v)) / std::sqrt(u * u + v * v);
    u *= f;
    v *= f;
  }
  return center + u * a1 + v * a2;
}

bool AreaLight::differ(const Color (&c)[4]) {
  for (int a = 0; a < 4; ++a) {
    for (int b = a + 1; b < 4; ++b) {
      const Color d = glm::abs(c[a] - c[b]);
      if (d.r + d.g + d.b > 0.1f) return true;
    }
  }
  return false;
}

}  // namespace rt
