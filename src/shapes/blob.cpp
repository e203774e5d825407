#include "raytrace/shapes/blob.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

namespace {

// The box of a component's support in the blob's space: its own box's eight corners moved by its transforms.
Aabb<double> supportBox(const BlobComponent& c) {
  const glm::dmat4 m = composeTransforms<double>(c.transforms);
  Aabb<double> box;
  const glm::dvec3 lo = glm::min(c.a, c.b) - c.radius, hi = glm::max(c.a, c.b) + c.radius;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 corner((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    box.expand(glm::dvec3(m * glm::dvec4(corner, 1)));
  }
  return box;
}

// Only the components of positive strength raise the field to a positive threshold: the surface lies in theirs.
Aabb<double> surfaceBox(const std::vector<BlobComponent>& components) {
  Aabb<double> box;
  for (const BlobComponent& c : components) {
    if (c.strength > 0) box.expand(supportBox(c));
  }
  if (box.min.x > box.max.x) box.min = box.max = components.front().a;  // no surface: a point's box
  return box;
}

// The relative rounding of a quartic's value, its coefficients sums of products of the ray's and the parts'
// numbers that can be larger than the value: a root within it of the ray's start is the surface it leaves.
// 1024 ulps of the value's size, and so of t where the slope is of the field's size (the sweeps' choice).
constexpr double kRounding = 1024 * std::numeric_limits<double>::epsilon();

constexpr double kMerged = 1e-10;

// A stretch of the ray, from..to, where one component adds the quartic `field` in t.
struct Stretch {
  double from, to;
  Polynomial field;
};

// strength·(1 − q)² for q = q2·t² + q1·t + q0, the squared distance over the squared radius.
Polynomial density(double strength, double q2, double q1, double q0) {
  const double p2 = -q2, p1 = -q1, p0 = 1 - q0;
  Polynomial f;
  f.degree = 4;
  f.c = {strength * p0 * p0, strength * 2 * p0 * p1, strength * (p1 * p1 + 2 * p0 * p2), strength * 2 * p1 * p2,
         strength * p2 * p2};
  return f;
}

// Where q(t) < 1 within from..to, as a stretch of the ray.
void addStretch(double strength, double q2, double q1, double q0, double from, double to, std::vector<Stretch>& out) {
  double lo = from, hi = to;
  if (q2 > 0) {
    const double disc = q1 * q1 - 4 * q2 * (q0 - 1);
    if (!(disc > 0)) return;
    const double s = std::sqrt(disc);
    lo = std::max(lo, (-q1 - s) / (2 * q2));
    hi = std::min(hi, (-q1 + s) / (2 * q2));
  } else if (!(q0 < 1)) {
    return;  // along the axis: the distance does not change
  }
  if (lo < hi) out.push_back({lo, hi, density(strength, q2, q1, q0)});
}

}  // namespace

double BlobDesc::smallestFeature() const {
  double smallest = std::numeric_limits<double>::infinity();
  for (const BlobComponent& c : components) smallest = std::min(smallest, c.radius);
  return smallest;
}

Ball BlobDesc::boundingBall() const {
  const Aabb<double> box = surfaceBox(components);
  return {(box.min + box.max) / 2.0, glm::length(box.max - box.min) / 2};
}

void BlobDesc::describe(std::ostream& out) const {
  out << "- Threshold: " << fixed4(threshold) << "\n- Components: " << components.size() << "\n";
  for (const BlobComponent& c : components) {
    out << "  - " << (c.cylinder ? "Cylinder " + braces(c.a) + " " + braces(c.b) : "Sphere " + braces(c.a))
        << ", radius " << fixed4(c.radius) << ", strength " << fixed4(c.strength) << "\n";
  }
}

template <class T> std::unique_ptr<Object<T>> BlobDesc::make(const ObjectBuild& b) const {
  std::vector<typename Blob<T>::Part> parts;
  for (const BlobComponent& c : components) {
    parts.push_back({c.a, c.b - c.a, c.radius * c.radius, c.strength,
                     glm::inverse(composeTransforms<double>(c.transforms))});
  }
  const Aabb<double> box = surfaceBox(components);
  return std::make_unique<Blob<T>>(std::move(parts), threshold, sturm ? RootMethod::Sturm : RootMethod::Auto,
                                   Aabb<T>{Vec3<T>(box.min), Vec3<T>(box.max)}, b.material, b.id);
}

template std::unique_ptr<Object<float>> BlobDesc::make<float>(const ObjectBuild&) const;
template std::unique_ptr<Object<double>> BlobDesc::make<double>(const ObjectBuild&) const;

template <class T>
Blob<T>::Blob(std::vector<Part> parts, double threshold, RootMethod method, const Aabb<T>& box,
              const Material& material, int id)
    : Object<T>(material, id), parts_(std::move(parts)), threshold_(threshold), method_(method), box_(box) {}

// The point of a part's ball centre or segment nearest p, in the part's space.
template <class T> static glm::dvec3 nearest(const typename Blob<T>::Part& part, const glm::dvec3& local) {
  const double length2 = glm::dot(part.axis, part.axis);
  const double u = length2 > 0 ? std::clamp(glm::dot(local - part.a, part.axis) / length2, 0.0, 1.0) : 0.0;
  return part.a + u * part.axis;
}

template <class T> double Blob<T>::field(const glm::dvec3& p) const {
  double sum = 0;
  for (const Part& part : parts_) {
    const glm::dvec3 local(part.fromWorld * glm::dvec4(p, 1));
    const glm::dvec3 offset = local - nearest<T>(part, local);
    const double q = glm::dot(offset, offset) / part.radius2;
    if (q < 1) sum += part.strength * (1 - q) * (1 - q);
  }
  return sum;
}

// ∇field = −Σ 4·strength·(1 − q)·Mᵀ(p′ − nearest)/r², with M each part's linear map.
template <class T> glm::dvec3 Blob<T>::gradient(const glm::dvec3& p) const {
  glm::dvec3 g(0);
  for (const Part& part : parts_) {
    const glm::dvec3 local(part.fromWorld * glm::dvec4(p, 1));
    const glm::dvec3 offset = local - nearest<T>(part, local);
    const double q = glm::dot(offset, offset) / part.radius2;
    if (q < 1) g -= 4 * part.strength * (1 - q) / part.radius2 * (glm::transpose(glm::dmat3(part.fromWorld)) * offset);
  }
  return g;
}

// t is counted from where the ray enters the blob's box, so that the quartics' coefficients stay of the blob's
// size. Each part gives the stretches where it reaches the ray (a capsule: its two caps and its side, split
// where the ray crosses the planes across its ends); between consecutive ends of stretches the field is one
// quartic, whose first root against the threshold is the hit.
template <class T> std::optional<Hit<T>> Blob<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const glm::dvec3 origin(ray.origin), d(ray.dir);
  double near = double(range.min), far = double(range.max);
  for (int i = 0; i < 3; ++i) {
    const double ta = (double(box_.min[i]) - origin[i]) / d[i], tb = (double(box_.max[i]) - origin[i]) / d[i];
    if (std::isnan(ta) || std::isnan(tb)) continue;  // in a face's plane, parallel to it
    near = std::max(near, std::min(ta, tb));
    far = std::min(far, std::max(ta, tb));
  }
  if (!(near <= far)) return std::nullopt;
  const double shift = near;
  const glm::dvec3 o = origin + shift * d;
  std::vector<Stretch> stretches;
  for (const Part& part : parts_) {
    const glm::dvec3 lo(part.fromWorld * glm::dvec4(o, 1)), ld(part.fromWorld * glm::dvec4(d, 0));
    const auto ball = [&](const glm::dvec3& c, double from, double to) {
      const glm::dvec3 w = lo - c;
      addStretch(part.strength, glm::dot(ld, ld) / part.radius2, 2 * glm::dot(w, ld) / part.radius2,
                 glm::dot(w, w) / part.radius2, from, to, stretches);
    };
    const double inf = std::numeric_limits<double>::infinity();
    const double length2 = glm::dot(part.axis, part.axis);
    if (length2 == 0) {
      ball(part.a, -inf, inf);
      continue;
    }
    // u(t) = u0 + u1·t, the position along the axis (0 at a, 1 at b).
    const glm::dvec3 w = lo - part.a;
    const double u0 = glm::dot(w, part.axis) / length2, u1 = glm::dot(ld, part.axis) / length2;
    double enter = -inf, leave = inf;  // where u lies in [0, 1]
    if (u1 != 0) {
      enter = std::min(-u0 / u1, (1 - u0) / u1);
      leave = std::max(-u0 / u1, (1 - u0) / u1);
      ball(u1 > 0 ? part.a : part.a + part.axis, -inf, enter);
      ball(u1 > 0 ? part.a + part.axis : part.a, leave, inf);
    } else if (u0 < 0 || u0 > 1) {
      ball(u0 < 0 ? part.a : part.a + part.axis, -inf, inf);
      continue;
    }
    // The side: |w + t·d|² − L²·u(t)², the squared distance from the axis.
    addStretch(part.strength, (glm::dot(ld, ld) - length2 * u1 * u1) / part.radius2,
               (2 * glm::dot(w, ld) - 2 * length2 * u0 * u1) / part.radius2,
               (glm::dot(w, w) - length2 * u0 * u0) / part.radius2, enter, leave, stretches);
  }
  // Where two stretches meet their quartics agree only up to rounding, and a crossing there can be found again
  // from just past it: crossings closer than this fraction of the blob's size are one.
  const double skip = kMerged * glm::length(glm::dvec3(box_.max - box_.min)) / glm::length(d);
  std::vector<double> ends{0, far - shift};
  for (const Stretch& s : stretches) {
    if (s.from > 0 && s.from < far - shift) ends.push_back(s.from);
    if (s.to > 0 && s.to < far - shift) ends.push_back(s.to);
  }
  std::sort(ends.begin(), ends.end());
  for (size_t k = 0; k + 1 < ends.size(); ++k) {
    const double lo = ends[k], hi = ends[k + 1], mid = lo + (hi - lo) / 2;
    if (!(lo < hi)) continue;
    Polynomial f;
    f.degree = 4;
    bool reached = false;
    for (const Stretch& s : stretches) {
      if (!(s.from <= mid && mid <= s.to)) continue;
      reached = true;
      for (size_t i = 0; i < 5; ++i) f.c[i] += s.field.c[i];
    }
    if (!reached) continue;
    f.c[0] -= threshold_;
    double roots[4];
    const int n = realRoots(f.trimmed(), lo, hi, roots, 4, method_);
    const Polynomial slope = f.derivative();
    for (int r = 0; r < n; ++r) {
      // A root within its rounding of the start is the surface the ray leaves (as in Algebraic::firstHit).
      const double s = roots[r], size = std::abs(f.c[0] + threshold_) + std::abs(f.c[1] * s) +
                                        std::abs(f.c[2] * s * s) + std::abs(f.c[3] * s * s * s) +
                                        std::abs(f.c[4] * s * s * s * s) + threshold_;
      if (s - kRounding * size / std::abs(slope(s)) <= skip) continue;
      const double t = s + shift;
      if (!range.surrounds(T(t))) return std::nullopt;
      glm::dvec3 p = origin + t * d;
      const glm::dvec3 g = gradient(p);
      const double gg = glm::dot(g, g);
      if (!(gg > 0 && std::isfinite(gg))) return std::nullopt;  // a point where the field is flat: no normal
      p -= (field(p) - threshold_) / gg * g;  // one Newton step onto the surface (docs/reference/stability.md F4)
      Hit<T> hit;
      hit.t = T(t);
      hit.point = Vec3<T>(p);
      hit.normal = Vec3<T>(-g / std::sqrt(gg));  // the field falls outward
      hit.object = this;
      return hit;
    }
  }
  return std::nullopt;
}

template class Blob<float>;
template class Blob<double>;

}  // namespace rt
