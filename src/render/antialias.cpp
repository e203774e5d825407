#include "raytrace/render/antialias.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <mutex>

#include "raytrace/render/sampler.hpp"
#include "raytrace/util/parallel.hpp"

namespace rt {

namespace {

// The pixels of the first pass go to the threads in squares of this side, as the renderer's tiles.
constexpr int kBlock = 32;
// The branch of a sample's key its jitter comes from: far from the small indices gathering branches on.
constexpr uint64_t kJitterBranch = uint64_t(1) << 40;

glm::vec2 jitterOf(uint64_t key) { return uniformPair(childKey(key, kJitterBranch)) - glm::vec2(0.5f); }

}  // namespace

namespace {

// x^0.4 for x in [0, 1] from a table over the float's exponent and the top 8 bits of its mantissa, interpolated
// linearly in between: within 1e-6 of pow() (the curve is nearly straight across 1/256 of an octave), at a
// fraction of its cost, which every pixel pays. Below 2^-40, where x^0.4 < 2e-5, it is 0.
class Power04 {
 public:
  static constexpr int kOctaves = 40, kSteps = 256;
  Power04() {
    for (int e = 0; e < kOctaves; ++e) {
      for (int i = 0; i <= kSteps; ++i) {
        table_[size_t(e * (kSteps + 1) + i)] = float(std::pow(std::ldexp(1.0 + double(i) / kSteps, -1 - e), 0.4));
      }
    }
  }
  float operator()(float x) const {
    if (!(x > 0)) return 0;
    if (x >= 1) return 1;
    uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int octave = 126 - int(bits >> 23);  // x in [2^(−1−octave), 2^−octave)
    if (octave >= kOctaves) return 0;
    const uint32_t mantissa = bits & 0x7FFFFFu;
    const float* row = &table_[size_t(octave * (kSteps + 1)) + (mantissa >> 15)];
    const float t = float(mantissa & 0x7FFFu) * (1.0f / 32768.0f);
    return row[0] + (row[1] - row[0]) * t;
  }

 private:
  std::array<float, size_t(kOctaves * (kSteps + 1))> table_;
};

const Power04 kPower04;

}  // namespace

Color aaCompared(const Color& c) { return {kPower04(c.r), kPower04(c.g), kPower04(c.b)}; }

float aaDifference(const Color& a, const Color& b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

std::vector<char> refinedPixels(const Color* compared, int w, int h, float threshold) {
  std::vector<char> refined(size_t(w) * size_t(h), 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t p = size_t(y) * size_t(w) + size_t(x);
      // Each pair once, with the neighbour to the right and the one in the next row: both are refined.
      if (x + 1 < w && aaDifference(compared[p], compared[p + 1]) > threshold) refined[p] = refined[p + 1] = 1;
      if (y + 1 < h && aaDifference(compared[p], compared[p + size_t(w)]) > threshold) {
        refined[p] = refined[p + size_t(w)] = 1;
      }
    }
  }
  return refined;
}

template <class T>
AdaptiveSampler<T>::AdaptiveSampler(const Tracer<T>& tracer, const Camera<T>& camera, const RenderOptions& options,
                                    int width, int height, int left, int bottom, int right, int top,
                                    RayCounts& counts)
    : camera_(camera), aa_(options.aa), seed_(options.gi.seed), gi_(options.gi.enabled),
      cells_(1 << (options.aa.depth - 1)) {
  // +AM1 compares each pixel with its neighbours, so the pixels around the area are traced too (those of the
  // picture only); +AM2 traces the area's corners, one more than its pixels each way.
  int x1 = right + 1, y1 = top + 1;
  x0_ = left, y0_ = bottom;
  if (aa_.method == 1) {
    x0_ = std::max(0, left - 1), y0_ = std::max(0, bottom - 1);
    x1 = std::min(width, right + 1), y1 = std::min(height, top + 1);
  }
  stride_ = x1 - x0_;
  const int rows = y1 - y0_;
  raw_.resize(size_t(stride_) * size_t(rows));
  compared_.resize(raw_.size());
  const int blocksX = (stride_ + kBlock - 1) / kBlock, blocksY = (rows + kBlock - 1) / kBlock;
  std::mutex countsMutex;
  parallelFor(blocksX * blocksY, options.threads, [&](int block) {
    const int bx0 = x0_ + block / blocksY * kBlock, by0 = y0_ + block % blocksY * kBlock;
    const int bx1 = std::min(x1, bx0 + kBlock), by1 = std::min(y1, by0 + kBlock);
    std::vector<Ray<T>> rays(size_t(bx1 - bx0) * size_t(by1 - by0));
    // Only gathering reads the keys (Tracer::eyeRays): without -gi their hashes are left out.
    std::vector<uint64_t> keys(gi_ ? rays.size() : 0);
    size_t n = 0;
    for (int y = by0; y < by1; ++y) {
      for (int x = bx0; x < bx1; ++x, ++n) {
        rays[n] = aa_.method == 1 ? camera.sampleRay(x, y, 0, 0, 1) : gridRay(x, y, 0, 0);
        if (gi_) keys[n] = aa_.method == 1 ? pixelKey(seed_, x, y, 0) : gridKey(x, y, 0, 0);
      }
    }
    Tracer<T> blockTracer = tracer;
    const Color* colors = blockTracer.eyeRays(rays.data(), keys.data(), rays.size());
    size_t k = 0;
    for (int y = by0; y < by1; ++y) {
      for (int x = bx0; x < bx1; ++x, ++k) {
        const size_t p = size_t(y - y0_) * size_t(stride_) + size_t(x - x0_);
        raw_[p] = colors[k];
        compared_[p] = aaCompared(tracer.finished(colors[k]));
      }
    }
    const std::lock_guard<std::mutex> lock(countsMutex);
    counts += blockTracer.counts();
  });
  if (aa_.method == 1) refined_ = refinedPixels(compared_.data(), stride_, rows, aa_.threshold);
}

template <class T>
void AdaptiveSampler<T>::tile(Tracer<T>& tracer, int x0, int y0, int x1, int y1, std::vector<Color>& out) const {
  out.resize(size_t(x1 - x0) * size_t(y1 - y0));
  if (aa_.method == 1) return nonRecursive(tracer, x0, y0, x1, y1, out);
  size_t k = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) out[k++] = tracer.finished(recursive(tracer, x, y));
  }
}

