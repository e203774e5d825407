#include "raytrace/render/irradiance_cache.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/constants.hpp>

namespace rt {

namespace {

// Ward's error of a record at (x, n), the inverse of its weight: |x − xᵢ|/Rᵢ + √(1 − n·nᵢ).
template <class T> T recordError(const IrradianceRecord<T>& r, const Vec3<T>& x, const Vec3<T>& n) {
  return glm::length(x - r.point) / r.radius + std::sqrt(std::max(T(0), T(1) - glm::dot(n, r.normal)));
}

// A unit vector of the tangent plane of n at azimuth phi, in the frame cosineHemisphere's directions use.
template <class T> glm::vec3 tangent(const Vec3<T>& n, double phi) {
  return glm::vec3(aroundNormal(Vec3<T>(T(std::cos(phi)), T(std::sin(phi)), T(0)), n));
}

constexpr int kMaxDepth = 24;  // octree levels: far below any radius a float scene can tell apart

}  // namespace

template <class T> T recordWeight(const IrradianceRecord<T>& r, const Vec3<T>& x, const Vec3<T>& n) {
  const T e = recordError(r, x, n);
  return e > T(0) ? T(1) / e : std::numeric_limits<T>::infinity();
}

template <class T> bool inFront(const IrradianceRecord<T>& r, const Vec3<T>& x, const Vec3<T>& n) {
  // The hair's breadth keeps records on the same plane, off by rounding, from being rejected.
  constexpr T kTolerance = T(1e-3);
  return glm::dot(x - r.point, (n + r.normal) * T(0.5)) < -kTolerance * r.radius;
}

template <class T> Color extrapolate(const IrradianceRecord<T>& r, const Vec3<T>& x, const Vec3<T>& n) {
  const Color c =
      r.value + r.translation * glm::vec3(x - r.point) + r.rotation * glm::vec3(glm::cross(r.normal, n));
  return glm::max(c, Color(0));
}

template <class T>
IrradianceRecord<T> makeRecord(const Vec3<T>& point, const Vec3<T>& normal, const GatherSamples<T>& s, T nearest) {
  const int rows = s.strata.rows, cols = s.strata.cols, count = rows * cols;
  IrradianceRecord<T> r;
  r.point = point;
  r.normal = normal;
  Color sum(0);
  T inverseDistances = 0;
  for (int i = 0; i < count; ++i) {
    sum += s.radiance[i];
    inverseDistances += T(1) / s.distances[i];  // 0 for a miss
  }
  r.value = sum / float(count);
  r.radius = inverseDistances > T(0) ? T(count) / inverseDistances : std::numeric_limits<T>::infinity();

  // Rotational gradient (Ward and Heckbert 1992): turning n about axis a changes the cosine of direction d by
  // a·(n × d) = a·v(φ) sin θ, which under the density cos θ/π weighs its radiance by tan θ along v(φ), the
  // tangent a quarter turn past d's azimuth. At the strata's middles, so that a constant field gives 0.
  for (int k = 0; k < cols; ++k) {
    const glm::vec3 v = tangent(normal, 2 * glm::pi<double>() * (k + 0.5) / cols + glm::half_pi<double>());
    Color column(0);
    for (int j = 0; j < rows; ++j) {
      const double sin2 = (j + 0.5) / rows;
      column += s.radiance[size_t(j * cols + k)] * float(std::sqrt(sin2 / (1 - sin2)));
    }
    r.rotation += glm::outerProduct(column, v);
  }
  r.rotation /= float(count);

  // Translational gradient (Ward and Heckbert 1992, for strata of equal cos θ/π share: rows in sin²θ, columns
  // in φ): moving the point moves the edges between strata by 1/distance of the nearer hit; each edge trades
  // the radiance difference across it. Divided by π, as the value is the irradiance over π.
  const auto at = [&](int j, int k) { return size_t(j * cols + (k + cols) % cols); };
  const auto nearer = [&](size_t a, size_t b) {
    return T(1) / std::max(nearest, std::min(s.distances[a], s.distances[b]));
  };
  for (int k = 0; k < cols; ++k) {
    const double phi = 2 * glm::pi<double>() * (k + 0.5) / cols;  // the column's middle
    const double edge = 2 * glm::pi<double>() * k / cols;         // its edge with column k − 1
    const glm::vec3 u = tangent(normal, phi), v = tangent(normal, edge + glm::half_pi<double>());
    for (int j = 1; j < rows; ++j) {  // the cone between rows j − 1 and j, at sin²θ = j/rows
      const double sin2 = double(j) / rows;
      const float f =
          float(2 * glm::pi<double>() / cols * std::sqrt(sin2) * (1 - sin2) * nearer(at(j, k), at(j - 1, k)));
      r.translation += glm::outerProduct((s.radiance[at(j, k)] - s.radiance[at(j - 1, k)]) * f, u);
    }
    for (int j = 0; j < rows; ++j) {  // the half-plane between columns k − 1 and k
      const double width = std::sqrt(double(j + 1) / rows) - std::sqrt(double(j) / rows);  // in sin θ
      const float f = float(width * nearer(at(j, k), at(j, k - 1)));
      r.translation += glm::outerProduct((s.radiance[at(j, k)] - s.radiance[at(j, k - 1)]) * f, v);
    }
  }
  r.translation /= glm::pi<float>();
  return r;
}

template <class T>
IrradianceCache<T>::IrradianceCache(float accuracy, const Vec3<T>& eye, T pixelSize)
    : accuracy_(accuracy), eye_(eye), pixelSize_(pixelSize) {}

template <class T> T IrradianceCache<T>::clampRadius(const Vec3<T>& point, T radius) const {
  const T pixel = glm::length(point - eye_) * pixelSize_;
  return std::clamp(radius, kMinRadius * pixel, kMaxRadius * pixel);
}

template <class T> void IrradianceCache<T>::add(const std::vector<IrradianceRecord<T>>& records) {
  records_.insert(records_.end(), records.begin(), records.end());
  rebuild();
}

template <class T> void IrradianceCache<T>::rebuild() {
  nodes_.clear();
  if (records_.empty()) return;
  Vec3<T> lo = records_[0].point, hi = lo;
  for (const auto& r : records_) lo = glm::min(lo, r.point), hi = glm::max(hi, r.point);
  const Vec3<T> extent = hi - lo;
  nodes_.push_back(Node{(lo + hi) * T(0.5), std::max({extent.x, extent.y, extent.z, T(1e-6)}) * T(0.5), {}, {}});
  std::fill(std::begin(nodes_[0].children), std::end(nodes_[0].children), -1);
  for (int i = 0; i < int(records_.size()); ++i) insert(i);
}

template <class T> void IrradianceCache<T>::insert(int record) {
  const IrradianceRecord<T>& r = records_[size_t(record)];
  const T reach = T(accuracy_) * r.radius;  // beyond it, |x − xᵢ|/Rᵢ alone exceeds a
  size_t node = 0;
  for (int depth = 0; depth < kMaxDepth && nodes_[node].half * T(0.5) >= reach; ++depth) {
    const Vec3<T> c = nodes_[node].centre;
    const T half = nodes_[node].half * T(0.5);
    const int octant = (r.point.x >= c.x ? 1 : 0) | (r.point.y >= c.y ? 2 : 0) | (r.point.z >= c.z ? 4 : 0);
    if (nodes_[node].children[octant] < 0) {
      const Vec3<T> offset((octant & 1) ? half : -half, (octant & 2) ? half : -half, (octant & 4) ? half : -half);
      nodes_[node].children[octant] = int(nodes_.size());
      nodes_.push_back(Node{c + offset, half, {}, {}});
      std::fill(std::begin(nodes_.back().children), std::end(nodes_.back().children), -1);
    }
    node = size_t(nodes_[node].children[octant]);
  }
  nodes_[node].held.push_back(record);
}

template <class T> std::optional<Color> IrradianceCache<T>::lookup(const Vec3<T>& x, const Vec3<T>& n) const {
  if (nodes_.empty()) return std::nullopt;
  Color sum(0);
  T weights = 0;
  int stack[8 * kMaxDepth + 8], top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[size_t(stack[--top])];
    for (const int i : node.held) {
      const IrradianceRecord<T>& r = records_[size_t(i)];
      // A record in front of x sees light that x may not (a record facing away has an error above 1 ≥ a).
      if (inFront(r, x, n)) continue;
      const T e = recordError(r, x, n);
      if (e == T(0)) return extrapolate(r, x, n);
      if (e >= T(accuracy_)) continue;  // weight 1/e not above 1/a
      sum += float(T(1) / e) * extrapolate(r, x, n);
      weights += T(1) / e;
    }
    // Children pushed last first, so that they are visited in index order.
    for (int c = 7; c >= 0; --c) {
      const int child = node.children[c];
      if (child < 0) continue;
      const Node& k = nodes_[size_t(child)];
      const Vec3<T> d = glm::abs(x - k.centre);
      if (std::max({d.x, d.y, d.z}) <= T(2) * k.half) stack[top++] = child;
    }
  }
  if (weights == T(0)) return std::nullopt;
  return sum / float(weights);
}

#define RT_INSTANTIATE(T)                                                                                       \
  template T recordWeight(const IrradianceRecord<T>&, const Vec3<T>&, const Vec3<T>&);                          \
  template bool inFront(const IrradianceRecord<T>&, const Vec3<T>&, const Vec3<T>&);                           \
  template Color extrapolate(const IrradianceRecord<T>&, const Vec3<T>&, const Vec3<T>&);                      \
  template IrradianceRecord<T> makeRecord(const Vec3<T>&, const Vec3<T>&, const GatherSamples<T>&, T);         \
  template class IrradianceCache<T>;
RT_INSTANTIATE(float)
RT_INSTANTIATE(double)
#undef RT_INSTANTIATE

}  // namespace rt
