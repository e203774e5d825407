#include "raytrace/scene/tier_domain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "raytrace/geometry/spawn.hpp"
#include "raytrace/scene/scene_scale.hpp"

namespace rt {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

glm::dvec3 toWorld(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1)); }

// A plane's normal is carried by the inverse transpose.
glm::dvec3 normalToWorld(const glm::dmat4& m, const glm::dvec3& n) {
  return glm::normalize(glm::transpose(glm::inverse(glm::dmat3(m))) * n);
}

double brightest(const Color& c) { return std::max({double(c.r), double(c.g), double(c.b)}); }

// A point of a flat surface with its outward normal, the material that shades it, and the camera: the
// largest shift in pixels of a shadow edge through it, over the lights (docs/accuracy.md, "offset").
struct FlatSample {
  glm::dvec3 point, normal;
};
double shadowShiftPixels(const SceneDesc& scene, const Material& m, const FlatSample& s, double theta) {
  glm::dvec3 n = s.normal;
  const glm::dvec3 toCamera = scene.camera.location - s.point;
  const double seen = glm::dot(n, toCamera);
  if (seen == 0) return 0;
  if (seen < 0) n = -n;  // the side the camera sees
  double worst = 0;
  for (const LightDesc& light : scene.lights) {
    const glm::dvec3 toLight = light.position - s.point;
    const double cosPhi = glm::dot(n, toLight) / glm::length(toLight);
    if (!(cosPhi > 0)) continue;
    const double change = brightest(light.color * (m.diffuse * float(cosPhi) + m.specular));
    if (change < kVisibleLight) continue;
    const double tanPhi = std::sqrt(std::max(0.0, 1 - cosPhi * cosPhi)) / cosPhi;
    worst = std::max(worst, kCourseEpsilon * tanPhi / (theta * glm::length(toCamera)));
  }
  return worst;
}

// An unbounded plane: the camera's foot F and height H over it, the light's foot and height. A point at
// distance ρ from F is at most ρ + |F − F_light| from the light's foot, so tan φ ≤ (ρ + b)/H_light there
// while the camera is √(H² + ρ²) away. The worst ρ is found on a geometric grid out to 1e7 (POV-Ray's own
// horizon), keeping only distances where the light still shows.
double planeShadowPixels(const SceneDesc& scene, const Material& m, glm::dvec3 n, double d, double theta) {
  const double hc = glm::dot(n, scene.camera.location) - d;
  if (hc == 0) return 0;
  if (hc < 0) {
    n = -n;
    d = -d;
  }
  const double cameraHeight = std::abs(hc);
  const glm::dvec3 cameraFoot = scene.camera.location - hc * (hc < 0 ? -n : n);
  double worst = 0;
  for (const LightDesc& light : scene.lights) {
    const double hl = glm::dot(n, light.position) - d;
    if (!(hl > 0)) continue;
    const glm::dvec3 lightFoot = light.position - hl * n;
    const double b = glm::length(lightFoot - cameraFoot);
    for (double rho = 0; rho <= 1e7; rho = rho == 0 ? 1e-3 : rho * 1.05) {
      const double rhoLight = rho + b;
      const double cosPhi = hl / std::hypot(hl, rhoLight);
      const double change = brightest(light.color * (m.diffuse * float(cosPhi) + m.specular));
      if (change < kVisibleLight) break;  // farther out the light only fades
      const double shift = kCourseEpsilon * (rhoLight / hl) / (theta * std::hypot(cameraHeight, rho));
      worst = std::max(worst, shift);
    }
  }
  return worst;
}

// The flat faces an object's kind gives (shapes/kind.hpp): a parallelogram sampled on a 5 × 5 grid of
// points, a triangle at its corners and edge midpoints (a mesh has many small triangles: that is enough).
double flatShadowPixels(const SceneDesc& scene, const ObjectDesc& o, const glm::dmat4& m, double theta) {
  const FlatFaces faces = std::visit([](const auto& k) { return k.flatFaces(); }, o.shape);
  double worst = 0;
  for (size_t k = 0; k < faces.count; ++k) {
    const FlatFace& f = faces.face[k];
    const int steps = f.triangle ? 2 : 4;
    const glm::dvec3 normal = normalToWorld(m, glm::cross(f.u, f.v));
    if (glm::any(glm::isnan(normal))) continue;
    for (int i = 0; i <= steps; ++i) {
      for (int j = 0; j <= steps - (f.triangle ? i : 0); ++j) {
        const glm::dvec3 p = toWorld(m, f.corner + f.u * (double(i) / steps) + f.v * (double(j) / steps));
        worst = std::max(worst, shadowShiftPixels(scene, o.material, {p, normal}, theta));
      }
    }
  }
  return worst;
}

struct WorldSphere {
  glm::dvec3 center;
  double radius, bound, most, least;  // own radius; bounding radius in the world; the transform's stretch
};

