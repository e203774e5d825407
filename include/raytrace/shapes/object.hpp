// The abstract scene object: every shape answers one query, the closest intersection inside an open interval.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "raytrace/geometry/aabb.hpp"
#include "raytrace/geometry/hit.hpp"
#include "raytrace/geometry/interval.hpp"
#include "raytrace/geometry/ray.hpp"
#include "raytrace/surface/material.hpp"
#include "raytrace/surface/texture.hpp"

namespace rt {

template <class T> class Object {
 public:
  Object(const Material& material, int id) : material_(material), id_(id) {}
  virtual ~Object() = default;

  // The closest intersection whose t lies strictly inside `range`, or nothing. On a hit, `point` lies on the
  // surface (re-projected, not just ray.at(t)) and `normal` is the unit outward normal at it.
  virtual std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const = 0;

  // The tests of a packet of rays, one call per object and packet: a shape whose test is a few operations
  // answers them in a loop the processor pipelines, without a call per ray. closerHits, for the objects
  // scanned in file order rather than through a hierarchy (Scene): best[i] becomes this object's hit on
  // rays[i] when one lies strictly inside `range` and strictly before best[i]; an equal t keeps the earlier
  // object. occludes, for shadow rays, in the scan and in the hierarchy's leaves: the rays among `open` that
  // this object meets strictly inside ranges[i], as a bit mask (a sphere skips the hit record they would not
  // use).
  virtual void closerHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* best) const {
    for (int i = 0; i < n; ++i) {
      if (auto hit = intersect(rays[i], {range.min, best[i] ? best[i]->t : range.max})) best[i] = hit;
    }
  }
  virtual uint32_t occludes(const Ray<T>* rays, const Interval<T>* ranges, uint32_t open) const {
    uint32_t occluded = 0;
    for (uint32_t mask = open; mask; mask &= mask - 1) {
      const int i = __builtin_ctz(mask);
      if (intersect(rays[i], ranges[i])) occluded |= 1u << i;
    }
    return occluded;
  }
  // occludes(), with this object made the occluder of each ray it meets; returns those rays.
  uint32_t noteOccluder(const Ray<T>* rays, const Interval<T>* ranges, uint32_t open,
                        const Object** occluders) const {
    const uint32_t met = occludes(rays, ranges, open);
    for (uint32_t mask = met; mask; mask &= mask - 1) occluders[__builtin_ctz(mask)] = this;
    return met;
  }

  // The outward normal at `point`, a point on the surface at or next to `hit`: the course tier takes a
  // transformed object's normal where its world hit point maps back to (Transformed). A sphere computes it
  // from the point, as the course's reference does; the other shapes keep the hit's, the same on a flat face.
  virtual Vec3<T> normalAt(const Vec3<T>& point, const Hit<T>& hit) const {
    static_cast<void>(point);
    return hit.normal;
  }

  // Whether `point` lies strictly inside the solid: what CSG keeps or cuts away (shapes/csg). A shape that
  // encloses nothing (a triangle) has no inside.
  virtual bool inside(const Vec3<T>& point) const = 0;
  // Whether `point` lies inside the solid's complement, what a difference keeps of the first child: POV-Ray's
  // inverse of the solid, which keeps a clipped object's clips (shapes/clipped); for any other, not inside.
  virtual bool insideComplement(const Vec3<T>& point) const { return !inside(point); }

  // World-space bounds, or nothing for unbounded shapes (planes), which stay outside any hierarchy.
  virtual std::optional<Aabb<T>> bounds() const = 0;

  // The type name the course prints ("Sphere", "Plane", …; shapeName() for the description's shapes).
  virtual const char* name() const = 0;

  const Material& material() const { return material_; }
  // What shading reads at a hit on the surface: the texture there (at the hit's uv for a uv_mapping texture),
  // written into `scratch`, or the constant material of an object without one. The one test costs an
  // untextured scene nothing measurable (docs/performance.md, "Textures").
  const Material& materialAt(const Hit<T>& hit, Material& scratch) const {
    if (!texture_) return material_;
    textured(hit, scratch, hit.normal);
    return scratch;
  }
  // The same, and the shading normal `normal` (facing the viewer) bent where the texture has a normal; the
  // interior_texture is what a hit sees where `normal` points into the object.
  const Material& materialAt(const Hit<T>& hit, Material& scratch, Vec3<T>& normal) const {
    if (!texture_) return material_;
    const Texture& seen = textured(hit, scratch, normal);
    if (seen.bumpy) normal = Vec3<T>(seen.bent(glm::dvec3(hit.point), glm::dvec3(normal)));
    return scratch;
  }
  void setTexture(std::shared_ptr<const Texture> texture) { texture_ = std::move(texture); }
  // Calls f(material) for every material a hit on this object can report: its own, or a group's parts'.
  // A textured object reports its texture's bound, and its own material too, which holds its interior (media).
  virtual void forEachMaterial(const std::function<void(const Material&)>& f) const {
    if (texture_) f(texture_->bound);
    f(material_);
  }
  int id() const { return id_; }  // 1-based position in the scene file, as printrays shows it

 private:
  // The texture at the hit into `scratch`, where `facing` is the surface's normal that a slope pattern reads;
  // returns the texture seen: the interior one where `facing` points into the object.
  const Texture& textured(const Hit<T>& hit, Material& scratch, const Vec3<T>& facing) const {
    const Texture& seen = texture_->interior && glm::dot(facing, hit.normal) < T(0) ? *texture_->interior : *texture_;
    if (seen.readsNormal) setSurfaceNormal(glm::normalize(glm::dvec3(facing)));
    scratch = seen.uvMapped ? seen.inSpace(glm::dvec3(hit.uv, 0)) : seen.at(glm::dvec3(hit.point));
    return seen;
  }

  Material material_;
  int id_;
  std::shared_ptr<const Texture> texture_;
};

}  // namespace rt