// A supersampled pixel is the mean of its own ray and R x R more on a grid over it, each jittered within its
// cell; POV-Ray's counts and colours show the pixel's own ray is kept (R² "additional samples" in the manual).
template <class T>
void AdaptiveSampler<T>::nonRecursive(Tracer<T>& tracer, int x0, int y0, int x1, int y1,
                                      std::vector<Color>& out) const {
  const int r = aa_.depth;
  std::vector<Ray<T>> rays;
  std::vector<uint64_t> keys;
  const auto at = [&](int x, int y) { return size_t(y - y0_) * size_t(stride_) + size_t(x - x0_); };
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (!refined_[at(x, y)]) continue;
      for (int i = 0; i < r; ++i) {
        for (int j = 0; j < r; ++j) {
          const uint64_t key = gi_ || aa_.jitter > 0 ? pixelKey(seed_, x, y, 1 + i * r + j) : 0;
          const glm::vec2 jitter = aa_.jitter > 0 ? aa_.jitter * jitterOf(key) : glm::vec2(0);
          rays.push_back(camera_.offsetRay(x, y, (T(i) + T(0.5) + T(jitter.x)) / T(r) - T(0.5),
                                           (T(j) + T(0.5) + T(jitter.y)) / T(r) - T(0.5)));
          keys.push_back(key);
        }
      }
    }
  }
  const Color* colors = rays.empty() ? nullptr : tracer.eyeRays(rays.data(), keys.data(), rays.size());
  size_t k = 0, next = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x, ++k) {
      Color sum = raw_[at(x, y)];
      if (refined_[at(x, y)]) {
        for (int s = 0; s < r * r; ++s) sum += colors[next++];
        sum /= float(r * r + 1);
      }
      out[k] = tracer.finished(sum);
    }
  }
}

template <class T> uint64_t AdaptiveSampler<T>::gridKey(int x, int y, int i, int j) const {
  // Named by its place on the picture's finest grid, so that pixels sharing a point give it one position.
  return pixelKey(seed_, x * cells_ + i, y * cells_ + j, 0);
}

template <class T> Ray<T> AdaptiveSampler<T>::gridRay(int x, int y, int i, int j) const {
  // A point first made at a level of spacing s moves at most s/4 either way, so it stays nearest its own place.
  int spacing = cells_;
  while (i % spacing != 0 || j % spacing != 0) spacing /= 2;
  const glm::vec2 jitter =
      aa_.jitter > 0 ? aa_.jitter * jitterOf(gridKey(x, y, i, j)) * (float(spacing) / float(cells_) / 2) : glm::vec2(0);
  return camera_.offsetRay(x, y, T(i) / T(cells_) - T(0.5) + T(jitter.x), T(j) / T(cells_) - T(0.5) + T(jitter.y));
}

