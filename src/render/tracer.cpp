#include "raytrace/render/tracer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include <glm/gtc/constants.hpp>

#include "raytrace/render/sampler.hpp"

namespace rt {

namespace {

// The normal on the side the ray arrives from: the shading normal.
template <class T> Vec3<T> viewerSide(const Hit<T>& hit, const Ray<T>& ray) {
  return glm::dot(ray.dir, hit.normal) <= T(0) ? hit.normal : -hit.normal;
}

// The random-number keys of a hit's reflected and refracted rays, apart from those of its gather samples
// (0, 1, … below any sample count).
constexpr uint64_t kReflectionBranch = uint64_t(1) << 40;
constexpr uint64_t kRefractionBranch = kReflectionBranch + 1;

float brightest(const Color& c) { return std::max(c.r, std::max(c.g, c.b)); }

// The random-number key of what a point does with light `index` (an area light's jitter, crand): keyed by the
// point itself, so a picture is the same for any threads and tiles.
template <class T> uint64_t pointKey(const Vec3<T>& point, size_t index) {
  const auto bits = [](T x) {
    uint64_t b = 0;
    std::memcpy(&b, &x, sizeof x);
    return b;
  };
  return childKey(childKey(childKey(mix64(bits(point.x)), bits(point.y)), bits(point.z)), uint64_t(index));
}

// An area light's grid as the point shaded sees it: its axes turned toward the point (`orient`), each grid point
// jittered by the point's own key, so that its shadow rays and `area_illumination` use the same points.
class GridSeenFrom {
 public:
  template <class T>
  GridSeenFrom(const AreaLight& area, const glm::dvec3& center, const Vec3<T>& point, size_t index)
      : area_(area), center_(center), key_(pointKey(point, index)) {
    area.axesToward(center, glm::dvec3(point), a1_, a2_);
  }
  glm::dvec3 operator()(int i, int j) const {
    const glm::vec2 jitter =
        area_.jitter ? uniformPair(childKey(key_, uint64_t(j) * uint64_t(area_.size1) + uint64_t(i))) : glm::vec2(0);
    return area_.point(i, j, center_, a1_, a2_, jitter);
  }

 private:
  const AreaLight& area_;
  glm::dvec3 center_, a1_, a2_;
  uint64_t key_;
};

// crand's darkening of light `index` at `point`: crand·u·C·light (SurfaceExtras::crand). Kept out of line: the
// light loop of every other surface then pays only the test.
template <class T>
[[gnu::noinline]] Color grain(const Color& light, const Material& m, const Vec3<T>& point, size_t index) {
  return light * m.pigment * (m.extras->crand * uniformPair(pointKey(point, index)).x);
}

// The largest factor a specular term can put on Lc·ks·C: 1 for Blinn-Phong (a clamped cosine to a power
// ≥ 0); for Cook-Torrance D ≤ max(1/(πα²), α²/π), G ≤ 1, F ≤ 1 and the denominator is at least 4/16.
float specularBound(const Material& m, Brdf brdf) {
  if (brdf == Brdf::BlinnPhong) return 1.0f;
  const float alpha = ggxAlpha(m.roughness);
  return 4.0f * std::max(1.0f / (glm::pi<float>() * alpha * alpha), alpha * alpha / glm::pi<float>());
}

}  // namespace

// Recursion cutoff (docs/reference/stability.md F12). A secondary ray is skipped when its accumulated weight w (the product
// of the weights and tints from the eye down to it) times the brightest colour its subtree could return,
// bound_[levels left], is below cutoff_ = (½/255) / 2^(D+1), D = min(maxDepth, kFullTreeDepth), or when its
// eye ray's tree already has 2^(D+1) − 1 rays. A tree of depth D has no more, and fewer than 2^(D+1) rays are
// skipped beside its traced ones, so all the skipped subtrees of one eye ray together move its colour by less
// than half an 8-bit step: the byte changes only if the exact value lay within that distance of a rounding
// boundary. Only deeper trees can reach the ray budget (scenes/depth_bomb.pov would take ~10^11 rays at
// --depth=64): it bounds an eye ray's work whatever the depth, at the price of that guarantee. bound_ is built
// bottom-up: a ray returns the background or wl·local + Σ weight·tint·(child colour) with |wl·local| ≤
// Lmax and Σ weight·tint ≤ G, the largest ((1−f)k + f)·max(1, C) of the scene's materials.
template <class T>
Tracer<T>::Tracer(const Scene<T>& scene, const RenderOptions& options)
    : scene_(scene),
      options_(options),
      dialect_(scene.desc().dialect),
      background_(scene.desc().background),
      maxDepth_(options.depth.value_or(scene.desc().maxDepth())),
      lastOccluder_(scene.lights().size(), nullptr),
      sky_(scene.desc().sky.get()),
      fogs_(!scene.desc().fogs.empty()),
      batches_(size_t(1 + (options.gi.enabled ? options.gi.bounceCount() : 0))) {
  for (const Light<T>& light : scene.lights()) sampledLights_ = sampledLights_ || light.sampled;
  float localMax = 0, gain = 0;
  // Every material a hit can report: a CSG group's parts' too.
  for (const auto& object : scene.objects()) {
    object->forEachMaterial([&](const Material& m) {
      float local = brightest(m.ambient);
      for (const Light<T>& light : scene.lights()) {
        local +=
            brightest(light.color) * (brightest(m.diffuse) + brightest(m.specular) * specularBound(m, options.brdf));
      }
      // A filter or transmit outside [0, 1], which POV-Ray draws as written, makes a local weight 1 − f above 1
      // or below 0, and a transmitted one f below 0.
      localMax = std::max(localMax, options.normals ? 1.0f : local * std::max(1.0f, std::abs(1 - m.filter)));
      const float reflection = std::max(m.reflection, m.extras->reflectionMin);
      const float reflected = (dialect_.transparencyDimsReflection() ? 1 - m.filter : 1) * reflection;
      gain = std::max(gain, (reflected + std::abs(m.filter)) * std::max(1.0f, brightest(m.pigment)));
      filteredShadows_ = filteredShadows_ || (dialect_.filtersShadows() && m.filter != 0);
      interiors_ = interiors_ || fogs_ || !m.extras->media.empty();
    });
  }
  // What a ray that leaves the scene brings back; fogs add their colours (throughFogs).
  const SceneDesc& desc = scene.desc();
  // Scene-level media: one outermost hollow interior named by its address, which no object's key is.
  if (!desc.media.empty()) {
    sceneMedia_.push_back({reinterpret_cast<uintptr_t>(&desc.media), nullptr, &desc.media, true, false, nullptr});
  }
  interiors_ = interiors_ || !sceneMedia_.empty();
  float background = std::max(brightest(background_), desc.sky ? brightest(desc.sky->bound()) : 0.0f);
  float fogs = 0;
  for (const Fog& f : desc.fogs) fogs += brightest(f.colour.rgb);
  background = std::max(background, fogs);
  localMax = std::max(localMax, fogs);
  const auto level = [&](float children) {
    return std::max(background, dialect_.bounced(localMax + gain * children));
  };
  bound_.push_back(level(0));
  for (int r = 1; r <= maxDepth_; ++r) bound_.push_back(level(bound_.back()));
  const int fullDepth = std::min(maxDepth_, kFullTreeDepth);
  // Gathered light has no bound known beforehand: with -gi every secondary ray of any weight is traced, and
  // only the ray budget bounds a tree.
  cutoff_ = options.gi.enabled ? 0.0f : std::ldexp(0.5f / 255.0f, -(fullDepth + 1));
  if (desc.adcBailout && !options.gi.enabled) {
    // The scene's own rule: a ray's weight alone against adc_bailout, as POV-Ray decides which rays to trace.
    std::fill(bound_.begin(), bound_.end(), 1.0f);
    cutoff_ = *desc.adcBailout;
  }
  treeRays_ = (1 << (fullDepth + 1)) - 1;
}

template <class T> bool Tracer<T>::matters(float weight, int depth) {
  if (raysLeft_ == 0 || sampleRaysLeft_ == 0 || weight * bound_[size_t(maxDepth_ - depth)] < cutoff_) {
    return false;
  }
  --raysLeft_;
  --sampleRaysLeft_;
  return true;
}

template <class T>
Color Tracer<T>::pixel(const Camera<T>& camera, int x, int y, std::vector<RayRecord>* trees,
                       std::vector<GatherSummary>* gathers) {
  if (camera.blurred()) return blurredPixel(camera, x, y);
  if (camera.raysPerPixel() > 1) return meshPixel(camera, x, y);
  const int n = options_.samples;
  if (gathers) gathers->assign(size_t(options_.gi.enabled ? options_.gi.bounceCount() : 0), GatherSummary{});
  gathers_ = gathers;
  Color sum(0);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      RayRecord* record = trees ? &trees->emplace_back() : nullptr;
      Path path;
      path.key = pixelKey(options_.gi.seed, x, y, i * n + j);
      ++counts_.eye;
      raysLeft_ = treeRays_ - 1;
      sampleRaysLeft_ = kSampleRays - 1;
      const Ray<T> ray = camera.sampleRay(x, y, i, j, n);
      if (camera.hasBlanks() && camera.blank(ray)) continue;  // black, as POV-Ray leaves it
      sum += trace(ray, RayRecord::Kind::Primary, path, record).color;
    }
  }
  gathers_ = nullptr;
  return finished(sum / float(n * n));
}