// The world plane n·p = d of a plane object.
std::pair<glm::dvec3, double> worldPlane(const PlaneDesc& p, const glm::dmat4& m) {
  const glm::dvec3 n = normalToWorld(m, p.normal);
  return {n, glm::dot(n, toWorld(m, p.distance * glm::normalize(p.normal)))};
}

WorldSphere worldSphere(const SphereDesc& s, const glm::dmat4& m) {
  const Stretch k = stretch(m);
  return {toWorld(m, s.center), s.radius, k.most * s.radius, k.most, k.least};
}

// The smallest clearance between two spheres, by a sweep along x, and between a sphere and a plane.
double closestPair(std::vector<WorldSphere> spheres, const std::vector<std::pair<glm::dvec3, double>>& planes) {
  double gap = kInf;
  for (const WorldSphere& s : spheres) {
    for (const auto& [n, d] : planes) gap = std::min(gap, std::abs(glm::dot(n, s.center) - d) - s.bound);
  }
  std::sort(spheres.begin(), spheres.end(),
            [](const WorldSphere& a, const WorldSphere& b) { return a.center.x - a.bound < b.center.x - b.bound; });
  // Only neighbours closer than 2·kCourseEpsilon matter to the course tier; pairs farther apart along x are
  // not measured.
  const double reach = 2 * kCourseEpsilon;
  for (size_t i = 0; i < spheres.size(); ++i) {
    const WorldSphere& a = spheres[i];
    for (size_t j = i + 1; j < spheres.size(); ++j) {
      const WorldSphere& b = spheres[j];
      if (b.center.x - b.bound > a.center.x + a.bound + reach) break;
      gap = std::min(gap, glm::length(a.center - b.center) - a.bound - b.bound);
    }
  }
  return gap;
}

}  // namespace

double textbookSphereError(double D, double r) { return 8 * kFloatRoundoff * D * D / r + 4 * kFloatRoundoff * D; }

double robustSphereError(double D) { return 9 * kFloatRoundoff * D; }

double pixelAngle(const CameraDesc& c, View view) {
  const double across = glm::length(c.right) * (c.rightFollowsImage ? double(view.width) / view.height : 1.0);
  const double up = glm::length(c.up);
  // An image-plane step s at the corner, (across/2, up/2) from the centre at distance 1, subtends s·cos²α.
  const double cos2 = 1 / (1 + across * across / 4 + up * up / 4);
  return std::min(across / view.width, up / view.height) * cos2;
}

TierDomain tierDomain(const SceneDesc& scene, View view) {
  TierDomain out;
  const double theta = pixelAngle(scene.camera, view);
  const SceneScale scale = sceneScale(scene);
  // Rays start at the camera and on every bounded object, inside the scale's box.
  const auto farthest = [&](const glm::dvec3& c) {
    return glm::length(glm::max(glm::abs(scale.hi - c), glm::abs(c - scale.lo)));
  };
  for (const ObjectDesc& o : scene.objects) {
    const glm::dmat4 m = o.worldFromObject();
    if (const auto* p = std::get_if<PlaneDesc>(&o.shape)) {
      const auto [n, d] = worldPlane(*p, m);
      out.offsetShadowPixels = std::max(out.offsetShadowPixels, planeShadowPixels(scene, o.material, n, d, theta));
      continue;
    }
    const auto* sphere = std::get_if<SphereDesc>(&o.shape);
    if (!sphere) {
      out.offsetShadowPixels = std::max(out.offsetShadowPixels, flatShadowPixels(scene, o, m, theta));
      continue;
    }
    const WorldSphere s = worldSphere(*sphere, m);
    // In the sphere's own space (where the course tier solves it) the origins are up to 1/least farther per
    // world unit, and its errors come back stretched by at most `most`.
    const double D = farthest(s.center) / s.least;
    const double nearSurface = std::max(glm::length(scene.camera.location - s.center) - s.bound, s.least * s.radius);
    const double footprint = theta * nearSurface;
    const double textbook = s.most * textbookSphereError(D, s.radius);
    out.textbookPixels = std::max(out.textbookPixels, textbook / footprint);
    out.robustPixels = std::max(out.robustPixels, s.most * robustSphereError(D) / footprint);
    out.textbookHitError = std::max(out.textbookHitError, textbook);
    if (o.material.filter != 0) {
      const double behind = farthest(s.center);
      out.offsetRefractionPixels =
          std::max(out.offsetRefractionPixels, 2 * kCourseEpsilon / (s.least * s.radius) * behind / footprint);
    }
  }
  return out;
}

double smallestGap(const SceneDesc& scene) {
  std::vector<WorldSphere> spheres;
  std::vector<std::pair<glm::dvec3, double>> planes;
  for (const ObjectDesc& o : scene.objects) {
    if (const auto* s = std::get_if<SphereDesc>(&o.shape)) spheres.push_back(worldSphere(*s, o.worldFromObject()));
    if (const auto* p = std::get_if<PlaneDesc>(&o.shape)) planes.push_back(worldPlane(*p, o.worldFromObject()));
  }
  return closestPair(std::move(spheres), planes);
}

}  // namespace rt
