// Test support for -gi: its options, matte materials, a small room lit by one and two bounces, bit-exact
// image comparison, and the picture traced in other orders than render()'s.
#pragma once

#include <algorithm>
#include <cstring>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "raytrace/image/image.hpp"
#include "raytrace/render/camera.hpp"
#include "raytrace/render/options.hpp"
#include "raytrace/render/tracer.hpp"
#include "scene_builder.hpp"

namespace rt::test {

inline Material matte(const Color& ambient, const Color& diffuse) {
  Material m;
  m.pigment = Color(1);
  m.ambient = ambient;
  m.diffuse = diffuse;
  return m;
}

inline RenderOptions gi(std::vector<int> samples, std::optional<int> bounces = {}, uint64_t seed = 0) {
  RenderOptions o;
  o.gi.enabled = true;
  o.gi.samples = std::move(samples);
  o.gi.bounces = bounces;
  o.gi.seed = seed;
  o.threads = 1;
  return o;
}

// A floor, a back wall, two spheres and a light: light reaches most points by one or two bounces.
inline SceneDesc smallRoom() {
  SceneDesc scene;
  scene.camera.location = {0, 1.5, 6};
  scene.camera.lookAt = {0, 1, 0};
  scene.lights.push_back({{2, 5, 3}, Color(1)});
  add(scene, PlaneDesc{{0, 1, 0}, 0}, matte(Color(0.1f), Color(0.7f, 0.3f, 0.2f)));
  add(scene, PlaneDesc{{0, 0, 1}, -2}, matte(Color(0.1f), Color(0.2f, 0.6f, 0.3f)));
  add(scene, SphereDesc{{-0.8, 1, 0}, 1}, matte(Color(0.1f), Color(0.8f)));
  add(scene, SphereDesc{{1.2, 0.5, 0.8}, 0.5}, matte(Color(0.1f), Color(0.3f, 0.3f, 0.9f)));
  return scene;
}

inline bool sameBits(const Image& a, const Image& b) {
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      if (std::memcmp(&a.at(x, y), &b.at(x, y), sizeof(Color)) != 0) return false;
    }
  }
  return true;
}

// The means of an image's `block` × `block`-pixel blocks, per channel: entry (block index · 3 + channel), blocks
// row by row. The image's sides are multiples of `block`.
inline std::vector<double> blockMeans(const Image& image, int block) {
  const int across = image.width() / block;
  std::vector<double> means(size_t(across * (image.height() / block) * 3), 0);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      for (int k = 0; k < 3; ++k) {
        means[size_t(((y / block) * across + x / block) * 3 + k)] += image.at(x, y)[k] / (block * block);
      }
    }
  }
  return means;
}

// The mean and sample variance, entry by entry, of several runs' vectors of one length.
struct Spread {
  std::vector<double> mean, variance;
};
inline Spread spreadOf(const std::vector<std::vector<double>>& runs) {
  const size_t n = runs.front().size();
  const double k = double(runs.size());
  Spread out{std::vector<double>(n, 0), std::vector<double>(n, 0)};
  for (size_t i = 0; i < n; ++i) {
    double sum = 0, squares = 0;
    for (const auto& run : runs) sum += run[i], squares += run[i] * run[i];
    out.mean[i] = sum / k;
    out.variance[i] = std::max(0.0, (squares - k * out.mean[i] * out.mean[i]) / (k - 1));
  }
  return out;
}

// The camera's picture traced by one tracer in tiles of 5 × 4 pixels taken in a shuffled order.
template <class T> Image shuffledTiles(Tracer<T>& tracer, const Camera<T>& camera) {
  const int w = camera.width(), h = camera.height();
  std::vector<std::pair<int, int>> tiles;
  for (int y = 0; y < h; y += 4) {
    for (int x = 0; x < w; x += 5) tiles.emplace_back(x, y);
  }
  std::shuffle(tiles.begin(), tiles.end(), std::mt19937(12345));
  Image image(w, h);
  for (const auto& [x0, y0] : tiles) {
    const int x1 = std::min(w, x0 + 5), y1 = std::min(h, y0 + 4);
    const Color* colors = tracer.tile(camera, x0, y0, x1, y1);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) image.at(x, y) = *colors++;
    }
  }
  return image;
}

// The camera's picture traced pixel by pixel, as pixelcolor traces one.
template <class T> Image pixelByPixel(Tracer<T>& tracer, const Camera<T>& camera) {
  Image image(camera.width(), camera.height());
  for (int y = 0; y < camera.height(); ++y) {
    for (int x = 0; x < camera.width(); ++x) image.at(x, y) = tracer.pixel(camera, x, y);
  }
  return image;
}

}  // namespace rt::test
