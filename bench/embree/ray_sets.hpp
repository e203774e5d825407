// The rays the Embree comparison traces, made as the renderer makes them: eye rays in the order and packets of
// `render`, and from their hits the shadow rays toward each light, the mirror bounces and cosine-distributed
// diffuse bounces (Monte Carlo's bulk, the rays packets help least).
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "raytrace/accel/scene.hpp"
#include "raytrace/render/camera.hpp"
#include "raytrace/render/shading.hpp"
#include "raytrace/geometry/spawn.hpp"

namespace rt::bench {

// A set of rays of one kind and how they are asked: the closest hit or whether anything blocks them, in
// packets of up to Bvh<T>::kPacket (packet k is rays [start[k], start[k + 1])) or one at a time.
template <class T> struct RaySet {
  RaySet(std::string name, bool anyHitQuery, bool inPackets)
      : kind(std::move(name)), anyHit(anyHitQuery), packets(inPackets) {}

  std::string kind;
  bool anyHit = false;
  bool packets = false;
  std::vector<Ray<T>> rays;
  std::vector<Interval<T>> ranges;
  std::vector<int> light;            // any-hit sets: the light each ray aims at (the shadow cache's key)
  std::vector<uint32_t> start{0};    // packet bounds, the last one rays.size()

  void add(const Ray<T>& ray, Interval<T> range, int toLight = -1) {
    rays.push_back(ray);
    ranges.push_back(range);
    light.push_back(toLight);
  }
  void endPacket() {
    if (start.back() != rays.size()) start.push_back(uint32_t(rays.size()));
  }
  // The same rays, asked one at a time.
  RaySet singles(const std::string& name) const {
    RaySet s = *this;
    s.kind = name;
    s.packets = false;
    s.start = {0, uint32_t(rays.size())};
    return s;
  }
};

// The normal on the side the ray arrives from, the one shading uses.
template <class T> Vec3<T> viewerNormal(const Hit<T>& hit, const Ray<T>& ray) {
  return glm::dot(ray.dir, hit.normal) <= T(0) ? hit.normal : -hit.normal;
}

// A direction about n with density cos θ / π: a uniform point of the unit disc lifted onto the hemisphere
// (Malley's method; Pharr et al., PBRT 3rd ed. §13.6.3), in the basis of Duff et al., "Building an
// Orthonormal Basis, Revisited", JCGT 2017.
template <class T> Vec3<T> cosineDirection(const Vec3<T>& n, double u1, double u2) {
  const T sign = std::copysign(T(1), n.z);
  const T a = T(-1) / (sign + n.z), b = n.x * n.y * a;
  const Vec3<T> s(T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x);
  const Vec3<T> t(b, sign + n.y * n.y * a, -n.y);
  const double r = std::sqrt(u1), phi = 2 * M_PI * u2;
  return glm::normalize(T(r * std::cos(phi)) * s + T(r * std::sin(phi)) * t + T(std::sqrt(1 - u1)) * n);
}

// Eye rays of width × height pixels in the renderer's order (32-pixel tiles column by column, each row of a
// tile in packets of 16), then the rays of the eye rays' hits. The eye hits come from `scene` itself.
template <class T>
std::vector<RaySet<T>> makeRaySets(const Scene<T>& scene, const Camera<T>& camera, uint32_t seed) {
  constexpr int kTile = 32, kPacket = Bvh<T>::kPacket;
  const int width = camera.width(), height = camera.height();
  RaySet<T> eye("eye", false, true);
  for (int tile = 0, tilesY = (height + kTile - 1) / kTile; tile < (width + kTile - 1) / kTile * tilesY; ++tile) {
    const int x0 = tile / tilesY * kTile, y0 = tile % tilesY * kTile;
    for (int y = y0; y < std::min(height, y0 + kTile); ++y) {
      for (int x = x0; x < std::min(width, x0 + kTile); ++x) {
        eye.add(camera.pixelRay(x, y), {});
        if ((x - x0) % kPacket == kPacket - 1) eye.endPacket();
      }
      eye.endPacket();
    }
  }
  RaySet<T> shadow("shadow", true, true), mirror("mirror", false, false), diffuse("diffuse", false, false);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const OffsetPolicy offset = *scene.arithmetic().offset;
  const auto& lights = scene.lights();
  for (size_t k = 0; k + 1 < eye.start.size(); ++k) {
    const int first = int(eye.start[k]), n = int(eye.start[k + 1]) - first;
    std::optional<Hit<T>> hits[kPacket];
    scene.closestHits(&eye.rays[size_t(first)], n, {}, hits);
    // Toward each light, the rays of the packet's hits that face it, asked as one packet (Tracer::block).
    for (size_t l = 0; l < lights.size(); ++l) {
      for (int i = 0; i < n; ++i) {
        if (!hits[i]) continue;
        const Vec3<T> normal = viewerNormal(*hits[i], eye.rays[size_t(first + i)]);
        const Vec3<T> dir = glm::normalize(lights[l].position - hits[i]->point);
        if (!(glm::dot(normal, dir) > T(0))) continue;
        Ray<T> ray;
        Interval<T> segment;
        spawnRayTo(*hits[i], lights[l].position, dir, normal, offset, ray, segment);
        shadow.add(ray, segment, int(l));
      }
      shadow.endPacket();
    }
    for (int i = 0; i < n; ++i) {
      if (!hits[i]) continue;
      const Ray<T>& ray = eye.rays[size_t(first + i)];
      const Vec3<T> normal = viewerNormal(*hits[i], ray);
      mirror.add(spawnRay(*hits[i], reflectDirection(ray.dir, normal), offset), {});
      const double u1 = uniform(random), u2 = uniform(random);
      diffuse.add(spawnRay(*hits[i], cosineDirection(normal, u1, u2), offset), {});
    }
  }
  mirror.start.push_back(uint32_t(mirror.rays.size()));
  diffuse.start.push_back(uint32_t(diffuse.rays.size()));
  RaySet<T> eyeSingles = eye.singles("eye 1"), shadowSingles = shadow.singles("shadow 1");
  eye.kind = "eye 16";
  shadow.kind = "shadow 16";
  return {eye, eyeSingles, shadow, shadowSingles, mirror, diffuse};
}

}  // namespace rt::bench