// A mesh camera's pixel of several rays (manual, "Mesh projection"): the average of the rays its faces give,
// black when none does.
template <class T> Color Tracer<T>::meshPixel(const Camera<T>& camera, int x, int y) {
  Color sum(0);
  int rays = 0;
  for (int k = 0; k < camera.raysPerPixel(); ++k) {
    const Ray<T> ray = camera.meshRay(x, y, k);
    if (Camera<T>::blank(ray)) continue;
    Path path;
    path.key = pixelKey(options_.gi.seed, x, y, k);
    ++counts_.eye;
    raysLeft_ = treeRays_ - 1;
    sampleRaysLeft_ = kSampleRays - 1;
    sum += trace(ray, RayRecord::Kind::Primary, path, nullptr).color;
    ++rays;
  }
  return finished(rays > 0 ? sum / float(rays) : Color(0));
}

template <class T> Color Tracer<T>::raised(const Color& c) const {
  const float g = dialect_.gamma();
  return {std::pow(std::max(c.r, 0.0f), g), std::pow(std::max(c.g, 0.0f), g), std::pow(std::max(c.b, 0.0f), g)};
}

template <class T> const Color* Tracer<T>::tile(const Camera<T>& camera, int x0, int y0, int x1, int y1) {
  if (camera.blurred() || camera.raysPerPixel() > 1) {
    std::vector<Color>& colors = batches_[0].colors;
    colors.clear();
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) colors.push_back(camera.blurred() ? blurredPixel(camera, x, y) : meshPixel(camera, x, y));
    }
    return colors.data();
  }
  const int n = options_.samples;
  Batch& eye = batches_[0];  // in pixel() order: pixel by pixel, row by row, then sample by sample
  const size_t count = size_t(x1 - x0) * size_t(y1 - y0) * size_t(n * n);
  eye.rays.resize(count);
  eye.paths.resize(count);
  eye.colors.resize(count);
  eye.distances.resize(count);
  size_t k = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          // Stored member by member from registers: push_back would store the ray on the stack and copy it
          // from there at once, a store-forwarding stall per sample.
          const Ray<T> ray = camera.sampleRay(x, y, i, j, n);
          eye.rays[k].origin = ray.origin;
          eye.rays[k].dir = ray.dir;
          // Only gathering reads the keys: without -gi their four hashes per sample are left out.
          const uint64_t key = options_.gi.enabled ? pixelKey(options_.gi.seed, x, y, i * n + j) : 0;
          eye.paths[k++] = Path{0, 0, 1.0f, key};
        }
      }
    }
  }
  counts_.eye += count;
  // A projection's blank points are traced along the view and then made black, as POV-Ray leaves them.
  blanks_.clear();
  if (camera.hasBlanks()) {
    for (size_t s = 0; s < count; ++s) {
      if (!Camera<T>::blank(eye.rays[s])) continue;
      blanks_.push_back(s);
      eye.rays[s].dir = Vec3<T>(0, 0, 1);  // any direction: its colour is replaced
    }
  }
  traceBatch(eye, int(count), RayRecord::Kind::Primary);
  for (size_t s : blanks_) eye.colors[s] = Color(0);
  // Each pixel's average in place: pixel p's samples start at p·n² ≥ p.
  std::vector<Color>& colors = eye.colors;
  const size_t pixels = count / size_t(n * n);
  for (size_t p = 0, next = 0; p < pixels; ++p) {
    Color sum(0);
    for (int s = 0; s < n * n; ++s) sum += colors[next++];
    colors[p] = finished(sum / float(n * n));
  }
  return colors.data();
}

