// The Whitted ray tracer: one routine follows a ray, shades its closest hit and recurses into the reflected
// and refracted rays. Diagnostics (printrays, pixeltrace, pixelcolor) run the same routine with a RayRecord to
// fill, so they print what the renderer computes.
#pragma once

#include <cstdint>
#include <vector>

#include "raytrace/render/camera.hpp"
#include "raytrace/geometry/math.hpp"
#include "raytrace/render/irradiance_cache.hpp"
#include "raytrace/render/ray_counts.hpp"
#include "raytrace/render/ray_tree.hpp"
#include "raytrace/render/options.hpp"
#include "raytrace/accel/scene.hpp"

namespace rt {

// The depth up to which an eye ray's tree is traced in full wherever its rays can change the pixel; deeper
// recursion (--depth above it) stays within that many rays per eye ray, 2^13 − 1 (tracer.cpp).
constexpr int kFullTreeDepth = 12;
// The most rays one eye sample may cost with -gi, its tree and every tree it gathers together (2^20): gathering
// multiplies trees (each gathered ray has a tree of its own, which gathers again), and this keeps a pixel's
// work bounded whatever the depth, bounces and sample counts; renders below it are unchanged (tracer.cpp).
constexpr uint64_t kSampleRays = uint64_t(1) << 20;

template <class T> class Tracer {
 public:
  // Reads the options and the scene's Dialect; `scene` must outlive the tracer. A tracer keeps a shadow
  // cache and its buffers, so each thread uses its own copy.
  Tracer(const Scene<T>& scene, const RenderOptions& options);

  // The colour of pixel (x, y): the float average of options.samples² stratified eye rays. With `trees`, the
  // ray tree of each eye ray is appended to it, and with -gi `gathers` receives the gather rays per bounce.
  Color pixel(const Camera<T>& camera, int x, int y, std::vector<RayRecord>* trees = nullptr,
              std::vector<GatherSummary>* gathers = nullptr);
  // The colours of the pixels of [x0, x1) × [y0, y1), row by row from y0, each the colour pixel() gives it: the
  // eye rays and their shadow rays go through the scene in packets (Scene::closestHits), and so do the gather
  // rays of each hit. They are the tracer's own memory, valid until its next call.
  const Color* tile(const Camera<T>& camera, int x0, int y0, int x1, int y1);
  // The radiance of each of `count` eye rays, traced together in packets as tile() traces them; keys[i] is
  // the root of ray i's random numbers (pixelKey). Neither averaged nor finished; the tracer's own memory,
  // valid until its next call. Adaptive anti-aliasing (render/antialias) traces its samples with it.
  const Color* eyeRays(const Ray<T>* rays, const uint64_t* keys, size_t count);
  // A pixel's average as it is written: raised to the scene's gamma (Dialect::gamma). Inline: anti-aliasing
  // finishes every pixel's first ray to compare it.
  Color finished(const Color& c) const { return dialect_.gamma() == 1 ? c : raised(c); }

  // The colour of pixel (x, y) under a camera's focal blur (render/focal_blur.cpp): lens samples until
  // POV-Ray's confidence test holds or the camera's most are taken.
  Color blurredPixel(const Camera<T>& camera, int x, int y);
  // The colour of pixel (x, y) of a mesh camera with several rays a pixel.
  Color meshPixel(const Camera<T>& camera, int x, int y);

  // With --gi-cache the first bounce's gathered light is looked up in `cache` (docs/gi.md), which must outlive
  // the tracer; a point no record covers gathers as without it and, if `made` is given, appends its record
  // there. Null: gather everywhere.
  void useCache(const IrradianceCache<T>* cache, std::vector<IrradianceRecord<T>>* made = nullptr) {
    cache_ = cache;
    made_ = made;
  }

  // The rays traced so far, by kind.
  const RayCounts& counts() const { return counts_; }

  // The memory a tracer takes per light of the scene with `options`: each batch level's shadow rays of a
  // packet, and the shadow cache. The renderer checks it before giving each thread a tracer.
  static std::uint64_t bytesPerLight(const RenderOptions& options) {
    const std::uint64_t levels = 1 + std::uint64_t(options.gi.enabled ? options.gi.bounceCount() : 0);
    return levels * Bvh<T>::kPacket * sizeof(std::optional<ShadowRay>) + sizeof(const Object<T>*);
  }

 private:
  Color raised(const Color& c) const;  // finished() with a gamma other than 1

  struct Traced {
    Color color;
    T distance;  // to the hit, +∞ on a miss (Beer's law needs it)
  };

  // One object's interior a ray is in, and those it was in before (Path::interiors), kept in the frames of
  // the rays' parents. `key` names the interior (interiorKey()). `eye`: found around the eye ray's origin,
  // `object` then being a whole scene object.
  struct InteriorLink {
    uintptr_t key;
    const Object<T>* object;
    const std::vector<Media>* media;  // null for an interior without any
    bool hollow;
    bool eye;
    const InteriorLink* outer;
  };

  // Where a ray is in the tree of its eye ray.
  struct Path {
    int depth = 0;      // reflection/refraction level, the primary ray 0 (§c.9)
    int bounce = 0;     // gather rays between the eye and this ray (docs/gi.md)
    float weight = 1;   // the accumulated weight of its colour in the pixel (docs/reference/stability.md F12)
    uint64_t key = 0;   // the root of its random numbers (sampler.hpp); 0 without -gi, which reads none
    bool mirrored = false;  // reflected on its way from the eye
    // The interiors it is in, the last entered first; only kept in a scene with media or fog (interiors_).
    const InteriorLink* interiors = nullptr;
    // The objects it sees: a ray from the eye all but no_image ones until it is reflected, then all but
    // no_reflection ones; a gathered ray all but no_radiosity ones.
    Sight sight() const { return bounce > 0 ? Sight::Gathered : mirrored ? Sight::Reflected : Sight::Image; }
  };

  struct Local {
    Color diffuse{0}, specular{0};
  };

  struct ShadowRay {
    Ray<T> ray;            // aimed at the light from its offset origin (spawnRayTo)
    Interval<T> segment;
    Vec3<T> l;             // the unit vector from the point itself to the light, which shading uses
    float nl;              // n·l
    bool occluded = false;  // the answer, once asked
  };

  // Rays traced together (traceBatch): the eye rays of tile(), or the gather rays of one hit. Each level of
  // gathering has its own, kept from call to call so that the gather loop allocates nothing.
  struct Batch {
    std::vector<Ray<T>> rays;
    std::vector<Path> paths;
    std::vector<Color> colors;
    std::vector<T> distances;  // to each ray's hit, +∞ on a miss
    std::vector<std::optional<ShadowRay>> shadows;  // a packet's shadow rays, ray by ray and light by light
  };

  Traced trace(const Ray<T>& ray, RayRecord::Kind kind, const Path& path, RayRecord* record);
  // colors[i] = trace(rays[i], kind, paths[i]).color for i < count, with closest hits and shadow rays asked
  // for a packet at a time.
  void traceBatch(Batch& batch, int count, RayRecord::Kind kind);
  // trace() once the closest hit is known; `shadows`, if given, are the hit's shadow rays (one per light, as
  // shadowRay() makes them) with their answers, found beforehand for a whole packet.
  Traced follow(const Ray<T>& ray, const std::optional<Hit<T>>& hit, RayRecord::Kind kind, const Path& path,
                RayRecord* record, const std::optional<ShadowRay>* shadows);
  // The colour a hit sends back along the ray: the local light (ambient or gathered, plus direct) and the
  // secondary rays, weighted (§c.5).
  Color shade(const Ray<T>& ray, const Hit<T>& hit, const Path& path, RayRecord* record,
              const std::optional<ShadowRay>* shadows);
  // The share of a light's colour that reaches the end of a shadow ray through transparent surfaces, and the
  // media inside them.
  Color transmittance(const Ray<T>& ray, Interval<T> segment);
  // The share of a light with media_attenuation (Light::mediaAttenuation) left by the scene's fogs and media
  // over `distance` from `point` toward it along the unit `l`.
  Color attenuation(const Vec3<T>& point, const Vec3<T>& l, T distance) const;
  // What reaches a point of a scattering medium from each light (MediaLights), shadowed as a surface would be.
  struct MediaLighting;
  // `c` seen through the scene's fogs (fogs_) along the ray up to t (infinite for a ray that leaves the scene).
  Color fogged(Color c, const Ray<T>& ray, T t) const;
  // The background `sky` seen along a ray that hits nothing through the scene's media (sceneMedia_).
  Color missInMedia(const Color& sky, const Ray<T>& ray, RayRecord::Kind kind, const Path& path);
  // follow() for a hit in a scene with media.
  Traced followInMedia(const Ray<T>& ray, const Hit<T>& hit, RayRecord::Kind kind, const Path& path,
                       RayRecord* record, const std::optional<ShadowRay>* shadows);
  // What names an object's interior: its medium or its CSG's interior (both shared by a CSG's parts), else the
  // object itself.
  static uintptr_t interiorKey(const Object<T>& object);
  // Whether every interior of the list is hollow.
  static bool hollow(const InteriorLink* interiors);
  // `color` from a hit at t seen through the media of the interiors the ray is in, from its origin.
  Color throughMedia(const InteriorLink* interiors, const Color& color, const Ray<T>& ray, T t);
  // The interiors around an eye ray's origin (eyeInteriors_, kept while the origin stays), inside the scene's media.
  const InteriorLink* eyeInteriors(const Vec3<T>& origin);
  // The ray refracted across the surface `hit` is on, which it enters or leaves.
  Traced across(const Ray<T>& ray, const Hit<T>& hit, const Path& child, RayRecord* record);
  // The weights of the local light and the two secondary rays at a hit; `refracted` receives the transmitted
  // direction when there is one (total internal reflection moves the transmitted share to reflection).
  Weights split(const Ray<T>& ray, const Hit<T>& hit, const Material& m, const Vec3<T>& n, RayRecord* record,
                std::optional<Vec3<T>>& refracted) const;
  // The term the course calls ambient: the material's constant, or with -gi the indirect light gathered over
  // the hemisphere of n (docs/gi.md).
  Color ambient(const Hit<T>& hit, const Material& m, const Vec3<T>& n, const Path& path);
  // The gathered light: cached() at the first bounce with --gi-cache, gather() otherwise.
  Color gathered(const Hit<T>& hit, const Vec3<T>& n, const Path& path);
  // The ambient term of POV-Ray's radiosity: the material's own (its emission) and the gathered light it
  // diffuses (render/radiosity.hpp, docs/gi.md).
  Color radiosity(const Hit<T>& hit, const Material& m, const Vec3<T>& n, const Path& path);
  // The first bounce's gathered light with --gi-cache: the cache's, or gathered (and recorded, if records are
  // being made) where no record covers the point.
  Color cached(const Hit<T>& hit, const Vec3<T>& n, const Path& path);
  // The mean radiance of options.gi.samplesAt(bounce) stratified cosine-weighted rays from the hit (§c.14);
  // black at the last bounce.
  Color gather(const Hit<T>& hit, const Vec3<T>& n, const Path& path);
  // The sum of what `count` stratified rays bring back, their random numbers keyed 0 … count − 1 under the
  // path's key; batches_[1 + path.bounce] keeps the rays, their colours and distances until the next call.
  Color gatherSet(const Hit<T>& hit, const Vec3<T>& n, const Path& path, int count);
  // Diffuse and specular light from every light the point sees (§c.1, §c.7), before weighting. `side` is the
  // surface's normal on the viewer's side, `n` the shading normal (side, or bent by a texture's normal), `v`
  // the unit vector to the viewer. With `areaAsPoint` an area light lights as a point light at its centre.
  Local direct(const Hit<T>& hit, const Material& m, const Vec3<T>& side, const Vec3<T>& n, const Vec3<T>& v,
               RayRecord* record, const std::optional<ShadowRay>* shadows, bool areaAsPoint);
  // direct()'s loop over the lights; `kPlain` compiles out what only area and parallel lights, a bent normal
  // and crand need, so that a scene without them pays nothing for them.
  template <bool kPlain>
  Local lightLoop(const Hit<T>& hit, const Material& m, const Vec3<T>& side, const Vec3<T>& n, const Vec3<T>& v,
                  RayRecord* record, const std::optional<ShadowRay>* shadows, bool areaAsPoint);
  // The reflected and refracted light, weighted and tinted (§c.3, §c.4, §c.6), traced refraction first as the
  // course prints them (§a.3).
  Color secondary(const Ray<T>& ray, const Hit<T>& hit, const Material& m, const Vec3<T>& n, const Weights& w,
                  const std::optional<Vec3<T>>& refracted, const Path& path, RayRecord* record);
  // The shadow ray toward `light`, or false when the light cannot light the point from the viewer's side `n`:
  // a light behind the surface as the viewer sees it, or on the point itself.
  // It is written into `out` in place: it is made for every hit and light, and a returned copy would stall
  // (docs/performance-notes.md, "Shadow rays built in place").
  bool shadowRay(const Hit<T>& hit, const Vec3<T>& n, const Light<T>& light, ShadowRay& out) const;
  // The shadow ray toward a light the packets leave out (Light::sampled) as shadowRay() makes it, with the light
  // that reaches the point multiplied into `lightColor`: an area light's share of its grid (AreaLight::share),
  // a parallel light's along its direction; with `areaAsPoint`, an area light's centre alone. False when the
  // light cannot light the point.
  bool sampledLight(const Hit<T>& hit, const Vec3<T>& n, const Light<T>& light, size_t index, ShadowRay& out,
                    Color& lightColor, bool areaAsPoint);
  // POV-Ray's area_illumination (manual, "Area Lights"): the diffuse and specular light of an area light as
  // the mean of its grid's points, each a point light from its own direction (jittered as sampledLight's),
  // added into `diffuse` and `specular`; `lightColor` already holds the grid's shadow share.
  void illuminate(const Hit<T>& hit, const Vec3<T>& n, const Vec3<T>& v, const Material& m, const Light<T>& light,
                  size_t index, const Color& lightColor, Color& diffuse, Color& specular) const;
  // The specular highlight's factor for light from unit direction l: the BRDF's lobe (§c.2).
  float specularFactor(const Vec3<T>& n, const Vec3<T>& v, const Vec3<T>& l, const Material& m) const;
  // Whether a secondary ray of accumulated weight `weight` at `depth` is worth tracing and its eye ray's tree
  // has room for it (docs/reference/stability.md F12); a ray it says yes to is counted against that room.
  bool matters(float weight, int depth);

  const Scene<T>& scene_;
  RenderOptions options_;
  Dialect dialect_;
  Color background_;  // what a ray that leaves the scene sees where no sky is
  int maxDepth_;      // the deepest secondary ray traced: the command line's, the scene's or its dialect's
  std::vector<float> bound_;  // bound_[r]: the brightest colour a ray with r levels of recursion left can return
  float cutoff_;
  int treeRays_;      // the most rays an eye ray's tree may have: a full tree of depth min(maxDepth, kFullTreeDepth)
  int raysLeft_ = 0;  // the secondary rays the current eye ray's tree may still have
  uint64_t sampleRaysLeft_ = 0;  // the rays the current eye sample may still cost, gathered trees included
  std::vector<const Object<T>*> lastOccluder_;  // per light: what occluded its latest shadow ray (Scene::occluded)
  const SkySphere* sky_;                        // the scene's, or none
  bool fogs_;                                   // whether the scene has any fog
  bool interiors_ = false;  // whether some object has a medium or the scene a fog: rays keep Path::interiors
  std::vector<InteriorLink> eyeInteriors_;      // eyeInteriors(): around eyeOrigin_, the innermost last
  // The scene's (atmospheric) media as the outermost interior every eye ray starts in; none without any.
  std::vector<InteriorLink> sceneMedia_;
  std::optional<Vec3<T>> eyeOrigin_;
  bool sampledLights_ = false;   // some light is an area or parallel light, or dimmed by media (Light::sampled)
  bool filteredShadows_ = false;  // shadow rays pass transparent surfaces (POV-Ray, and some surface lets light through)
  std::vector<Batch> batches_;                 // [0] tile()'s eye rays, [1 + b] the gather rays at bounce b
  std::vector<size_t> blanks_;                 // tile()'s eye rays at the projection's blank points
  RayCounts counts_;
  std::vector<GatherSummary>* gathers_ = nullptr;  // pixel()'s per-bounce summary while it is asked for
  const IrradianceCache<T>* cache_ = nullptr;
  std::vector<IrradianceRecord<T>>* made_ = nullptr;
  std::vector<Vec3<T>> directions_;  // a record's gather directions
  std::vector<Color> areaGrid_;      // an area light's grid, sampled (sampledLight)
  std::vector<char> areaKnown_;
};

}  // namespace rt
