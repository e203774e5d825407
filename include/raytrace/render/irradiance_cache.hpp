// Irradiance caching (Ward, Rubinstein and Clear 1988, with the gradients of Ward and Heckbert 1992; docs/gi.md):
// what the first bounce gathers at a point is stored as a record and reused, corrected by its gradients, at
// nearby points whose normals agree. The records sit in an octree; a lookup visits them in a fixed order, so its
// answer depends only on the records and the order they were added in.
#pragma once

#include <optional>
#include <vector>

#include "raytrace/geometry/math.hpp"
#include "raytrace/render/sampler.hpp"

namespace rt {

template <class T> struct IrradianceRecord {
  Vec3<T> point, normal;  // where the value was gathered; the normal is the shading normal there
  Color value;            // the mean radiance of the gather rays: view-independent
  T radius;               // R: the harmonic mean distance of the gather rays' hits, clamped (clampRadius)
  // The value's change per unit of displacement (column c: along axis c) and per rotation of the normal
  // (column c: about axis c), per channel: value + translation·(x − point) + rotation·(normal × n).
  glm::mat3 translation{0.0f}, rotation{0.0f};
};

// Ward's weight of a record at (x, n): 1 / (|x − xᵢ|/Rᵢ + √(1 − n·nᵢ)); +∞ at the record itself.
template <class T> T recordWeight(const IrradianceRecord<T>& r, const Vec3<T>& x, const Vec3<T>& n);
// Ward's test: the record lies in front of x (above its tangent plane, by (x − xᵢ)·(n + nᵢ)/2 below a hair's
// breadth of −Rᵢ), so it sees light that x may not.
template <class T> bool inFront(const IrradianceRecord<T>& r, const Vec3<T>& x, const Vec3<T>& n);
// The record's value carried to (x, n) by its gradients, each channel at least 0.
template <class T> Color extrapolate(const IrradianceRecord<T>& r, const Vec3<T>& x, const Vec3<T>& n);

// What one stratified set of gather rays from a point brings back, sample i in stratum (i / cols, i % cols):
// its direction, its radiance and the distance to its hit (+∞ on a miss).
template <class T> struct GatherSamples {
  Strata strata;
  const Vec3<T>* directions;
  const Color* radiance;
  const T* distances;
};
// The record of a gathered point: the mean, the harmonic mean distance (+∞ if every ray missed) and Ward and
// Heckbert's gradients for the cosine-weighted strata (docs/gi.md); radius still to be clamped. The translational
// gradient takes no distance below `nearest`: a hit closer than the records' least radius would make it
// extrapolate wildly along edges and corners.
template <class T>
IrradianceRecord<T> makeRecord(const Vec3<T>& point, const Vec3<T>& normal, const GatherSamples<T>& samples,
                               T nearest = 0);

template <class T> class IrradianceCache {
 public:
  // `accuracy` is Ward's a: a record is used where its weight exceeds 1/a. A record's radius is kept within
  // [kMinRadius, kMaxRadius] pixels, a pixel at distance d from `eye` being d·pixelSize wide.
  IrradianceCache(float accuracy, const Vec3<T>& eye, T pixelSize);

  static constexpr T kMinRadius = 10, kMaxRadius = 100;
  // R clamped to the pixel-sized bounds at `point`: records neither shrink to nothing in corners nor reach
  // across the picture in open space.
  T clampRadius(const Vec3<T>& point, T radius) const;

  // Appends the records, in order, after those already there.
  void add(const std::vector<IrradianceRecord<T>>& records);
  // The weighted mean of the records usable at (x, n), Ward's interpolation; nothing if none is.
  std::optional<Color> lookup(const Vec3<T>& x, const Vec3<T>& n) const;

  size_t size() const { return records_.size(); }
  float accuracy() const { return accuracy_; }

 private:
  struct Node {
    Vec3<T> centre;
    T half;                 // half the cube's side
    int children[8];        // -1: none
    std::vector<int> held;  // records whose reach fits in this cube grown by half its side, but not a child's
  };
  void rebuild();
  void insert(int record);

  float accuracy_;
  Vec3<T> eye_;
  T pixelSize_;
  std::vector<IrradianceRecord<T>> records_;
  std::vector<Node> nodes_;  // [0] the root, a cube around every record
};

}  // namespace rt