template <class T> const Color* Tracer<T>::eyeRays(const Ray<T>* rays, const uint64_t* keys, size_t count) {
  Batch& eye = batches_[0];
  eye.rays.resize(count);
  eye.paths.resize(count);
  eye.colors.resize(count);
  eye.distances.resize(count);
  for (size_t k = 0; k < count; ++k) {
    eye.rays[k].origin = rays[k].origin;
    eye.rays[k].dir = rays[k].dir;
    eye.paths[k] = Path{0, 0, 1.0f, options_.gi.enabled ? keys[k] : 0};
  }
  counts_.eye += count;
  traceBatch(eye, int(count), RayRecord::Kind::Primary);
  return eye.colors.data();
}

// Each ray of a batch (an eye ray or a gathered one) gets a tree budget of its own; a batch gathered inside a
// tree leaves that tree's budget as it found it.
template <class T> void Tracer<T>::traceBatch(Batch& batch, int count, RayRecord::Kind kind) {
  const int outerRaysLeft = raysLeft_;
  const size_t lights = scene_.lights().size();
  constexpr int kPacket = Bvh<T>::kPacket;
  std::vector<std::optional<ShadowRay>>& shadows = batch.shadows;
  shadows.resize(kPacket * lights);
  for (int first = 0; first < count; first += kPacket) {
    const int size = std::min(kPacket, count - first);
    const Ray<T>* packet = &batch.rays[size_t(first)];
    std::optional<Hit<T>> hits[kPacket];
    scene_.closestHits(packet, size, {}, hits, batch.paths[size_t(first)].sight());  // one sight a batch
    // The shadow rays of the packet's hits toward each light, asked together: shadows[i · lights + l]. Shadows
    // through transparent surfaces are followed one ray at a time instead (direct()).
    for (size_t l = 0; l < lights && !filteredShadows_; ++l) {
      if (scene_.lights()[l].sampled) continue;  // direct() samples it for each hit
      Ray<T> query[kPacket];
      Interval<T> segments[kPacket];
      int index[kPacket], m = 0;
      for (int i = 0; i < size; ++i) {
        auto& s = shadows[size_t(i) * lights + l];
        s.emplace();
        if (!hits[i] || !shadowRay(*hits[i], viewerSide(*hits[i], packet[i]), scene_.lights()[l], *s)) s.reset();
      }
      if (scene_.lights()[l].shadowless) continue;  // each answer stays "not occluded"
      // Gathered in a second pass: copied right after it is written, a ray is read back before its stores
      // have left the store buffer, and each such read stalls.
      for (int i = 0; i < size; ++i) {
        if (const auto& s = shadows[size_t(i) * lights + l]) query[m] = s->ray, segments[m] = s->segment, index[m++] = i;
      }
      bool answers[kPacket];
      scene_.occluded(query, segments, m, answers, &lastOccluder_[l]);
      counts_.shadow += uint64_t(m);
      for (int k = 0; k < m; ++k) shadows[size_t(index[k]) * lights + l]->occluded = answers[k];
    }
    for (int i = 0; i < size; ++i) {
      const size_t r = size_t(first + i);
      raysLeft_ = treeRays_ - 1;
      if (batch.paths[r].bounce == 0) sampleRaysLeft_ = kSampleRays - 1;  // an eye ray, not a gathered one
      const std::optional<ShadowRay>* known = filteredShadows_ ? nullptr : shadows.data() + size_t(i) * lights;
      const Traced t = follow(packet[i], hits[i], kind, batch.paths[r], nullptr, known);
      batch.colors[r] = t.color;
      batch.distances[r] = t.distance;
    }
  }
  raysLeft_ = outerRaysLeft;
}

template <class T>
typename Tracer<T>::Traced Tracer<T>::trace(const Ray<T>& ray, RayRecord::Kind kind, const Path& path,
                                            RayRecord* record) {
  return follow(ray, scene_.closestHit(ray, {}, path.sight()), kind, path, record, nullptr);
}

template <class T>
typename Tracer<T>::Traced Tracer<T>::follow(const Ray<T>& ray, const std::optional<Hit<T>>& hit,
                                             RayRecord::Kind kind, const Path& path, RayRecord* record,
                                             const std::optional<ShadowRay>* shadows) {
  if (record) {
    record->kind = kind;
    record->origin = glm::dvec3(ray.origin);
    record->dir = glm::dvec3(ray.dir);
  }
  if (!hit) {
    Color sky = sky_ ? sky_->at(glm::dvec3(ray.dir), background_) : background_;
    if (fogs_) sky = fogged(sky, ray, std::numeric_limits<T>::infinity());
    if (!sceneMedia_.empty()) sky = missInMedia(sky, ray, kind, path);
    if (record) record->color = sky;
    return {sky, std::numeric_limits<T>::infinity()};
  }
  if (interiors_) return followInMedia(ray, *hit, kind, path, record, shadows);
  Color color = shade(ray, *hit, path, record, shadows);
  if (fogs_) color = fogged(color, ray, hit->t);
  color = dialect_.bounced(color);
  if (record) record->color = color;
  return {color, hit->t};
}

// follow() in a scene with media or fog: an eye ray starts in the interiors around its origin, and the colour
// from the hit is seen through the media of those the ray is in. Fog, as media, fills hollow objects alone (the
// manual, "Empty and Solid Objects"): a ray in a solid one is not fogged.
template <class T>
[[gnu::noinline]] typename Tracer<T>::Traced Tracer<T>::followInMedia(const Ray<T>& ray, const Hit<T>& hit,
                                                                    RayRecord::Kind kind, const Path& path,
                                                                    RayRecord* record,
                                                                    const std::optional<ShadowRay>* shadows) {
  Path within = path;
  if (kind == RayRecord::Kind::Primary && path.depth == 0 && path.bounce == 0) within.interiors = eyeInteriors(ray.origin);
  Color color = shade(ray, hit, within, record, shadows);
  if (fogs_ && hollow(within.interiors)) color = fogged(color, ray, hit.t);
  color = dialect_.bounced(color);
  // Gathered rays see no media (POV-Ray's radiosity `media` is off by default: the manual, "Radiosity").
  if (within.interiors && path.bounce == 0) color = throughMedia(within.interiors, color, ray, hit.t);
  if (record) record->color = color;
  return {color, hit.t};
}

