// The arithmetic chosen at default settings at the edges of each tier's domain (docs/accuracy.md, "Choosing
// the arithmetic"): on the edge-case scenes in scenes/stability/, the default picture is the one
// --precision=double gives, where the course tier's would not be.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "raytrace/accel/scene.hpp"
#include "raytrace/parse/scene_file.hpp"
#include "raytrace/render/camera.hpp"
#include "raytrace/render/renderer.hpp"

namespace rt {
namespace {

std::string edgeCase(const std::string& name) {
  const std::string file = __FILE__;
  return file.substr(0, file.rfind("/tests/")) + "/scenes/stability/" + name;
}

// The objects each eye ray meets first (0: none), as the raycast command finds them, in the given tier.
std::vector<int> coverage(const SceneDesc& desc, int width, int height, Arithmetic requested) {
  const Arithmetic arithmetic = chooseArithmetic(desc, requested, View{width, height});
  return withPrecision(arithmetic.tier, [&](auto tag) {
    using T = decltype(tag);
    const Scene<T> scene(desc, arithmetic);
    const Camera<T> camera(desc.camera, width, height);
    std::vector<int> ids;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const auto hit = scene.closestHit(camera.pixelRay(x, y), {});
        ids.push_back(hit ? hit->object->id() : 0);
      }
    }
    return ids;
  });
}

int differing(const std::vector<int>& a, const std::vector<int>& b) {
  int n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
  return n;
}

// Pixels whose 8-bit colour differs by more than 8 levels in some channel.
int differing(const Rgb8Image& a, const Rgb8Image& b) {
  int n = 0;
  const size_t pixels = size_t(a.width()) * size_t(a.height());
  for (size_t i = 0; i < pixels; ++i) {
    const unsigned char* p = a.data() + 3 * i;
    const unsigned char* q = b.data() + 3 * i;
    n += std::abs(p[0] - q[0]) > 8 || std::abs(p[1] - q[1]) > 8 || std::abs(p[2] - q[2]) > 8;
  }
  return n;
}

Rgb8Image renderIn(const SceneDesc& scene, Arithmetic arithmetic) {
  RenderOptions options;
  options.arithmetic = arithmetic;
  return renderRgb8(scene, 640, 480, options);
}

}  // namespace

// The far sphere: radius 0.1 at 300 units, 2e-5 rad per pixel. The textbook quadratic in float
// would move its outline by 70 pixels' worth (it covered 532 pixels of 812, in stripes).
TEST_CASE("the far small sphere covers the pixels double covers", "[stability][tiers]") {
  const SceneDesc scene = loadScene(edgeCase("edge_far_sphere.pov"));
  CHECK(chooseArithmetic(scene, {}, View{640, 480}).tier != Tier::Course);
  const std::vector<int> chosen = coverage(scene, 640, 480, {});
  const std::vector<int> exact = coverage(scene, 640, 480, {Tier::Double});
  CHECK(std::count(exact.begin(), exact.end(), 1) > 800);
  CHECK(differing(chosen, exact) == 0);
  CHECK(differing(coverage(scene, 640, 480, {Tier::Course}), exact) > 100);  // what the course tier drew
}

// A camera 0.05 over a long plane, with spheres of radius 0.25 to 0.5 out to 400 units: R = 1600.
TEST_CASE("a grazing camera over a long plane sees the spheres double sees", "[stability][tiers]") {
  const SceneDesc scene = loadScene(edgeCase("edge_grazing_camera.pov"));
  CHECK(differing(coverage(scene, 640, 480, {}), coverage(scene, 640, 480, {Tier::Double})) == 0);
  CHECK(differing(renderIn(scene, {}), renderIn(scene, {Tier::Double})) <= 2);
}

// A light 2.4° above the floor beside two low boxes: the floor's shadow rays graze the boxes' top edges, where
// the course's 0.001 offset moves the shadows' far ends (by up to 5.5 pixels, the domain's bound).
TEST_CASE("shadow rays grazing a box edge agree with double", "[stability][tiers]") {
  const SceneDesc scene = loadScene(edgeCase("edge_box_edge_shadow.pov"));
  CHECK(tierDomain(scene, View{640, 480}).offsetShadowPixels > kVisiblePixels);
  const Rgb8Image exact = renderIn(scene, {Tier::Double});
  CHECK(differing(renderIn(scene, {}), exact) <= 2);
  CHECK(differing(renderIn(scene, {Tier::Course}), exact) > 20);  // what the course tier drew
}

// A glass sphere filling the frame in front of stripes: its silhouette refracts at grazing entry.
TEST_CASE("refraction at a glass sphere's silhouette agrees with double", "[stability][tiers]") {
  const SceneDesc scene = loadScene(edgeCase("edge_refraction_silhouette.pov"));
  CHECK(tierDomain(scene, View{640, 480}).offsetRefractionPixels > kVisiblePixels);
  const Rgb8Image exact = renderIn(scene, {Tier::Double});
  CHECK(differing(renderIn(scene, {}), exact) <= 2);
  CHECK(differing(renderIn(scene, {Tier::Course}), exact) > 10);  // what the course tier drew
}

// Spheres touching each other and the floor: the course offset starts shadow rays inside a neighbour.
TEST_CASE("touching spheres are shaded as double shades them", "[stability][tiers]") {
  const SceneDesc scene = loadScene(edgeCase("edge_touching_spheres.pov"));
  CHECK(smallestGap(scene) < 2 * kCourseEpsilon);
  const Rgb8Image exact = renderIn(scene, {Tier::Double});
  CHECK(differing(renderIn(scene, {}), exact) <= 2);
  CHECK(differing(renderIn(scene, {Tier::Course}), exact) > 50);  // what the course tier drew
}

// Pointed cones seen near their apexes: the float answer is the double one.
TEST_CASE("pointed cones near the apex hit where double hits", "[stability][tiers]") {
  const SceneDesc scene = loadScene(edgeCase("edge_cone_apex.pov"));
  CHECK(differing(coverage(scene, 640, 480, {Tier::Float}), coverage(scene, 640, 480, {Tier::Double})) == 0);
}

}  // namespace rt
