#include "raytrace/shapes/text.hpp"

#include <cmath>

namespace rt {

namespace {

double cross(const glm::dvec2& u, const glm::dvec2& v) { return u.x * v.y - u.y * v.x; }

// How far past an edge's ends, and past the faces, a wall still counts: a ray through the corner of two edges,
// or along the rim of a face, meets one of them despite rounding.
constexpr double kSlack = 1e-9;

// Where the ray is inside the box lo..hi, narrowing [tNear, tFar]; false if nowhere (slabs, inclusive, as Box).
bool slabs(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& o, const glm::dvec3& d, double& tNear,
           double& tFar) {
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0) {
      if (o[a] < lo[a] || o[a] > hi[a]) return false;
      continue;
    }
    const double t0 = (lo[a] - o[a]) / d[a], t1 = (hi[a] - o[a]) / d[a];
    tNear = std::max(tNear, std::min(t0, t1));
    tFar = std::min(tFar, std::max(t0, t1));
  }
  return tNear <= tFar;
}

}  // namespace

template <class T>
Text<T>::Slices::Slices(double from, double to, size_t count)
    : lo(from), size(std::max((to - from) / double(count), 1e-12)), items(count) {}

template <class T> void Text<T>::Slices::add(uint32_t item, double from, double to) {
  for (size_t k = at(from); k <= at(to); ++k) items[k].push_back(item);
}

template <class T>
Text<T>::Text(const TextDesc& desc, const Material& material, int id)
    : Object<T>(material, id),
      glyphs_(desc.glyphs),
      thickness_(desc.thickness),
      bounds_(desc.bounds()),
      columns_(bounds_.min.x, bounds_.max.x, std::max<size_t>(glyphs_->size(), 1)) {
  for (uint32_t gi = 0; gi < glyphs_->size(); ++gi) {
    const PlacedGlyph& g = (*glyphs_)[gi];
    columns_.add(gi, g.lo.x, g.hi.x);
    // About eight edges to a band: few edges to test, and few edges in several bands.
    Slices bands(g.lo.y, g.hi.y, std::clamp<size_t>(g.edges.size() / 8, 1, 256));
    for (uint32_t i = 0; i < g.edges.size(); ++i) {
      const OutlineEdge& e = g.edges[i];
      bands.add(i, std::min(e.a.y, e.b.y), std::max(e.a.y, e.b.y));
    }
    bands_.push_back(std::move(bands));
  }
}

// The winding number counts the edges that cross the horizontal line through p to its right, upward ones +1
// and downward ones -1 (each edge half-open in y, so a contour's vertex on the line counts once).
template <class T> bool Text<T>::covers(size_t glyph, const glm::dvec2& p) const {
  const PlacedGlyph& g = (*glyphs_)[glyph];
  if (p.x < g.lo.x || p.x > g.hi.x || p.y < g.lo.y || p.y > g.hi.y) return false;
  int winding = 0;
  for (const uint32_t i : bands_[glyph].items[bands_[glyph].at(p.y)]) {
    const OutlineEdge& e = g.edges[i];
    const double side = cross(e.b - e.a, p - e.a);
    if (e.a.y <= p.y && p.y < e.b.y && side > 0) ++winding;
    if (e.b.y <= p.y && p.y < e.a.y && side < 0) --winding;
  }
  return winding != 0;
}

template <class T> bool Text<T>::inside(const Vec3<T>& point) const {
  const glm::dvec3 p(point);
  if (!(p.z > 0 && p.z < thickness_)) return false;
  for (const uint32_t gi : columns_.items[columns_.at(p.x)]) {
    if (covers(gi, glm::dvec2(p))) return true;
  }
  return false;
}

template <class T>
void Text<T>::hitGlyph(size_t glyph, const glm::dvec3& o, const glm::dvec3& d, double from, double& best,
                       glm::dvec3& point, glm::dvec3& normal) const {
  const PlacedGlyph& g = (*glyphs_)[glyph];
  const double z0 = 0, z1 = thickness_;
  double tNear = from, tFar = best;
  if (!slabs(glm::dvec3(g.lo, z0), glm::dvec3(g.hi, z1), o, d, tNear, tFar)) return;
  const glm::dvec2 o2(o), d2(d);

  // The faces: outward normals -z in front, +z behind. A ray parallel to them gives an infinite or NaN t.
  for (const double z : {z0, z1}) {
    const double t = (z - o.z) / d.z;
    if (!(from < t && t < best)) continue;
    const glm::dvec2 p = o2 + t * d2;
    if (!covers(glyph, p)) continue;
    best = t;
    point = glm::dvec3(p, z);
    normal = glm::dvec3(0, 0, z == z0 ? -1 : 1);
  }

  // The walls of the edges in the bands the ray crosses within the box.
  const Slices& bands = bands_[glyph];
  const double yNear = o.y + tNear * d.y, yFar = o.y + tFar * d.y;
  for (size_t k = bands.at(std::min(yNear, yFar)); k <= bands.at(std::max(yNear, yFar)); ++k) {
    for (const uint32_t i : bands.items[k]) {
      const OutlineEdge& e = g.edges[i];
      const glm::dvec2 along = e.b - e.a, toEdge = e.a - o2;
      const double denominator = cross(d2, along);
      if (denominator == 0) continue;
      const double t = cross(toEdge, along) / denominator;
      if (!(from < t && t < best)) continue;
      const double s = cross(toEdge, d2) / denominator, z = o.z + t * d.z;
      if (s < -kSlack || s > 1 + kSlack || z < z0 - kSlack || z > z1 + kSlack) continue;
      const double on = std::clamp(s, 0.0, 1.0);
      best = t;
      point = glm::dvec3(e.a + on * along, std::clamp(z, z0, z1));
      normal = glm::dvec3(glm::normalize(glm::mix(e.normalA, e.normalB, on)), 0);
    }
  }
}

template <class T> std::optional<Hit<T>> Text<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const glm::dvec3 o(ray.origin), d(ray.dir);
  double tNear = double(range.min), tFar = double(range.max);
  if (glyphs_->empty() || !slabs(bounds_.min, bounds_.max, o, d, tNear, tFar)) return std::nullopt;
  // The glyphs of the columns the ray crosses within the text's box, each once: in the first of its columns
  // that the ray crosses.
  const double xNear = o.x + tNear * d.x, xFar = o.x + tFar * d.x;
  const size_t first = columns_.at(std::min(xNear, xFar)), last = columns_.at(std::max(xNear, xFar));
  double best = double(range.max);
  glm::dvec3 point(0), normal(0);
  for (size_t k = first; k <= last; ++k) {
    for (const uint32_t gi : columns_.items[k]) {
      if (std::max(columns_.at((*glyphs_)[gi].lo.x), first) == k) hitGlyph(gi, o, d, double(range.min), best, point, normal);
    }
  }
  if (!(best < double(range.max))) return std::nullopt;
  Hit<T> hit;
  hit.t = T(best);
  hit.point = Vec3<T>(point);
  hit.normal = Vec3<T>(normal);
  hit.object = this;
  return hit;
}

template class Text<float>;
template class Text<double>;

}  // namespace rt