// Measured with POV-Ray 3.7 (a scene of emission media alone): a ray that hits nothing crosses the scene's
// media over 2·10¹⁰ units, whatever its direction, then sees the background.
template <class T>
[[gnu::noinline]] Color Tracer<T>::missInMedia(const Color& sky, const Ray<T>& ray, RayRecord::Kind kind,
                                               const Path& path) {
  if (path.bounce > 0) return sky;
  const bool eye = kind == RayRecord::Kind::Primary && path.depth == 0;
  const T length = glm::length(ray.dir);
  return throughMedia(eye ? eyeInteriors(ray.origin) : path.interiors, sky, ray, T(2e10) / length);
}

template <class T> Color Tracer<T>::fogged(Color c, const Ray<T>& ray, T t) const {
  const glm::dvec3 dir(ray.dir);
  const double length = glm::length(dir);
  return throughFogs(scene_.desc().fogs, c, glm::dvec3(ray.origin), dir / length, double(t) * length);
}

template <class T>
Color Tracer<T>::shade(const Ray<T>& ray, const Hit<T>& hit, const Path& path, RayRecord* record,
                       const std::optional<ShadowRay>* shadows) {
  if (record) {
    record->hit = true;
    record->objectId = hit.object->id();
    record->objectType = hit.object->name();
    record->point = glm::dvec3(hit.point);
    record->normal = glm::dvec3(hit.normal);
    record->t = double(hit.t);
  }
  if (path.depth == maxDepth_ && !dialect_.shadesAtDepthLimit()) return Color(0);
  if (options_.normals) return Color(hit.normal) * 0.5f + 0.5f;

  const Vec3<T> v = -ray.dir;
  const Vec3<T> side = viewerSide(hit, ray);
  Vec3<T> n = side;  // the shading normal: the surface's, or bent by the texture's normal
  std::optional<Vec3<T>> refracted;
  Material textured;
  const Material& m = hit.object->materialAt(hit, textured, n);
  const Weights w = split(ray, hit, m, n, record, refracted);
  Color ambientLight(0);
  Local local;
  // The cache's prepass keeps only the records its rays make, not its pixels: the direct light of a hit not
  // gathered (bounce 0) would go into the pixel alone, so it is left out there.
  if (w.local != 0 && !(made_ && path.bounce == 0)) {
    // Measured with POV-Ray 3.7 (docs/gi.md, "POV-Ray's radiosity"): where a radiosity ray lands, an area
    // light lights as a point light at its centre, shadows and all.
    const bool areaAsPoint = path.bounce > 0 && options_.gi.radiosity;
    local = direct(hit, m, side, n, v, record, shadows, areaAsPoint);
    if (m.extras->doubleIlluminate) {
      // The lights behind the surface, as if seen from that side: the normal and the side to leave by turned.
      const Local behind = direct(hit, m, -side, -n, v, record, nullptr, areaAsPoint);
      local.diffuse += behind.diffuse;
      local.specular += behind.specular;
    }
  }
  if (w.local != 0) ambientLight = w.local * ambient(hit, m, side, path);
  local.diffuse *= w.local;
  local.specular *= w.local;
  const Color secondaryLight = secondary(ray, hit, m, n, w, refracted, path, record);
  if (record) {
    record->ambient = ambientLight;
    record->diffuse = local.diffuse;
    record->specular = local.specular;
    record->local = w.local;
    record->reflect = w.reflection;
    record->transmit = w.transmission;
  }
  return ambientLight + local.diffuse + local.specular + secondaryLight;
}

// Inlined into shade(), its only caller, as secondary() is (docs/performance-notes.md, "Whitted path").
template <class T>
[[gnu::always_inline]] inline
Weights Tracer<T>::split(const Ray<T>& ray, const Hit<T>& hit, const Material& m, const Vec3<T>& n,
                         RayRecord* record, std::optional<Vec3<T>>& refracted) const {
  const float fresnel = options_.fresnel ? schlick(float(glm::dot(n, -ray.dir)), m.ior) : 0.0f;
  Weights w = weights(m, fresnel, dialect_);
  if (m.extras->reflectionFalloff > 0) {
    Material varied = m;
    const Color reflection = variableReflection(m, float(glm::dot(n, -ray.dir)));
    varied.reflection = brightest(reflection);
    w = weights(varied, fresnel, dialect_);
    if (varied.reflection > 0) w.reflectionTint = reflection / varied.reflection;
  }
  if (w.transmission != 0) {
    // The outward normal as the shading normal bends it: hit.normal itself where nothing bends it.
    refracted = refractDirection(ray.dir, glm::dot(ray.dir, hit.normal) <= T(0) ? n : -n, m.ior);
    if (!refracted) {  // total internal reflection: the transmitted share is reflected (§c.4), or all (POV-Ray)
      if (dialect_.totalReflectionWhole()) {
        w.reflection = 1;
        w.reflectionTint = Color(1);
      } else {
        w.reflection += w.transmission;
      }
      w.transmission = 0;
      if (record) record->extraInfo.push_back("total-internal-reflection");
    }
  }
  return w;
}

template <class T>
Color Tracer<T>::ambient(const Hit<T>& hit, const Material& m, const Vec3<T>& n, const Path& path) {
  if (!options_.gi.enabled) return m.ambient;
  if (options_.gi.radiosity) return radiosity(hit, m, n, path);
  // The gathered light takes the place of ka·C (Ca in .cli) as it is: no ka, kd or pigment factor (§c.14; the
  // reference images show it, docs/gi.md).
  return gathered(hit, n, path);
}

template <class T>
Color Tracer<T>::gathered(const Hit<T>& hit, const Vec3<T>& n, const Path& path) {
  if (cache_ && path.bounce == 0 && options_.gi.bounceCount() > 0) return cached(hit, n, path);
  return gather(hit, n, path);
}

// POV-Ray's radiosity: the gathered light lights the surface as its diffuse term takes light (kd·C), times
// brightness; the material's ambient is its emission alone (POV-Ray 3.7 manual, "How Radiosity Works",
// "brightness"; measured, docs/gi.md). gray_threshold mixes in the light's gray (manual, "gray_threshold"),
// weighted as the manual's grayscale conversion (0.3, 0.59, 0.11; "HF_Gray_16").
template <class T>
Color Tracer<T>::radiosity(const Hit<T>& hit, const Material& m, const Vec3<T>& n, const Path& path) {
  if (m.diffuse == Color(0)) return m.ambient;  // nothing would take the light
  Color light = gathered(hit, n, path);
  const float t = options_.gi.grayThreshold;
  if (t > 0) light = light * (1 - t) + Color(0.3f * light.r + 0.59f * light.g + 0.11f * light.b) * t;
  return m.ambient + options_.gi.brightness * m.diffuse * light;
}

