// POV-Ray's focal blur (manual, "Focal Blur"): each pixel averages rays from points of the lens through the
// plane of focus, taken until the confidence test holds. Every number is counter-based (render/sampler), so
// a pixel's colour is the same for any threads or tiles.
#include <algorithm>
#include <cmath>

#include "raytrace/render/sampler.hpp"
#include "raytrace/render/tracer.hpp"

namespace rt {

namespace {

// The radical inverse of i in `base` (Halton's sequence): well spread points of the lens and the pixel.
float radicalInverse(uint32_t i, uint32_t base) {
  float inverse = 0, digit = 1.0f / float(base);
  for (; i > 0; i /= base, digit /= float(base)) inverse += float(i % base) * digit;
  return inverse;
}

// z with P(|N(0, 1)| < z) = confidence, by bisection on erf.
double twoSidedQuantile(double confidence) {
  double low = 0, high = 40;
  for (int k = 0; k < 100; ++k) {
    const double mid = (low + high) / 2;
    (std::erf(mid / std::sqrt(2.0)) < confidence ? low : high) = mid;
  }
  return low;
}

float wrapped(float v) { return v - std::floor(v); }

}  // namespace

template <class T> Color Tracer<T>::blurredPixel(const Camera<T>& camera, int x, int y) {
  const CameraDesc::FocalBlur& blur = camera.focalBlur();
  // Stop once the mean is within √variance of the true colour with the given confidence: z²·s²/n < variance
  // in every channel (strictly: variance 0 takes every sample).
  const double z = twoSidedQuantile(std::clamp(blur.confidence, 0.0, 0.999999));
  // One random shift per pixel of the Halton points (Cranley and Patterson's rotation).
  const uint64_t key = pixelKey(options_.gi.seed, x, y, 0);
  const glm::vec2 lensShift = uniformPair(childKey(key, 0)), pixelShift = uniformPair(childKey(key, 1));
  Color sum(0), squares(0);
  int n = 0;
  while (n < blur.maxSamples) {
    const uint32_t k = uint32_t(n) + 1;
    const glm::vec2 lens{wrapped(radicalInverse(k, 2) + lensShift.x), wrapped(radicalInverse(k, 3) + lensShift.y)};
    const glm::vec2 spot{wrapped(radicalInverse(k, 5) + pixelShift.x), wrapped(radicalInverse(k, 7) + pixelShift.y)};
    const Ray<T> pinhole = camera.ray(T(x) + T(spot.x), T(y) + T(spot.y));
    Color c(0);
    if (!(camera.hasBlanks() && camera.blank(pinhole))) {
      Path path;
      path.key = pixelKey(options_.gi.seed, x, y, n);
      ++counts_.eye;
      raysLeft_ = treeRays_ - 1;
      sampleRaysLeft_ = kSampleRays - 1;
      c = trace(camera.throughLens(pinhole, lens), RayRecord::Kind::Primary, path, nullptr).color;
    }
    sum += c;
    squares += c * c;
    ++n;
    if (n < std::max(blur.minSamples, 2)) continue;
    const Color mean = sum / float(n);
    const Color spread = glm::max(squares / float(n) - mean * mean, Color(0)) * (float(n) / float(n - 1));
    const float widest = std::max({spread.r, spread.g, spread.b});
    if (z * z * double(widest) / n < blur.variance) break;
  }
  return finished(sum / float(n));
}

template Color Tracer<float>::blurredPixel(const Camera<float>&, int, int);
template Color Tracer<double>::blurredPixel(const Camera<double>&, int, int);

}  // namespace rt
