#include <cmath>
#include <memory>
#include <optional>

#include <catch2/catch.hpp>

#include "raytrace/render/camera.hpp"
#include "raytrace/render/renderer.hpp"
#include "raytrace/render/scene_setup.hpp"
#include "raytrace/render/tracer.hpp"
#include "raytrace/surface/texture.hpp"

using namespace rt;

namespace {

const Color kLight(0.9f, 0.8f, 0.1f), kDark(0.1f, 0.2f, 0.7f);

Material glowing(const Color& c) {
  Material m;
  m.pigment = c;
  m.ambient = c;
  return m;
}

// Squares of side 2 in x and z, alternating between two ambient-only materials: the least pattern texture.
class Checker final : public Texture {
 public:
  Material at(const glm::dvec3& p) const override {
    const bool odd = (int(std::floor(p.x / 2)) + int(std::floor(p.z / 2))) & 1;
    return glowing(odd ? kDark : kLight);
  }
  Material brightest() const override { return glowing(Color(0.9f, 0.8f, 0.7f)); }
};

// The plane y = 0 under a camera 10 above it looking down; the picture spans x and z from −5 to 5.
SceneDesc checkerFloor() {
  SceneDesc desc;
  desc.camera.location = {0, 10, 0};
  desc.camera.lookAt = {0, 0, 0};
  desc.camera.up = {0, 0, 1};
  desc.camera.right = {1, 0, 0};
  desc.lights.push_back({{0, 20, 0}, Color(1)});
  auto checker = std::make_shared<Checker>();
  ObjectDesc floor;
  floor.shape = PlaneDesc{{0, 1, 0}, 0};
  floor.material.texture = checker.get();
  desc.textures.push_back(checker);
  desc.objects.push_back(floor);
  return desc;
}

}  // namespace

TEST_CASE("a pattern texture is evaluated at every hit, by render and by the one-pixel commands alike", "[texture]") {
  const SceneDesc desc = checkerFloor();
  const int size = 16;  // pixel centres at x = −5 + 0.625·(i + ½): never on a square's edge
  const Image image = render(desc, size, size, RenderOptions{});
  withScene(desc, size, size, RenderOptions{}, [&](const auto& scene, const auto& camera) {
    using T = typename std::decay_t<decltype(scene)>::Real;
    Tracer<T> tracer(scene, RenderOptions{});
    int light = 0, dark = 0;
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const Ray<T> ray = camera.pixelRay(x, y);
        const double t = -double(ray.origin.y) / double(ray.dir.y);
        const glm::dvec3 p = glm::dvec3(ray.origin) + t * glm::dvec3(ray.dir);
        const Color expected = Checker().at(p).ambient;
        INFO("pixel " << x << ", " << y << " sees (" << p.x << ", " << p.z << ")");
        CHECK(image.at(x, y) == expected);
        CHECK(tracer.pixel(camera, x, y) == expected);
        (expected == kLight ? light : dark) += 1;
      }
    }
    CHECK(light == 128);
    CHECK(dark == 128);
    return 0;
  });
}

TEST_CASE("an object without a texture reads its own material at every hit", "[texture]") {
  SceneDesc desc = checkerFloor();
  desc.objects[0].material = glowing(kDark);
  const Scene<float> scene(desc, chooseArithmetic(desc));
  const auto hit = scene.closestHit({{0, 10, 0}, {0, -1, 0}}, {});
  REQUIRE(hit);
  std::optional<Material> scratch;
  CHECK(&hit->object->materialAt(*hit, scratch) == &hit->object->material());
  CHECK_FALSE(scratch);
}