template <class T> Color Tracer<T>::cached(const Hit<T>& hit, const Vec3<T>& n, const Path& path) {
  ++counts_.cacheLookups;
  if (const std::optional<Color> c = cache_->lookup(hit.point, n)) return *c;
  if (!made_) {
    ++counts_.cacheMisses;
    return gather(hit, n, path);
  }
  // The same rays and sum as gather(), so a record's value is what the uniform estimator gives at its point.
  const int count = options_.gi.samplesAt(0);
  gatherSet(hit, n, path, count);
  const Batch& batch = batches_[1];
  directions_.resize(size_t(count));
  for (int i = 0; i < count; ++i) directions_[size_t(i)] = batch.rays[size_t(i)].dir;
  IrradianceRecord<T> record =
      makeRecord(hit.point, n, GatherSamples<T>{strataFor(count), directions_.data(), batch.colors.data(),
                                                batch.distances.data()},
                 cache_->clampRadius(hit.point, T(0)));  // the least radius there
  record.radius = cache_->clampRadius(hit.point, record.radius);
  made_->push_back(record);
  ++counts_.cacheRecords;
  return record.value;
}

template <class T> Color Tracer<T>::gather(const Hit<T>& hit, const Vec3<T>& n, const Path& path) {
  if (path.bounce >= options_.gi.bounceCount()) return Color(0);  // "use 0 for the last bounce" (§c.14)
  const int count = options_.gi.samplesAt(path.bounce);
  return gatherSet(hit, n, path, count) / float(count);
}

template <class T>
Color Tracer<T>::gatherSet(const Hit<T>& hit, const Vec3<T>& n, const Path& path, int count) {
  const Strata strata = strataFor(count);
  Batch& batch = batches_[size_t(1 + path.bounce)];
  batch.rays.resize(size_t(count));
  batch.paths.resize(size_t(count));
  batch.colors.resize(size_t(count));
  batch.distances.resize(size_t(count));
  const OffsetPolicy offset = *scene_.arithmetic().offset;
  for (int i = 0; i < count; ++i) {
    const uint64_t key = childKey(path.key, uint64_t(i));
    const Vec3<T> dir = aroundNormal(cosineHemisphere<T>(stratified(strata, i, uniformPair(key))), n);
    batch.rays[size_t(i)] = spawnRay(hit, dir, offset);
    batch.paths[size_t(i)] = Path{path.depth, path.bounce + 1, path.weight, key};
  }
  // Past the eye sample's room the set is not traced and brings back nothing, as a tree's rays past its room.
  if (sampleRaysLeft_ < uint64_t(count)) {
    sampleRaysLeft_ = 0;
    std::fill(batch.colors.begin(), batch.colors.end(), Color(0));
    std::fill(batch.distances.begin(), batch.distances.end(), std::numeric_limits<T>::infinity());
    return Color(0);
  }
  sampleRaysLeft_ -= uint64_t(count);
  counts_.gather += uint64_t(count);
  traceBatch(batch, count, RayRecord::Kind::Primary);
  Color sum(0);
  for (int i = 0; i < count; ++i) sum += batch.colors[size_t(i)];
  if (gathers_) {
    GatherSummary& g = (*gathers_)[size_t(path.bounce)];
    g.rays += uint64_t(count);
    g.radiance += sum;
  }
  return sum;
}

template <class T>
typename Tracer<T>::Local Tracer<T>::direct(const Hit<T>& hit, const Material& m, const Vec3<T>& side,
                                            const Vec3<T>& n, const Vec3<T>& v, RayRecord* record,
                                            const std::optional<ShadowRay>* shadows, bool areaAsPoint) {
  const bool plain = !sampledLights_ && n == side && !(m.extras->crand > 0) && !m.extras->irid;
  return plain ? lightLoop<true>(hit, m, side, n, v, record, shadows, areaAsPoint)
               : lightLoop<false>(hit, m, side, n, v, record, shadows, areaAsPoint);
}

template <class T>
template <bool kPlain>
typename Tracer<T>::Local Tracer<T>::lightLoop(const Hit<T>& hit, const Material& m, const Vec3<T>& side,
                                               const Vec3<T>& n, const Vec3<T>& v, RayRecord* record,
                                               const std::optional<ShadowRay>* shadows, bool areaAsPoint) {
  const bool bent = !kPlain && n != side;
  // Summed in locals, not in the returned struct: that one lives in the caller's memory, and each sum would
  // wait for the store before it.
  Color diffuse(0), specular(0);
  const float crand = kPlain ? 0.0f : m.extras->crand;
  for (size_t i = 0; i < scene_.lights().size(); ++i) {
    const Light<T>& light = scene_.lights()[i];
    Color lightColor = light.color;
    ShadowRay own;
    const ShadowRay* s = nullptr;
    if (!kPlain && light.sampled) {
      if (sampledLight(hit, n, light, i, own, lightColor, areaAsPoint)) s = &own;
    } else if (shadows) {
      if (shadows[i]) s = &*shadows[i];
    } else if (shadowRay(hit, side, light, own)) {
      if (filteredShadows_ && !light.shadowless) {
        lightColor = light.color * transmittance(own.ray, own.segment);
        own.occluded = lightColor == Color(0);
      } else if (!light.shadowless) {
        own.occluded = scene_.occluded(own.ray, own.segment, &lastOccluder_[i]);
        ++counts_.shadow;
      }
      s = &own;
    }
    if (!s) continue;
    if (record) record->shadows.push_back({glm::dvec3(s->ray.origin), glm::dvec3(s->ray.dir), s->occluded});
    if (s->occluded) continue;
    if (light.shape) {
      const glm::dvec3 toPoint = glm::dvec3(hit.point - light.position);
      const double distance = glm::length(toPoint);
      lightColor *= light.shape->at(toPoint / distance, distance);
    }
    if (!kPlain && light.area && light.area->illumination && !areaAsPoint) {
      illuminate(hit, n, v, m, light, i, lightColor, diffuse, specular);
      if (crand > 0) diffuse -= grain(lightColor, m, hit.point, i);
      continue;
    }
    // A bent normal turned away from the light takes none of it (the shadow ray leaves the true surface).
    const float nl = std::min(bent ? float(glm::dot(n, s->l)) : s->nl, 1.0f);
    if (bent && nl <= 0.0f) continue;
    if (!kPlain && m.extras->irid) {
      lightColor *= m.extras->irid->factor(glm::dvec3(hit.point), double(glm::dot(n, s->l)), double(glm::dot(n, v)));
    }
    diffuse += lightColor * m.diffuse * (m.brilliance == 1.0f ? nl : std::pow(nl, m.brilliance));
    if (!kPlain && crand > 0) diffuse -= grain(lightColor, m, hit.point, i);
    // A matte surface has no power to take; a shadowless light gives no highlight (the manual's "Shadowless
    // Lights", as POV-Ray's pictures show).
    if (m.specular == Color(0) || light.shadowless) continue;
    specular += lightColor * m.specular * specularFactor(n, v, s->l, m);
  }
  return {diffuse, specular};
}

