// Test support for -gi: its options, matte materials, a small room lit by one and two bounces, and bit-exact
// image comparison.
#pragma once

#include <cstring>
#include <optional>
#include <vector>

#include "raytrace/image/image.hpp"
#include "raytrace/render/options.hpp"
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

}  // namespace rt::test
