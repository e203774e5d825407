// The Whitted ray tracer: one routine follows a ray, shades its closest hit and recurses into the reflected
// and refracted rays. Diagnostics (printrays, pixeltrace, pixelcolor) run the same routine with a RayRecord to
// fill, so they print what the renderer computes.
#pragma once

#include <vector>

#include "raytrace/render/camera.hpp"
#include "raytrace/geometry/math.hpp"
#include "raytrace/render/ray_tree.hpp"
#include "raytrace/render/options.hpp"
#include "raytrace/accel/scene.hpp"

namespace rt {

template <class T> class Tracer {
 public:
  // Reads the options and the scene's Conventions; `scene` must outlive the tracer. A tracer keeps a shadow
  // cache, so each thread uses its own copy.
  Tracer(const Scene<T>& scene, const RenderOptions& options);

  // The colour of pixel (x, y): the float average of options.samples² stratified eye rays. With `trees`, the
  // ray tree of each eye ray is appended to it.
  Color pixel(const Camera<T>& camera, int x, int y, std::vector<RayRecord>* trees = nullptr);
  // The colours of the pixels of [x0, x1) × [y0, y1), row by row from y0, each the colour pixel() gives it: the
  // eye rays and their shadow rays go through the scene in packets (Scene::closestHits), the rest one ray at a
  // time. They are the tracer's own memory, valid until its next call.
  const Color* block(const Camera<T>& camera, int x0, int y0, int x1, int y1);

 private:
  struct Traced {
    Color color;
    T distance;  // to the hit, +∞ on a miss (Beer's law needs it)
  };

  struct Local {
    Color diffuse{0}, specular{0};
  };

  struct ShadowRay {
    Ray<T> ray;            // aimed at the light from its offset origin (spawnRayTo)
    Interval<T> segment;
    Vec3<T> l;             // the unit vector from the point itself to the light, which shading uses
    float nl;              // n·l
    bool blocked = false;  // the answer, once asked
  };

  Traced trace(const Ray<T>& ray, RayRecord::Kind kind, int depth, float weight, RayRecord* record);
  // trace() once the closest hit is known; `shadows`, if given, are the hit's shadow rays (one per light, as
  // shadowRay() makes them) with their answers, found beforehand for a whole packet.
  Traced follow(const Ray<T>& ray, const std::optional<Hit<T>>& hit, RayRecord::Kind kind, int depth,
                float weight, RayRecord* record, const std::optional<ShadowRay>* shadows);
  Color shade(const Ray<T>& ray, const Hit<T>& hit, int depth, float weight, RayRecord* record,
              const std::optional<ShadowRay>* shadows);
  // Diffuse and specular light from every light the point sees (§c.1, §c.7), before weighting. `n` is the
  // shading normal on the viewer's side, `v` the unit vector to the viewer.
  Local direct(const Hit<T>& hit, const Vec3<T>& n, const Vec3<T>& v, RayRecord* record,
               const std::optional<ShadowRay>* shadows);
  // The shadow ray toward `light`, or false when the light cannot light the point from the viewer's side `n`:
  // a light behind the surface as the viewer sees it, or on the point itself.
  // It is written into `out` in place: it is made for every hit and light, and a returned copy would stall
  // (docs/performance-notes.md, "Shadow rays built in place").
  bool shadowRay(const Hit<T>& hit, const Vec3<T>& n, const Light<T>& light, ShadowRay& out) const;
  // Whether a secondary ray of accumulated weight `weight` at `depth` is worth tracing (docs/reference/stability.md
  // F12).
  bool matters(float weight, int depth) const;

  const Scene<T>& scene_;
  RenderOptions options_;
  Conventions conventions_;
  std::vector<float> bound_;  // bound_[r]: the brightest colour a ray with r levels of recursion left can return
  float cutoff_;
  std::vector<const Object<T>*> lastBlocker_;  // per light: what blocked its latest shadow ray (Scene::occluded)
  std::vector<Ray<T>> rays_;                   // block()'s eye rays and their colours, kept to reuse the memory
  std::vector<Color> colors_;
  std::vector<std::optional<ShadowRay>> shadows_;  // a packet's shadow rays, ray by ray and light by light
};

}  // namespace rt