template <class T>
float Tracer<T>::specularFactor(const Vec3<T>& n, const Vec3<T>& v, const Vec3<T>& l, const Material& m) const {
  return options_.brdf == Brdf::BlinnPhong ? m.lobe == Material::Lobe::Mirror ? phongSpecular(n, v, l, m.exponent)
                                                                              : blinnPhongSpecular(n, v, l, m.exponent)
                                           : cookTorranceSpecular(n, v, l, m.roughness, m.ior);
}

template <class T>
void Tracer<T>::illuminate(const Hit<T>& hit, const Vec3<T>& n, const Vec3<T>& v, const Material& m,
                           const Light<T>& light, size_t index, const Color& lightColor, Color& diffuse,
                           Color& specular) const {
  const AreaLight& area = *light.area;
  const GridSeenFrom grid(area, glm::dvec3(light.position), hit.point, index);
  // Each point is a light of 1 / (size1 · size2) of the colour, so that the grid gives the light's colour.
  const Color each = lightColor / float(area.size1 * area.size2);
  Color d(0), s(0);
  for (int j = 0; j < area.size2; ++j) {
    for (int i = 0; i < area.size1; ++i) {
      const Vec3<T> l = light.parallel ? *light.parallel : glm::normalize(Vec3<T>(grid(i, j)) - hit.point);
      // A point below the surface's horizon lights none of it.
      const float nl = std::min(float(glm::dot(n, l)), 1.0f);
      if (!(nl > 0.0f)) continue;
      const Color c = m.extras->irid ? each * m.extras->irid->factor(glm::dvec3(hit.point), double(glm::dot(n, l)),
                                                                     double(glm::dot(n, v)))
                                     : each;
      d += c * m.diffuse * (m.brilliance == 1.0f ? nl : std::pow(nl, m.brilliance));
      if (m.specular != Color(0) && !light.shadowless) s += c * m.specular * specularFactor(n, v, l, m);
    }
  }
  diffuse += d;
  specular += s;
}

// POV-Ray's shadows through transparent surfaces: each surface on the way lets through its filter·colour +
// transmit (Material: filter·pigment). At most kMaxShadowCrossings surfaces are followed; past them, none.
template <class T> Color Tracer<T>::transmittance(const Ray<T>& ray, Interval<T> segment) {
  constexpr int kMaxShadowCrossings = 64;
  Color through(1);
  for (int k = 0; k < kMaxShadowCrossings; ++k) {
    ++counts_.shadow;
    const std::optional<Hit<T>> hit = scene_.closestHit(ray, segment, Sight::Shadow);
    if (!hit) return through;
    Material textured;
    Vec3<T> n = hit->normal;
    const Material& m = hit->object->materialAt(*hit, textured, n);
    through *= m.filter * m.pigment;
    if (m.extras->caustics != 0) {
      through *= fakedCaustics(m.extras->caustics, float(glm::dot(n, ray.dir) / glm::length(ray.dir)));
    }
    // Leaving an object with an interior fade: the light faded over its way inside, from the surface before.
    if (m.extras->fadeDistance > 0 && glm::dot(ray.dir, hit->normal) > T(0)) {
      through *= interiorFade(m, float((hit->t - segment.min) * glm::length(ray.dir)));
    }
    // Leaving a medium: the light dimmed by its extinction on the way inside (the manual's note under "Media":
    // absorbing and scattering media cast shadows).
    if (!m.extras->media.empty() && glm::dot(ray.dir, hit->normal) > T(0)) {
      const double length = double(hit->t - segment.min) * double(glm::length(ray.dir));
      const glm::dvec3 dir = glm::normalize(glm::dvec3(ray.dir));
      through *= Media::kept(m.extras->media, glm::dvec3(ray.at(segment.min)), dir, length);
    }
    if (through == Color(0)) return through;
    segment.min = hit->t;
  }
  return Color(0);
}

// The manual's "Atmospheric Attenuation": the light is dimmed by the fogs and the scene's media it crosses, as
// a ray is (objects' media dim every light: transmittance()). Measured with POV-Ray 3.7: e^(−d/D) of a fog
// and e^(−absorption·d) of a medium over the d from the point to the light.
template <class T> Color Tracer<T>::attenuation(const Vec3<T>& point, const Vec3<T>& l, T distance) const {
  const SceneDesc& desc = scene_.desc();
  const glm::dvec3 from(point), dir(l);
  Color kept = desc.media.empty() ? Color(1) : Media::kept(desc.media, from, dir, double(distance));
  for (const Fog& fog : desc.fogs) kept *= fog.effect(from, dir, double(distance)).through;
  return kept;
}

