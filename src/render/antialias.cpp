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
  rows_ = y1 - y0_;
  raw_.resize(size_t(stride_) * size_t(rows_));
  compared_.resize(raw_.size());
  const int blocksX = (stride_ + kBlock - 1) / kBlock, blocksY = (rows_ + kBlock - 1) / kBlock;
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
        // Stored member by member from registers, as Tracer::tile() stores its rays: assigned whole, the ray
        // goes through the stack and each read of it back stalls.
        const Ray<T> ray = aa_.method == 1 ? camera.sampleRay(x, y, 0, 0, 1) : gridRay(x, y, 0, 0);
        rays[n].origin = ray.origin;
        rays[n].dir = ray.dir;
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
}

template <class T>
void AdaptiveSampler<T>::tile(Tracer<T>& tracer, int x0, int y0, int x1, int y1, std::vector<Color>& out) const {
  out.resize(size_t(x1 - x0) * size_t(y1 - y0));
  if (aa_.method == 1) return nonRecursive(tracer, x0, y0, x1, y1, out);
  recursive(tracer, x0, y0, x1, y1, out);
}

// A supersampled pixel is the mean of its own ray and R x R more on a grid over it, each jittered within its
// cell; POV-Ray's counts and colours show the pixel's own ray is kept (R² "additional samples" in the manual).
// Unjittered and without gathering (whose rays hang on the sample's key), an odd grid's middle sample is the
// pixel's own ray exactly, so its colour is reused rather than traced again.
template <class T>
void AdaptiveSampler<T>::nonRecursive(Tracer<T>& tracer, int x0, int y0, int x1, int y1,
                                      std::vector<Color>& out) const {
  const int r = aa_.depth;
  const int middle = r % 2 == 1 && !(aa_.jitter > 0) && !gi_ ? r / 2 * r + r / 2 : -1;
  std::vector<Ray<T>> rays;
  std::vector<uint64_t> keys;
  const auto at = [&](int x, int y) { return size_t(y - y0_) * size_t(stride_) + size_t(x - x0_); };
  // Each tile tests its own pixels against their neighbours, on the threads.
  std::vector<char> refined(out.size());
  size_t p = 0, count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x, ++p) {
      refined[p] = refinedPixel(compared_.data(), stride_, rows_, x - x0_, y - y0_, aa_.threshold);
      count += size_t(refined[p]);
    }
  }
  rays.reserve(count * size_t(r * r));
  keys.reserve(rays.capacity());
  p = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x, ++p) {
      if (!refined[p]) continue;
      for (int i = 0; i < r; ++i) {
        for (int j = 0; j < r; ++j) {
          if (i * r + j == middle) continue;
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
      if (refined[k]) {
        for (int s = 0; s < r * r; ++s) sum += s == middle ? raw_[at(x, y)] : colors[next++];
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

// Each pixel's square, its corners traced: a square whose corners differ by more than the threshold (any two
// of them) is cut into four, down to R − 1 levels, and is the mean of its quarters; else of its corners.
// The tile's pixels are subdivided together, level by level, so that each level's rays go through the scene
// in one batch, and a point on the side two pixels share is traced once for both (POV-Ray traces it for
// each). A point's ray is made from its place on the picture's finest grid alone, so its colour is the same
// whichever pixel or tile asks for it.
template <class T>
void AdaptiveSampler<T>::recursive(Tracer<T>& tracer, int x0, int y0, int x1, int y1, std::vector<Color>& out) const {
  const int m = cells_, shift = aa_.depth - 1, mask = m - 1;  // m = 2^shift: divisions by m are shifts
  const int side = (x1 - x0) * m + 1;  // points a row of the tile's finest grid
  const auto corner = [&](int cx, int cy) { return size_t(cy - y0_) * size_t(stride_) + size_t(cx - x0_); };
  const auto differ = [&](const Color& a, const Color& b, const Color& c, const Color& d) {
    const float t = aa_.threshold;
    return aaDifference(a, b) > t || aaDifference(a, c) > t || aaDifference(a, d) > t || aaDifference(b, c) > t ||
           aaDifference(b, d) > t || aaDifference(c, d) > t;
  };
  // The points traced here, by their place (gx, gy) on the tile's finest grid (raw[index], or −1 before);
  // a pixel's corner is the first pass's.
  std::vector<int> index;
  std::vector<Color> raw, compared;
  const auto at = [&](int gx, int gy, bool isCompared) -> const Color& {
    if (((gx | gy) & mask) == 0) {
      const size_t c = corner(x0 + (gx >> shift), y0 + (gy >> shift));
      return isCompared ? compared_[c] : raw_[c];
    }
    const size_t n = size_t(index[size_t(gy) * size_t(side) + size_t(gx)]);
    return isCompared ? compared[n] : raw[n];
  };
  // A square: its lower-left point on the tile's finest grid and its side, in that grid's steps.
  struct Square {
    int gx, gy, s;
  };
  const auto splits = [&](const Square& q) {
    return q.s > 1 && differ(at(q.gx, q.gy, true), at(q.gx + q.s, q.gy, true), at(q.gx, q.gy + q.s, true),
                             at(q.gx + q.s, q.gy + q.s, true));
  };
  const auto meanOfCorners = [&](const Square& q) {
    return (at(q.gx, q.gy, false) + at(q.gx + q.s, q.gy, false) + at(q.gx, q.gy + q.s, false) +
            at(q.gx + q.s, q.gy + q.s, false)) / 4.0f;
  };
  std::vector<std::pair<Square, size_t>> subdivided;  // each pixel's square cut, and its place in `out`
  size_t k = 0;
  for (int y = y0; y < y1; ++y) {
    // The pixels' squares straight from the first pass: every pixel of the picture pays this test.
    const size_t below = corner(x0, y), above = corner(x0, y + 1);
    for (int x = x0; x < x1; ++x, ++k) {
      const size_t a = below + size_t(x - x0), c = above + size_t(x - x0);
      if (m > 1 && differ(compared_[a], compared_[a + 1], compared_[c], compared_[c + 1])) {
        subdivided.emplace_back(Square{(x - x0) * m, (y - y0) * m, m}, k);
      } else {
        out[k] = tracer.finished((raw_[a] + raw_[a + 1] + raw_[c] + raw_[c + 1]) / 4.0f);
      }
    }
  }
  if (subdivided.empty()) return;
  index.assign(size_t(side) * size_t((y1 - y0) * m + 1), -1);
  std::vector<Square> level, next;
  for (const auto& [q, place] : subdivided) level.push_back(q);
  std::vector<Ray<T>> rays;
  std::vector<uint64_t> keys;
  while (!level.empty()) {
    // The new points are midpoints of this level's squares, never corners of one: each square's test reads
    // points of earlier levels only.
    rays.clear(), keys.clear(), next.clear();
    for (const Square& q : level) {
      if (!splits(q)) continue;
      const int gx = q.gx, gy = q.gy, s = q.s, h = s / 2;
      for (const auto& [px, py] : {std::array<int, 2>{gx + h, gy}, {gx, gy + h}, {gx + h, gy + h}, {gx + s, gy + h},
                                   {gx + h, gy + s}}) {
        int& n = index[size_t(py) * size_t(side) + size_t(px)];
        if (n >= 0) continue;
        n = int(raw.size() + rays.size());
        const int fx = x0 * m + px, fy = y0 * m + py;  // on the picture's finest grid
        rays.push_back(gridRay(fx >> shift, fy >> shift, fx & mask, fy & mask));
        keys.push_back(gi_ ? gridKey(fx >> shift, fy >> shift, fx & mask, fy & mask) : 0);
      }
      next.insert(next.end(), {{gx, gy, h}, {gx + h, gy, h}, {gx, gy + h, h}, {gx + h, gy + h, h}});
    }
    if (!rays.empty()) {
      const Color* colors = tracer.eyeRays(rays.data(), keys.data(), rays.size());
      for (size_t n = 0; n < rays.size(); ++n) {
        raw.push_back(colors[n]);
        compared.push_back(aaCompared(tracer.finished(colors[n])));
      }
    }
    level.swap(next);
  }
  const auto value = [&](const auto& self, const Square& q) -> Color {
    if (!splits(q)) return meanOfCorners(q);
    const int h = q.s / 2;
    return (self(self, Square{q.gx, q.gy, h}) + self(self, Square{q.gx + h, q.gy, h}) +
            self(self, Square{q.gx, q.gy + h, h}) + self(self, Square{q.gx + h, q.gy + h, h})) / 4.0f;
  };
  for (const auto& [q, place] : subdivided) out[place] = tracer.finished(value(value, q));
}

template class AdaptiveSampler<float>;
template class AdaptiveSampler<double>;

}  // namespace rt