// The pixel's square, its corners traced: a square whose corners differ by more than the threshold (any two
// of them) is cut into four, down to R − 1 levels, and is the mean of its quarters; else of its corners.
// Points inside a pixel are traced once for it, level by level in one batch each.
template <class T> Color AdaptiveSampler<T>::recursive(Tracer<T>& tracer, int x, int y) const {
  const int m = cells_, side = m + 1;
  const auto corner = [&](int cx, int cy) { return size_t(cy - y0_) * size_t(stride_) + size_t(cx - x0_); };
  const std::array<size_t, 4> corners{corner(x, y), corner(x + 1, y), corner(x, y + 1), corner(x + 1, y + 1)};
  const auto differ = [&](const std::array<const Color*, 4>& c) {
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        if (aaDifference(*c[size_t(a)], *c[size_t(b)]) > aa_.threshold) return true;
      }
    }
    return false;
  };
  const auto mean = [](const Color& a, const Color& b, const Color& c, const Color& d) {
    return (a + b + c + d) / 4.0f;
  };
  if (m == 1 || !differ({&compared_[corners[0]], &compared_[corners[1]], &compared_[corners[2]],
                         &compared_[corners[3]]})) {
    return mean(raw_[corners[0]], raw_[corners[1]], raw_[corners[2]], raw_[corners[3]]);
  }
  std::vector<Color> raw(size_t(side) * size_t(side)), compared(raw.size());
  std::vector<char> known(raw.size(), 0);
  const auto point = [&](int i, int j) { return size_t(j) * size_t(side) + size_t(i); };
  const std::array<size_t, 4> gridCorners{point(0, 0), point(m, 0), point(0, m), point(m, m)};
  for (size_t c = 0; c < 4; ++c) {
    raw[gridCorners[c]] = raw_[corners[c]];
    compared[gridCorners[c]] = compared_[corners[c]];
    known[gridCorners[c]] = 1;
  }
  // A square (i, j, s): its lower-left point and its side, in the finest grid's steps.
  const auto splits = [&](int i, int j, int s) {
    return s > 1 && differ({&compared[point(i, j)], &compared[point(i + s, j)], &compared[point(i, j + s)],
                            &compared[point(i + s, j + s)]});
  };
  std::vector<std::array<int, 3>> level{{0, 0, m}}, next;
  std::vector<Ray<T>> rays;
  std::vector<uint64_t> keys;
  std::vector<size_t> pending;
  while (!level.empty()) {
    rays.clear(), keys.clear(), pending.clear(), next.clear();
    for (const auto& [i, j, s] : level) {
      if (!splits(i, j, s)) continue;
      const int h = s / 2;
      for (const auto& [pi, pj] : {std::array<int, 2>{i + h, j}, {i, j + h}, {i + h, j + h}, {i + s, j + h},
                                   {i + h, j + s}}) {
        if (known[point(pi, pj)]) continue;
        known[point(pi, pj)] = 1;
        pending.push_back(point(pi, pj));
        rays.push_back(gridRay(x, y, pi, pj));
        keys.push_back(gridKey(x, y, pi, pj));
      }
      next.insert(next.end(), {{i, j, h}, {i + h, j, h}, {i, j + h, h}, {i + h, j + h, h}});
    }
    if (!rays.empty()) {
      const Color* colors = tracer.eyeRays(rays.data(), keys.data(), rays.size());
      for (size_t k = 0; k < pending.size(); ++k) {
        raw[pending[k]] = colors[k];
        compared[pending[k]] = aaCompared(tracer.finished(colors[k]));
      }
    }
    level.swap(next);
  }
  const auto value = [&](const auto& self, int i, int j, int s) -> Color {
    if (!splits(i, j, s)) {
      return mean(raw[point(i, j)], raw[point(i + s, j)], raw[point(i, j + s)], raw[point(i + s, j + s)]);
    }
    const int h = s / 2;
    return mean(self(self, i, j, h), self(self, i + h, j, h), self(self, i, j + h, h), self(self, i + h, j + h, h));
  };
  return value(value, 0, 0, m);
}

template class AdaptiveSampler<float>;
template class AdaptiveSampler<double>;

}  // namespace rt