template <class T> struct Tracer<T>::MediaLighting final : MediaLights {
  explicit MediaLighting(Tracer& tracer) : tracer(tracer) {}
  void at(const glm::dvec3& point, std::vector<Arrival>& out) override {
    const Vec3<T> p(point);
    for (size_t i = 0; i < tracer.scene_.lights().size(); ++i) {
      const Light<T>& light = tracer.scene_.lights()[i];
      if (!light.mediaInteraction) continue;
      Color color = light.color;
      if (light.shape) {
        const glm::dvec3 fromLight = glm::dvec3(p - light.position);
        const double length = glm::length(fromLight);
        color *= light.shape->at(fromLight / length, length);
      }
      // Measured with POV-Ray 3.7 (docs/povray-language.md, "Media"): a medium sees every point of an area
      // light's grid as a light of its own, whatever `adaptive` says, so its shadow shafts are soft.
      if (light.area && !light.parallel) {
        const AreaLight& area = *light.area;
        const GridSeenFrom grid(area, glm::dvec3(light.position), p, i);
        const Color each = color / float(area.size1 * area.size2);
        for (int v = 0; v < area.size2; ++v) {
          for (int u = 0; u < area.size1; ++u) arrive(p, light, i, Vec3<T>(grid(u, v)), each, out);
        }
      } else {
        arrive(p, light, i, light.position, color, out);
      }
    }
  }
  // The light `color` from `from` that reaches `p`, past the shadows on its way.
  void arrive(const Vec3<T>& p, const Light<T>& light, size_t i, const Vec3<T>& from, Color color,
              std::vector<Arrival>& out) {
    // A parallel light shines along its direction from the plane through its position (sampledLight).
    const Vec3<T> toLight = light.parallel ? *light.parallel : from - p;
    const T distance = light.parallel ? glm::dot(from - p, *light.parallel) : glm::length(toLight);
    const Vec3<T> l = light.parallel ? toLight : toLight / distance;
    if ((!light.shadowless || tracer.scene_.projected(i)) && distance > T(0)) {
      const Ray<T> ray{p, l};
      const std::optional<Interval<T>> segment = tracer.scene_.reaching(i, ray, Interval<T>{T(0), distance});
      if (!segment) return;
      if (!light.shadowless && tracer.filteredShadows_) {
        color *= tracer.transmittance(ray, *segment);
      } else if (!light.shadowless) {
        ++tracer.counts_.shadow;
        if (tracer.scene_.occluded(ray, *segment, &tracer.lastOccluder_[i])) color = Color(0);
      }
    }
    if (light.mediaAttenuation && color != Color(0)) color *= tracer.attenuation(p, l, std::max(distance, T(0)));
    if (color != Color(0)) out.push_back({glm::dvec3(l), color});
  }
  Tracer& tracer;
};

// The manual's "Empty and Solid Objects": media are only inside hollow objects. Measured with POV-Ray 3.7: a
// ray's media (those of all the interiors it is in, adding up) count only while every interior it is in is
// hollow; a solid object inside a medium, or around it, takes its place.
// The numbers of CSG interiors (1, 2, …) are no object's or medium's address.
template <class T> uintptr_t Tracer<T>::interiorKey(const Object<T>& object) {
  const SurfaceExtras& extras = *object.material().extras;
  if (!extras.media.empty()) return reinterpret_cast<uintptr_t>(extras.media.data());
  return extras.interior != 0 ? extras.interior : reinterpret_cast<uintptr_t>(&object);
}

template <class T> bool Tracer<T>::hollow(const InteriorLink* interiors) {
  for (const InteriorLink* link = interiors; link; link = link->outer) {
    if (!link->hollow) return false;
  }
  return true;
}

template <class T>
[[gnu::noinline]] Color Tracer<T>::throughMedia(const InteriorLink* interiors, const Color& color, const Ray<T>& ray,
                                                T t) {
  std::vector<const Media*> media;
  for (const InteriorLink* link = interiors; link; link = link->outer) {
    if (!link->hollow) return color;
    if (link->media) {
      for (const Media& m : *link->media) media.push_back(&m);
    }
  }
  if (media.empty()) return color;
  const glm::dvec3 dir(ray.dir);
  const double length = glm::length(dir);
  MediaLighting lights(*this);
  return Media::through(media.data(), media.size(), color, glm::dvec3(ray.origin), dir / length, double(t) * length,
                        &lights);
}

// As POV-Ray's pictures show, an eye ray starting inside objects is in their interiors (a medium around the
// camera is seen from it; a solid object around it hides the media until the ray leaves it).
template <class T> const typename Tracer<T>::InteriorLink* Tracer<T>::eyeInteriors(const Vec3<T>& origin) {
  if (eyeOrigin_ != origin) {
    eyeOrigin_ = origin;
    eyeInteriors_.clear();
    for (const auto& object : scene_.objects()) {
      const std::optional<Aabb<T>> bounds = object->bounds();
      if (bounds && (glm::any(glm::lessThan(origin, bounds->min)) || glm::any(glm::greaterThan(origin, bounds->max)))) continue;
      if (!object->inside(origin)) continue;
      const SurfaceExtras& extras = *object->material().extras;
      eyeInteriors_.push_back({interiorKey(*object), object.get(), extras.media.empty() ? nullptr : &extras.media,
                               extras.hollow, true, nullptr});
    }
    for (size_t i = 1; i < eyeInteriors_.size(); ++i) eyeInteriors_[i].outer = &eyeInteriors_[i - 1];
  }
  const InteriorLink* scene = sceneMedia_.empty() ? nullptr : &sceneMedia_.back();
  if (!eyeInteriors_.empty()) eyeInteriors_.front().outer = scene;
  return eyeInteriors_.empty() ? scene : &eyeInteriors_.back();
}

// As POV-Ray's pictures show, a ray crossing a surface leaves the interior if it is in it (through any of the
// parts of a CSG that share it: in a union's overlap a ray is out of it), else enters it. Leaving, the interiors
// entered since are linked anew in this frame. An interior found around the eye is left where the ray is no
// longer inside its object.
template <class T>
[[gnu::noinline]] typename Tracer<T>::Traced Tracer<T>::across(const Ray<T>& ray, const Hit<T>& hit,
                                                             const Path& child, RayRecord* record) {
  const SurfaceExtras& extras = *hit.object->material().extras;
  const std::vector<Media>* media = extras.media.empty() ? nullptr : &extras.media;
  const uintptr_t key = interiorKey(*hit.object);
  const auto find = [&](const auto& left) {
    const InteriorLink* found = child.interiors;
    while (found && !left(*found)) found = found->outer;
    return found;
  };
  const InteriorLink* found = find([&](const InteriorLink& link) { return link.key == key; });
  if (!found) found = find([&](const InteriorLink& link) { return link.eye && !link.object->inside(ray.origin); });
  Path crossed = child;
  const InteriorLink entered{key, hit.object, media, extras.hollow, false, child.interiors};
  std::vector<InteriorLink> since;
  if (found) {
    for (const InteriorLink* link = child.interiors; link != found; link = link->outer) since.push_back(*link);
    const InteriorLink* outer = found->outer;
    for (size_t i = since.size(); i-- > 0;) since[i].outer = outer, outer = &since[i];
    crossed.interiors = outer;
  } else {
    crossed.interiors = &entered;
  }
  return trace(ray, RayRecord::Kind::Refraction, crossed, record);
}

template <class T>
[[gnu::always_inline]] inline
Color Tracer<T>::secondary(const Ray<T>& ray, const Hit<T>& hit, const Material& m, const Vec3<T>& n,
                           const Weights& w, const std::optional<Vec3<T>>& refracted, const Path& path,
                           RayRecord* record) {
  const bool entering = glm::dot(ray.dir, hit.normal) <= T(0);
  Color refraction(0), reflection(0);
  Path child = path;
  ++child.depth;
  // The weight a child's colour has in the pixel includes the tint put on it: transmitted light is tinted as
  // the dialect says (Beer's law instead, §c.6), reflected light by the pigment (§c.3).
  const Color transmitTint = options_.beers ? Color(1) : dialect_.transmissionTint(m.pigment, entering);
  child.weight = path.weight * std::abs(w.transmission) * brightest(transmitTint);
  if (child.depth <= maxDepth_ && w.transmission != 0 && matters(child.weight, child.depth)) {
    RayRecord* sub = record ? &record->children.emplace_back() : nullptr;
    if (sub) sub->extraInfo.push_back(entering ? "into-object" : "into-air");
    if (options_.gi.enabled) child.key = childKey(path.key, kRefractionBranch);
    ++counts_.secondary;
    // In a scene with media, the ray enters or leaves the object's interior (Path::interiors).
    const Ray<T> refractedRay = spawnRay(hit, *refracted, *scene_.arithmetic().offset);
    const Traced t = interiors_ ? across(refractedRay, hit, child, sub)
                            : trace(refractedRay, RayRecord::Kind::Refraction, child, sub);
    Color gathered = transmitTint * t.color;
    if (entering && options_.beers) gathered *= beerAttenuation(m.pigment, float(t.distance));
    if (entering && m.extras->fadeDistance > 0) gathered *= interiorFade(m, float(t.distance));
    refraction = w.transmission * gathered;
  }
  Color reflectTint = dialect_.reflectionTint(m.pigment) * w.reflectionTint;
  if (m.extras->reflectionMetallic != 0) {
    reflectTint *= metallicTint(m.pigment, m.extras->reflectionMetallic, float(glm::dot(n, -ray.dir)));
  }
  child.weight = path.weight * w.reflection * brightest(reflectTint);
  if (child.depth <= maxDepth_ && w.reflection > 0 && matters(child.weight, child.depth)) {
    RayRecord* sub = record ? &record->children.emplace_back() : nullptr;
    if (options_.gi.enabled) child.key = childKey(path.key, kReflectionBranch);
    ++counts_.secondary;
    child.mirrored = true;
    const Vec3<T> side = viewerSide(hit, ray);
    const Vec3<T> dir = n == side ? reflectDirection(ray.dir, n) : reflectBent(ray.dir, n, side);
    const Ray<T> mirrored = spawnRay(hit, dir, *scene_.arithmetic().offset);
    const Traced r = trace(mirrored, RayRecord::Kind::Reflection, child, sub);
    reflection = w.reflection * reflectTint * r.color;
  }
  if (record) {
    record->reflection = reflection;
    record->refraction = refraction;
  }
  return reflection + refraction;
}

template <class T>
bool Tracer<T>::shadowRay(const Hit<T>& hit, const Vec3<T>& n, const Light<T>& light, ShadowRay& out) const {
  // A light behind the surface, as the viewer sees it, cannot light it: for a closed surface the shadow ray
  // would run into the object itself (§c.7: no direct light on the inside of glass), and an open one is lit
  // on the light's side only. A light on the point has no direction: n·l is NaN.
  out.l = glm::normalize(light.position - hit.point);
  out.nl = float(glm::dot(n, out.l));
  // Where n faces the light (n·l > 0) it picks the side to leave by as l would. The ray is made before the
  // verdict, which it does not need, so that the two chains of square root and division overlap.
  spawnRayTo(hit, light.position, out.l, n, *scene_.arithmetic().offset, out.ray, out.segment);
  out.occluded = false;
  return out.nl > 0.0f;
}

template <class T>
bool Tracer<T>::sampledLight(const Hit<T>& hit, const Vec3<T>& n, const Light<T>& light, size_t index,
                             ShadowRay& out, Color& lightColor, bool areaAsPoint) {
  const OffsetPolicy offset = *scene_.arithmetic().offset;
  // A parallel light shines along its direction from the plane through its position across it; a point beyond
  // that plane is lit with no shadow (POV-Ray 3.7 manual, "Parallel Lights").
  const auto target = [&](const Vec3<T>& at) {
    return light.parallel ? hit.point + *light.parallel * glm::dot(at - hit.point, *light.parallel) : at;
  };
  out.l = light.parallel ? *light.parallel : glm::normalize(light.position - hit.point);
  out.nl = float(glm::dot(n, out.l));
  spawnRayTo(hit, target(light.position), out.l, n, offset, out.ray, out.segment);
  out.occluded = false;
  // With area_illumination a grid point above the surface's horizon may light it while the centre is below.
  const bool lit = out.nl > 0.0f || (light.area && light.area->illumination && !areaAsPoint);
  if (!lit || (light.shadowless && !scene_.projected(index))) return lit;
  const bool beyond = light.parallel && !(glm::dot(light.position - hit.point, *light.parallel) > T(0));
  // What reaches the point from `at` along a shadow ray: all, none, or through transparent surfaces.
  const auto seen = [&](const Ray<T>& ray, const Interval<T>& whole) {
    const std::optional<Interval<T>> segment = scene_.reaching(index, ray, whole);
    if (!segment) return Color(0);
    if (light.shadowless) return Color(1);
    if (filteredShadows_) return transmittance(ray, *segment);
    ++counts_.shadow;
    return scene_.occluded(ray, *segment, &lastOccluder_[index]) ? Color(0) : Color(1);
  };
  Color share(1);
  if (!light.area || areaAsPoint) {
    if (!beyond) share = seen(out.ray, out.segment);
  } else if (!beyond) {
    const GridSeenFrom grid(*light.area, glm::dvec3(light.position), hit.point, index);
    share = light.area->share(
        [&](int i, int j) {
          const Vec3<T> at = target(Vec3<T>(grid(i, j)));
          Ray<T> ray;
          Interval<T> segment;
          spawnRayTo(hit, at, glm::normalize(at - hit.point), n, offset, ray, segment);
          return seen(ray, segment);
        },
        areaGrid_, areaKnown_);
  }
  lightColor *= share;
  out.occluded = share == Color(0);
  if (light.mediaAttenuation && !out.occluded) {
    const T distance = light.parallel ? std::max(glm::dot(light.position - hit.point, *light.parallel), T(0))
                                      : glm::length(light.position - hit.point);
    lightColor *= attenuation(hit.point, out.l, distance);
  }
  return true;
}

template class Tracer<float>;
template class Tracer<double>;

}  // namespace rt
