#include <cmath>
#include <optional>
#include <sstream>

#include <catch2/catch.hpp>

#include "raytrace/app/commands.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/image/image.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/parse/scene_file.hpp"
#include "raytrace/render/renderer.hpp"
#include "raytrace/render/tracer.hpp"
#include "same_on_any_threads.hpp"
#include "scene_builder.hpp"

using namespace rt;
using Catch::Matchers::WithinAbs;

using rt::test::add;

namespace {

// The scene's source folder, found from this file's path so the tests run from any folder.
std::string sourceDir() {
  const std::string file = __FILE__;
  return file.substr(0, file.rfind("/tests/"));
}

// A camera at the origin looking down −z; a 1×1 image's only eye ray is exactly (0, 0, −1).
SceneDesc emptyScene() {
  SceneDesc scene;
  scene.camera.right = {1, 0, 0};
  return scene;
}

// A POV-style material: per-term colours are the finish coefficients times the pigment (§c.1).
Material pov(const Color& c, float ka, float kd, float ks = 0, float roughness = 1, float reflection = 0) {
  Material m;
  m.pigment = c;
  m.ambient = ka * c;
  m.diffuse = kd * c;
  m.specular = ks * c;
  m.roughness = roughness;
  m.exponent = 2 / (roughness * roughness) - 2;
  m.reflection = reflection;
  return m;
}

// A POV-Ray scene of one pixel.
SceneDesc onePixel(const std::string& text) {
  return rt::povray::parsePovRay(text, "scene.pov", rt::povray::PovRayOptions{{}, 1, 1, false});
}

Color centre(const SceneDesc& scene, const RenderOptions& options = {}) {
  return render(scene, 1, 1, options).at(0, 0);
}

void checkColor(const Color& actual, const Color& expected, double tolerance = 1e-5) {
  CAPTURE(actual.r, actual.g, actual.b, expected.r, expected.g, expected.b);
  for (int k = 0; k < 3; ++k) CHECK_THAT(actual[k], WithinAbs(expected[k], tolerance));
}

bool allFinite(const Image& image) {
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const Color& c = image.at(x, y);
      if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) return false;
    }
  }
  return true;
}

const Color kPigment(1.0f, 0.5f, 0.25f);

// A sphere whose nearest point (0, 0, −4) faces the camera, lit from (0, 4, 0): N·L = cos 45°, and the half
// vector is 22.5° off the normal, so Blinn-Phong with roughness 0.5 (p = 6) gives cos(22.5°)^6.
SceneDesc litSphere() {
  SceneDesc scene = emptyScene();
  scene.lights.push_back({{0, 4, 0}, Color(1)});
  add(scene, SphereDesc{{0, 0, -5}, 1}, pov(kPigment, 0.1f, 0.6f, 0.5f, 0.5f));
  return scene;
}
const float kDirect = 0.6f * std::cos(float(M_PI) / 4) + 0.5f * std::pow(std::cos(float(M_PI) / 8), 6.0f);

}  // namespace

TEST_CASE("Blinn-Phong: ambient once, diffuse and specular per light, tinted by the pigment", "[render]") {
  SceneDesc scene = litSphere();
  checkColor(centre(scene), kPigment * (0.1f + kDirect));
  // A second, mirror-image light adds its own diffuse and specular but no second ambient.
  scene.lights.push_back({{0, -4, 0}, Color(1)});
  checkColor(centre(scene), kPigment * (0.1f + 2 * kDirect));
}

TEST_CASE("A light hidden by another object leaves only the ambient term", "[render]") {
  SceneDesc scene = litSphere();
  add(scene, SphereDesc{{0, 2, -2}, 0.5}, pov(Color(1), 0, 0));  // on the segment to the light, off the eye ray
  checkColor(centre(scene), kPigment * 0.1f);
  // A light behind the surface does not light it either.
  scene.lights = {{{0, 0, -10}, Color(1)}};
  checkColor(centre(scene), kPigment * 0.1f);
}

TEST_CASE("Cook-Torrance replaces the specular term under -altbrdf", "[render]") {
  SceneDesc scene = emptyScene();
  scene.lights.push_back({{0, 0, 0}, Color(1)});  // at the eye: n = v = l
  Material m = pov(kPigment, 0, 0, 1, 0.5f);
  m.ior = 1.5f;
  add(scene, SphereDesc{{0, 0, -5}, 1}, m);
  RenderOptions options;
  options.brdf = Brdf::CookTorrance;
  // D·G·F / (4 n·v) at normal incidence = F0 / (4π α²) with α = 0.25, F0 = 0.04.
  checkColor(centre(scene, options), kPigment * float(0.04 / (4 * M_PI * 0.0625)));
}

TEST_CASE("A mirror mixes in the tinted reflection, or adds it untinted in the .cli dialect", "[render]") {
  SceneDesc scene = emptyScene();
  scene.background = Color(0.2f, 0.4f, 0.6f);
  // The plane z = −5 faces the camera; its reflection goes back past the eye into the background.
  add(scene, PlaneDesc{{0, 0, 1}, -5}, pov(kPigment, 0.2f, 0, 0, 1, 0.5f));
  const Color b = scene.background;
  checkColor(centre(scene), 0.5f * 0.2f * kPigment + 0.5f * kPigment * b);  // §c.3, §c.5
  scene.dialect = Dialect::cs3451();
  checkColor(centre(scene), 0.2f * kPigment + 0.5f * b);  // cs3451 §A.4.5
}

TEST_CASE("Clamping each bounce keeps every returned colour within [0, 1]", "[render]") {
  SceneDesc scene = emptyScene();
  add(scene, SphereDesc{{0, 0, -5}, 1}, pov(Color(1), 3, 0));
  CHECK(centre(scene).r == 3.0f);
  scene.dialect = Dialect::cs3451();
  CHECK(centre(scene).r == 1.0f);
}

// Two facing mirrors of reflection ½ and ambient `ambient`: in the course's dialect each level adds
// ½·(½)^depth for ambient 1, so the pixel shows how many levels were shaded.
SceneDesc mirrorHall(float ambient = 1) {
  SceneDesc scene = emptyScene();
  add(scene, PlaneDesc{{0, 0, 1}, -5}, pov(Color(1), ambient, 0, 0, 1, 0.5f));
  add(scene, PlaneDesc{{0, 0, -1}, -5}, pov(Color(1), ambient, 0, 0, 1, 0.5f));
  return scene;
}

TEST_CASE("Recursion stops after the primary ray and maxDepth secondary rays", "[render]") {
  SceneDesc scene = mirrorHall();
  // Course: primary + 5 secondary, all shaded; the deepest one spawns nothing (§c.9).
  CHECK(centre(scene).r == 1.0f - std::ldexp(1.0f, -6));
  scene.depthLimit = 2;
  CHECK(centre(scene).r == 1.0f - std::ldexp(1.0f, -3));
  // .cli: the deepest ray that hits returns black, and each level adds ½ of the one below to its ambient ½:
  // ½ + ½·(½ + ½·0), where shading the deepest would give ½ + ½·(½ + ½·½).
  SceneDesc cli = mirrorHall(0.5f);
  cli.dialect = Dialect::cs3451();
  cli.depthLimit = 2;
  CHECK(centre(cli).r == 0.75f);
}

TEST_CASE("The recorded ray tree is the traced one: one chain of maxDepth reflections", "[render]") {
  const SceneDesc desc = mirrorHall();
  const Scene<float> scene(desc, chooseArithmetic(desc));
  const Camera<float> camera(desc.camera, 1, 1);
  Tracer<float> tracer(scene, RenderOptions{});
  std::vector<RayRecord> trees;
  const Color color = tracer.pixel(camera, 0, 0, &trees);
  REQUIRE(trees.size() == 1);
  CHECK(trees[0].color == color);
  int depth = 0;
  const RayRecord* node = &trees[0];
  while (!node->children.empty()) {
    REQUIRE(node->children.size() == 1);
    node = &node->children[0];
    CHECK(node->kind == RayRecord::Kind::Reflection);
    ++depth;
  }
  CHECK(depth == desc.maxDepth());
  CHECK(node->hit);
  CHECK(node->reflection == Color(0));  // its reflection was not traced
}

TEST_CASE("Supersampling averages stratified sub-pixel rays in float", "[render]") {
  SceneDesc scene = emptyScene();
  // A triangle covering exactly the left half of the view (its right edge is the plane x = 0).
  add(scene, TriangleDesc{{0, -100, -5}, {0, 100, -5}, {-100, 0, -5}}, pov(Color(1), 0.6f, 0));
  RenderOptions options;
  options.samples = 2;
  checkColor(centre(scene, options), Color(0.3f));
  options.samples = 4;
  checkColor(centre(scene, options), Color(0.3f));
}

TEST_CASE("The normals debug view colours a hit by its outward normal", "[render]") {
  RenderOptions options;
  options.normals = true;
  checkColor(centre(litSphere(), options), Color(0.5f, 0.5f, 1.0f));
}

TEST_CASE("Rendered images are finite whatever the flags and materials", "[render]") {
  RenderOptions flags;
  const auto each = [&](const SceneDesc& scene) {
    for (const Brdf brdf : {Brdf::BlinnPhong, Brdf::CookTorrance}) {
      for (const bool fresnel : {false, true}) {
        for (const bool beers : {false, true}) {
          for (const OffsetPolicy offset : {OffsetPolicy::Relative, OffsetPolicy::Course}) {
            flags.brdf = brdf;
            flags.fresnel = fresnel;
            flags.beers = beers;
            flags.arithmetic.offset = offset;
            CAPTURE(int(brdf), fresnel, beers, int(offset));
            CHECK(allFinite(render(scene, 40, 30, flags)));
          }
        }
      }
    }
  };
  SECTION("our test scenes") {
    for (const char* file : {"/scenes/glass_mirror.pov", "/scenes/under_glass.pov"}) {
      CAPTURE(file);
      each(loadScene(sourceDir() + file));
    }
  }
  SECTION("hostile materials: negative exponent, tiny ior, pigment above 1, light on a surface") {
    SceneDesc scene = emptyScene();
    scene.lights.push_back({{0, 0, -4}, Color(2)});
    Material odd = pov(Color(1.5f, 0, 1), 0.1f, 0.9f, 0.9f, 5.0f, 0.3f);
    odd.filter = 0.7f;
    odd.ior = 0.01f;
    add(scene, SphereDesc{{0, 0, -5}, 1}, odd);
    Material rough = pov(Color(0.5f), 0.1f, 0.5f, 1, 0.001f);
    rough.filter = 1;
    rough.ior = 40;
    add(scene, TriangleDesc{{-3, -1, -3}, {3, -1, -3}, {0, 3, -8}}, rough);
    add(scene, TriangleDesc{{0, 0, -6}, {1, 1, -6}, {2, 2, -6}}, odd);  // degenerate
    add(scene, PlaneDesc{{0, 1, 0}, -1}, odd);
    each(scene);
  }
}

TEST_CASE("A rendered pixel is the colour pixel() reports for it: packets change nothing", "[render]") {
  // pixel() traces one ray at a time, as printrays and pixelcolor do; render() goes through Tracer::block's
  // packets and shadow cache. Scenes with and without a hierarchy, several lights, mirrors and glass.
  for (const char* file : {"/scenes/glass_mirror.pov", "/scenes/shapes.pov", "/scenes/stability/s3_glass_mirrors.pov",
                           "/scenes/default.pov", "/scenes/stability/s1_grazing.pov"}) {
    const SceneDesc scene = loadScene(sourceDir() + file);
    for (const int samples : {1, 2}) {
      for (const Hierarchy hierarchy : {Hierarchy::Always, Hierarchy::Never}) {
        CAPTURE(file, samples, int(hierarchy));
        RenderOptions options;
        options.samples = samples;
        options.fresnel = samples == 2;
        options.hierarchy = hierarchy;
        const Image image = render(scene, 37, 23, options);
        const Arithmetic arithmetic = chooseArithmetic(scene, options.arithmetic);
        withPrecision(arithmetic.tier, [&](auto tag) {
          using T = decltype(tag);
          const Scene<T> s(scene, arithmetic, hierarchy);
          const Camera<T> camera(scene.camera, 37, 23);
          Tracer<T> tracer(s, options);
          for (int y = 0; y < 23; ++y) {
            for (int x = 0; x < 37; ++x) {
              CAPTURE(x, y);
              REQUIRE(image.at(x, y) == tracer.pixel(camera, x, y));
            }
          }
        });
      }
    }
  }
}

TEST_CASE("renderRgb8 holds the bytes of render()'s colours, on any number of threads", "[render]") {
  // The .cli scene truncates where the course rounds: each keeps its own convention.
  for (const char* file : {"/scenes/glass_mirror.pov", "/scenes/pillars.cli"}) {
    const SceneDesc scene = loadScene(sourceDir() + file);
    RenderOptions options;
    options.samples = 2;
    options.threads = 1;
    const Image colours = render(scene, 45, 37, options);  // sizes that do not divide into tiles
    for (const int threads : {1, 3}) {
      CAPTURE(file, threads);
      options.threads = threads;
      Rgb8Image bytes = renderRgb8(scene, 45, 37, options);
      for (int y = 0; y < 37; ++y) {
        for (int x = 0; x < 45; ++x) {
          for (int c = 0; c < 3; ++c) {
            REQUIRE(bytes.at(x, y)[c] == toByte(colours.at(x, y)[c], scene.dialect.toByte()));
          }
        }
      }
    }
  }
}

// A white plane under a linear area light of `points` points along x, 10 above, half hidden by a wall at
// height 5 over x < 0; an orthographic camera looks straight down at `spot` on the plane.
SceneDesc wallScene(const std::string& light, double spot) {
  const std::string text = "#version 3.7;\n"
      "camera { orthographic location <" + std::to_string(spot) + ", 20, 0> sky z look_at <" + std::to_string(spot) +
      ", 0, 0> right 0.001*x up 0.001*z }\n"
      "light_source { <0, 10, 0> rgb 1 " + light + " }\n"
      "box { <-100, 4.9, -100>, <0, 5, 100> pigment { rgb 1 } }\n"
      "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
  return onePixel(text);
}

TEST_CASE("An area light lights a point by the share of its grid the point sees", "[render]") {
  // At x = 0.5 the wall hides the light's point at x = −1 only: POV-Ray's share for 3 points is 0.75, lit from
  // the centre (n·l = 10/√100.25).
  const double nl = 10 / std::sqrt(100.25);
  checkColor(centre(wallScene("area_light 2*x, 0*z, 3, 1", 0.5)), Color(float(0.75 * nl)), 1e-5);
  // Six points, three of them hidden at x = 0.1: POV-Ray's share 0.5 (l = (−0.1, 10, 0)).
  checkColor(centre(wallScene("area_light 2*x, 0*z, 6, 1", 0.1)), Color(float(0.5 * 10 / std::sqrt(100.01))), 1e-5);
  // A parallel light straight down lights x = 0.5 with n·l = 1, where a point light 10 above x = 0 clears
  // the wall. Aimed 1 down for 2 across, from (−39.5, 20) through (−19.5, 10), its rays to x = 0.5 run under the
  // wall; from (0, 10) through (20, 0), they end at the plane through the light, below the wall.
  checkColor(centre(wallScene("parallel point_at <0, 0, 0>", 0.5)), Color(1), 1e-5);
  checkColor(centre(wallScene("", 0.5)), Color(float(10 / std::sqrt(100.25))), 1e-5);
  checkColor(centre(wallScene("parallel point_at <20, 0, 0> translate <-39.5, 10, 0>", 0.5)), Color(0), 1e-5);
  checkColor(centre(wallScene("parallel point_at <20, 0, 0>", 0.5)), Color(float(1 / std::sqrt(5))), 1e-5);
}

TEST_CASE("area_illumination lights a point from each grid point's own direction, times the grid's share",
          "[render]") {
  // Two points, at x = -1 and x = 1, 10 above: each lights as a point light of half the colour, n·l from its
  // own direction, and the share of the grid the point sees (the shadow) scales the sum, as POV-Ray's
  // pictures show. At x = 5 both are seen; at x = 0.5 the wall hides the one at x = -1.
  const auto nl = [](double dx) { return 10 / std::sqrt(dx * dx + 100); };
  checkColor(centre(wallScene("area_light 2*x, 0*z, 2, 1 area_illumination", 5)),
             Color(float((nl(6) + nl(4)) / 2)), 1e-5);
  checkColor(centre(wallScene("area_light 2*x, 0*z, 2, 1 area_illumination on", 0.5)),
             Color(float(0.5 * (nl(1.5) + nl(0.5)) / 2)), 1e-5);
  // Off, the centre lights: n·l from x = 0.
  checkColor(centre(wallScene("area_light 2*x, 0*z, 2, 1 area_illumination off", 5)), Color(float(nl(5))), 1e-5);
}

TEST_CASE("A colour reflection tints what the surface reflects, channel by channel", "[render]") {
  // A mirror facing the camera reflects the background behind it: POV-Ray's picture of this scene is the
  // background times the reflection's colour, (0.4·0.5, 0.8·0.25, 1·0.1).
  const std::string text = "#version 3.7;\n"
      "camera { orthographic location <0, 0, -5> look_at 0 right 0.001*x up 0.001*y }\n"
      "background { rgb <0.4, 0.8, 1> }\n"
      "plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0 reflection rgb <0.5, 0.25, 0.1> } }\n";
  checkColor(centre(onePixel(text)),
             Color(0.2f, 0.2f, 0.1f), 1e-6);
}

TEST_CASE("Total internal reflection reflects whole, whatever reflection, filter and transmit", "[render]") {
  // Inside a hollow glass half-space, looking up at a grazing angle: the ray cannot leave and is reflected to a
  // floor of ambient 0.25. POV-Ray's linear values: (1 − f − t)·C·ambient + 0.25 whatever the reflection:
  // 0.25 for filter 0.9 and reflection 0.7 (not 0.9 + 0.7 of it), 0.65 for rgb 0.5 filter 0.2 reflection 0.3.
  const auto seen = [](const std::string& surface) {
    const std::string text = "#version 3.7;\n"
        "camera { orthographic location 0 direction <0, 0.2, 1> right 0.001*x up 0.001*y }\n"
        "plane { y, -1 pigment { rgb 1 } finish { ambient 0.25 diffuse 0 } }\n"
        "plane { y, 1 hollow on " + surface + " interior { ior 1.5 } }\n";
    return centre(onePixel(text));
  };
  checkColor(seen("pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 reflection 0.7 }"), Color(0.25f));
  checkColor(seen("pigment { rgbf <0.5, 0.5, 0.5, 0.2> } finish { ambient 1 diffuse 0 reflection 0.3 }"),
             Color(0.65f));
  checkColor(seen("pigment { rgbft <0.5, 0.5, 0.5, 0.3, 0.2> } finish { ambient 1 diffuse 0 reflection 0.3 }"),
             Color(0.5f));
  // An opaque surface has nothing to reflect internally: its reflection alone, 0.5·0.5 + 0.3·0.25.
  checkColor(seen("pigment { rgb 0.5 } finish { ambient 1 diffuse 0 reflection 0.3 }"), Color(0.575f));
}

TEST_CASE("A mirror whose normal a texture bends into the surface reflects out of it, as POV-Ray does", "[render]") {
  // A grazing view of a mirror plane, its normal bent by `gradient z`, under a sky coloured by direction
  // (green 0.5 + 0.5·y). POV-Ray's linear greens: 0.5167 bent by −0.5 (d reflected about the bent normal would go
  // down at y = −0.0335: mirrored up), 0.5498 bent by −1 (the bent normal faces away: d reflected about y).
  const auto seen = [](const std::string& bend) {
    const std::string text = "#version 3.7;\n"
        "#declare Bend = " + bend + ";\n"
        "camera { orthographic location <0, 1, -10> look_at 0 right 0.001*x up 0.001*y }\n"
        "sky_sphere { pigment { function { 0.5 + 0.5*y } color_map { [0 rgb 0] [1 rgb <0, 1, 0>] } } }\n"
        "plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 }\n"
        "  normal { gradient z Bend scale 100 translate -50*z } }\n";
    return centre(onePixel(text));
  };
  CHECK_THAT(seen("-0.5").g, Catch::Matchers::WithinAbs(0.5167, 2e-4));
  CHECK_THAT(seen("-1").g, Catch::Matchers::WithinAbs(0.5498, 2e-4));
  CHECK_THAT(seen("1").g, Catch::Matchers::WithinAbs(0.6784, 2e-4));
}

TEST_CASE("A filter or transmit outside [0, 1] is drawn as written, in eye rays and in shadows", "[render]") {
  // POV-Ray's `transmit 100` trick: the surface adds (1 − t)·ambient·C and t times what is behind, whatever t.
  const auto seen = [](const std::string& pigment) {
    const std::string text = "#version 3.7;\n"
        "camera { orthographic location <0, 0, -5> look_at 0 right 0.001*x up 0.001*y }\n"
        "background { rgb 0.3 }\n"
        "plane { z, 0 pigment { " + pigment + " } finish { ambient 1 diffuse 0 } }\n";
    return centre(onePixel(text));
  };
  checkColor(seen("rgb 0.5 transmit 2"), Color(-1 * 0.5f + 2 * 0.3f));
  checkColor(seen("rgb 0.5 transmit -1"), Color(2 * 0.5f - 0.3f));
  checkColor(seen("rgb 0.5 filter -1"), Color(2 * 0.5f - 0.5f * 0.3f));
  // A light straight above a white plane, through an unseen sheet (one crossing) or box (two) of transmit −1.
  const auto lit = [](const std::string& shape) {
    const std::string text = "#version 3.7;\n"
        "camera { orthographic location <0, 5, 0> look_at 0 right 0.001*x up 0.001*z }\n"
        "light_source { <0, 10, 0> rgb 1 }\n"
        "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n" +
        shape + " pigment { rgb 0.5 transmit -1 } no_image }\n";
    return centre(onePixel(text));
  };
  checkColor(lit("disc { 2*y, y, 1"), Color(-1));
  checkColor(lit("box { <-1, 2, -1>, <1, 3, 1>"), Color(1));
}

TEST_CASE("area_illumination: pixels of a sphere, a box and a plane under a 5x5 light, as POV-Ray draws them",
          "[render]") {
  // The pixels' bytes from `povray +W40 +H30 -A` of this scene, kept as data. The sphere's lower side, where the
  // light's centre is below the horizon, is lit by the grid points above it alone (black without
  // area_illumination).
  const std::string text = R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -8> look_at <0, 0, 0> angle 50 }
light_source { <0, 3, 0> rgb 1 area_light <6, 0, 0>, <0, 0, 6>, 5, 5 area_illumination on }
plane { y, 0 pigment { rgb 0.8 } finish { diffuse 1 ambient 0 } }
box { <-0.5, 0, -0.5>, <0.5, 1.5, 0.5> translate <2.5, 0, 1> pigment { rgb <1, 0.3, 0.2> }
      finish { diffuse 0.8 specular 0.6 roughness 0.02 ambient 0 } }
sphere { <-1.5, 1, -0.5>, 1 pigment { rgb <0.2, 0.5, 1> } finish { diffuse 0.7 phong 0.8 phong_size 40 ambient 0 } }
)";
  const SceneDesc scene = povray::parsePovRay(text, "lit.pov", povray::PovRayOptions{{}, 40, 30, false});
  Rgb8Image image = renderRgb8(scene, 40, 30, {});
  struct Pixel {
    int x, y;  // y counted from the top, as in the PNG
    glm::ivec3 rgb;
  };
  const Pixel povray[] = {{14, 8, {84, 119, 159}}, {10, 11, {41, 57, 76}}, {14, 14, {29, 49, 70}},
                          {11, 18, {90, 90, 90}},  {28, 12, {102, 56, 45}}, {20, 25, {176, 176, 176}}};
  for (const Pixel& p : povray) {
    const unsigned char* rgb = image.at(p.x, 29 - p.y);
    INFO("pixel " << p.x << ", " << p.y);
    for (int c = 0; c < 3; ++c) CHECK(std::abs(int(rgb[c]) - p.rgb[c]) <= 2);
  }
}

TEST_CASE("projected_through: a light reaches the floor only through its window, shadowed only below it",
          "[render]") {
  // The pixels' bytes from `povray +W40 +H30 -A` of this scene, kept as data: the floor is lit in the disc the
  // window sphere projects (250), dimly elsewhere by the shadowless light (104); the box above the window casts
  // no shadow, the small sphere below it does (111).
  const std::string text = R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 8, -6> look_at <0, 0, 0> angle 50 }
#declare Window = sphere { <0, 3, 0>, 1 };
light_source { <0, 6, 0> rgb 1 projected_through { Window } }
light_source { <0, 6, 0> rgb 0.2 shadowless }
plane { y, 0 pigment { rgb 0.8 } finish { diffuse 1 ambient 0 } }
box { <-0.3, 4.5, -0.3>, <0.3, 4.7, 0.3> pigment { rgb <1, 0.3, 0.2> } finish { ambient 0 } }
sphere { <0.8, 0.8, 0>, 0.3 pigment { rgb <0.2, 0.5, 1> } finish { ambient 0 } }
)";
  const SceneDesc scene = povray::parsePovRay(text, "window.pov", povray::PovRayOptions{{}, 40, 30, false});
  Rgb8Image image = renderRgb8(scene, 40, 30, {});
  struct Pixel {
    int x, y;  // y counted from the top, as in the PNG
    int grey;
  };
  const Pixel povray[] = {{20, 15, 250}, {4, 15, 104}, {24, 15, 111}, {24, 14, 111}, {22, 13, 0}, {20, 4, 103}};
  for (const Pixel& p : povray) {
    const unsigned char* rgb = image.at(p.x, 29 - p.y);
    INFO("pixel " << p.x << ", " << p.y);
    for (int c = 0; c < 3; ++c) CHECK(std::abs(int(rgb[c]) - p.grey) <= 2);
  }
}

TEST_CASE("crand lowers each point's diffuse light by crand·u·C·light, 0 ≤ u < 1, whatever n·l", "[render]") {
  // A wall of pigment 0.8 lit at n·l = 1 by a light of 0.5: ambient 0.08 + diffuse 0.5·0.5·0.8 = 0.28, less up
  // to 0.4·0.5·0.8 = 0.16 (POV-Ray's picture: 0.1195 to 0.2789).
  const std::string text = "#version 3.7;\n"
      "camera { orthographic location <0, 0, -10> look_at 0 right 4*x up 4*y }\n"
      "light_source { <0, 0, -1e6> rgb 0.5 }\n"
      "plane { -z, 0 pigment { rgb 0.8 } finish { ambient 0.1 diffuse 0.5 crand 0.4 } }\n";
  const SceneDesc scene = rt::povray::parsePovRay(text, "crand.pov", rt::povray::PovRayOptions{{}, 32, 32, false});
  const Image image = render(scene, 32, 32, {});
  float low = 1, high = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      low = std::min(low, image.at(x, y).r);
      high = std::max(high, image.at(x, y).r);
    }
  }
  CHECK(low >= 0.12f - 1e-5f);
  CHECK(high <= 0.28f + 1e-5f);
  CHECK(low < 0.13f);   // 1024 points: some u near 1, some near 0
  CHECK(high > 0.27f);
}

TEST_CASE("A shadowless light gives diffuse light but no highlight, from a point or an area light", "[render]") {
  // A wall facing the camera and the light head on: n·l = 1 and the highlight at its peak. Diffuse alone is
  // 0.6·0.5 = 0.3; with the highlight (phong 0.5) it is 0.3 + 0.5 = 0.8. POV-Ray's manual ("Shadowless
  // Lights"): such a light causes no highlights.
  const auto wall = [](const std::string& light) {
    const std::string text = "#version 3.7;\n"
        "camera { orthographic location <0, 0, -10> look_at 0 right 4*x up 4*y }\n"
        "light_source { <0, 0, -1e6> rgb 1 " + light + " }\n"
        "plane { -z, 0 pigment { rgb 0.5 } finish { ambient 0 diffuse 0.6 phong 0.5 phong_size 1 } }\n";
    return centre(onePixel(text));
  };
  checkColor(wall(""), Color(0.8f));
  checkColor(wall("shadowless"), Color(0.3f));
  checkColor(wall("shadowless area_light 2*x, 2*y, 2, 2 area_illumination"), Color(0.3f));
}

TEST_CASE("double_illuminate: a light behind the surface lights it as if it were in front, without a highlight",
          "[render]") {
  // A wall facing the camera, lit only from behind: kd·C·|n·l| = 0.6·0.5·|n·l| with double_illuminate, as
  // POV-Ray's pictures show (0.3 head on, 0.287 at n·l = 1/√1.09); the mirrored view points away from the light,
  // so phong adds nothing. Without it, or with `double_illuminate off`, the wall is dark.
  const auto wall = [](const std::string& light, const std::string& modifier) {
    const std::string text = "#version 3.7;\n"
        "camera { orthographic location <0, 0, -10> look_at 0 right 4*x up 4*y }\n"
        "light_source { " + light + " rgb 1 }\n"
        "plane { -z, 0 pigment { rgb 0.5 } finish { ambient 0 diffuse 0.6 phong 0.5 phong_size 1 } " + modifier + " }\n";
    return centre(onePixel(text));
  };
  checkColor(wall("<0, 0, 1e6>", "double_illuminate"), Color(0.3f));
  checkColor(wall("<0, 3e5, 1e6>", "double_illuminate"), Color(float(0.3 / std::sqrt(1.09))));
  checkColor(wall("<0, 0, 1e6>", ""), Color(0));
  checkColor(wall("<0, 0, 1e6>", "double_illuminate off"), Color(0));
  // A light in front lights it once, as without the modifier.
  checkColor(wall("<0, 0, -1e6>", "double_illuminate"), wall("<0, 0, -1e6>", ""));
}

TEST_CASE("A jittered area light gives the same picture on any threads, and pixel() agrees", "[render]") {
  const std::string text = "#version 3.7;\n"
      "camera { location <0, 3, -4> look_at 0 }\n"
      "light_source { <2, 6, -2> rgb 1 area_light 2*x, 2*z, 5, 5 adaptive 1 jitter circular orient }\n"
      "sphere { <0, 0.7, 0>, 0.7 pigment { rgb <1, 0.5, 0.2> } }\n"
      "plane { y, 0 pigment { rgb 1 } }\n";
  const SceneDesc scene = rt::povray::parsePovRay(text, "jitter.pov", rt::povray::PovRayOptions{{}, 45, 37, false});
  test::checkSameOnAnyThreads(scene, 45, 37, RenderOptions{});
}

TEST_CASE("Bad shading flags are reported with the accepted values", "[render]") {
  const auto error = [](std::vector<std::string> args) -> std::string {
    std::ostringstream out, err;
    try {
      runCommand(args, out, err);
    } catch (const Error& e) {
      return e.what();
    }
    return "no error";
  };
  CHECK(error({"render", "scene.pov", "4", "4", "-ss=0"}) == "-ss must be between 1 and 64, found 0");
  CHECK(error({"render", "scene.pov", "4", "4", "-ss=x"}) == "-ss must be a whole number, found 'x'");
  CHECK(error({"printrays", "scene.pov", "4", "4", "0", "0", "--offset=epsilon"}) ==
        "--offset must be relative, course, normal or wb, found 'epsilon'");
  CHECK(error({"render", "scene.pov", "4", "4", "--depth=-1"}) == "--depth must be between 0 and 64, found -1");
  CHECK(error({"pixelcolor", "scene.pov", "4", "4", "0", "0", "-altbrdff"}) ==
        "unknown option '-altbrdff': did you mean '-altbrdf'? (see raytrace --help)");
}

namespace {

size_t raysIn(const RayRecord& tree) {
  size_t n = 1;
  for (const RayRecord& child : tree.children) n += raysIn(child);
  return n;
}

}  // namespace

// A glass sphere inside a mirror sphere (scenes/depth_bomb.pov) at the highest depth accepted: a full tree
// would have 2^65 rays and took minutes a pixel. Up to depth kFullTreeDepth every ray that can change the pixel
// is traced; deeper, an eye ray's tree stops at 2^13 − 1 rays, as the guarantee of the cutoff allows.
TEST_CASE("The depth bomb at --depth=64: an eye ray's tree stays within 8191 rays", "[render]") {
  const SceneDesc desc = loadScene(sourceDir() + "/scenes/depth_bomb.pov");
  const Scene<double> scene(desc, chooseArithmetic(desc));
  const Camera<double> camera(desc.camera, 40, 30);
  const auto rays = [&](int depth) {
    RenderOptions options;
    options.depth = depth;
    Tracer<double> tracer(scene, options);
    std::vector<RayRecord> trees;
    tracer.pixel(camera, 20, 15, &trees);
    REQUIRE(trees.size() == 1);
    return raysIn(trees[0]);
  };
  CHECK(kFullTreeDepth == 12);
  CHECK(rays(64) == 8191);
  CHECK(rays(40) == 8191);
  // Up to that depth the tree is what the cutoff leaves, far below the budget.
  CHECK(rays(12) == 528);
  CHECK(rays(8) == 116);
}

TEST_CASE("A scene's adc_bailout: a ray is traced while its weight alone reaches it, as POV-Ray decides",
          "[render]") {
  SceneDesc desc = loadScene(sourceDir() + "/scenes/depth_bomb.pov");
  const Camera<double> camera(desc.camera, 40, 30);
  const auto rays = [&](float bailout) {
    desc.adcBailout = bailout;
    const Scene<double> scene(desc, chooseArithmetic(desc));
    RenderOptions options;
    options.depth = 12;
    Tracer<double> tracer(scene, options);
    std::vector<RayRecord> trees;
    tracer.pixel(camera, 20, 15, &trees);
    REQUIRE(trees.size() == 1);
    return raysIn(trees[0]);
  };
  // 98 rays at POV-Ray's default, where the exact cutoff keeps 528 (the test above); the eye ray alone once no
  // secondary ray weighs enough.
  CHECK(rays(1.0f / 255) == 98);
  CHECK(rays(2.0f) == 1);
}

// Issue 35: with -gi every gathered ray had a tree of its own and gathered again, so one eye sample of the
// depth bomb cost billions of rays (minutes a pixel at --depth=64, or at -gi_bounces=7). Now one eye sample,
// gathered trees included, stays within kSampleRays; counted, not timed.
TEST_CASE("The depth bomb with -gi: one eye sample costs at most 2^20 rays, gathered trees included", "[render]") {
  const SceneDesc desc = loadScene(sourceDir() + "/scenes/depth_bomb.pov");
  const Scene<double> scene(desc, chooseArithmetic(desc));
  const Camera<double> camera(desc.camera, 4, 3);
  const auto rays = [&](std::optional<int> depth, std::optional<int> bounces) {
    RenderOptions options;
    options.depth = depth;
    options.gi.enabled = true;
    options.gi.samples = {8, 4};
    options.gi.bounces = bounces;
    Tracer<double> tracer(scene, options);
    tracer.pixel(camera, 2, 1);
    const RayCounts& c = tracer.counts();
    return c.eye + c.gather + c.secondary;
  };
  CHECK(kSampleRays == 1048576);
  const uint64_t deep = rays(64, std::nullopt), bounced = rays(std::nullopt, 7);
  CHECK(deep <= kSampleRays);
  CHECK(deep > kSampleRays / 2);  // the bound is what stopped it
  CHECK(bounced <= kSampleRays);
  CHECK(bounced > kSampleRays / 2);
}

TEST_CASE("A scene's gamma raises each pixel's colour before it is written, in render() and pixel() alike",
          "[render]") {
  SceneDesc scene = emptyScene();
  scene.lights.push_back({{0, 4, 0}, Color(1)});
  add(scene, SphereDesc{{0, 0, -5}, 1}, pov(kPigment, 1.0f, 0.0f));
  scene.dialect = Dialect::povray(2.2);
  const Color expected(1.0f, std::pow(0.5f, 2.2f), std::pow(0.25f, 2.2f));
  checkColor(centre(scene), expected);
  const Scene<double> built(scene, chooseArithmetic(scene));
  Tracer<double> tracer(built, RenderOptions{});
  checkColor(tracer.pixel(Camera<double>(scene.camera, 1, 1), 0, 0), expected);
}

TEST_CASE("A no_shadow object casts no shadow through transparent surfaces either", "[render]") {
  // The filtering sphere makes shadow rays pass transparent surfaces; the no_shadow sphere lies between the light
  // and the point seen, which POV-Ray 3.7 lights fully: n·l = 10 / |(3.75, 10)| (its picture: 0.93632).
  const SceneDesc scene = onePixel(R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <-0.75, 1, 0> look_at <-0.75, 0, 0> right x * 0.1 up z * 0.1 }
light_source { <3, 10, 0>, rgb 1 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
sphere { <0, 2, 0>, 0.5 pigment { rgb 1 } no_shadow }
sphere { <5, 2, 0>, 0.5 pigment { rgbf 0.5 } }
)");
  checkColor(centre(scene), Color(float(10 / std::hypot(3.75, 10.0))));
}

TEST_CASE("An eye ray across a hollow box of media gets POV-Ray's method 3 colour", "[render][media]") {
  // POV-Ray 3.7's picture of this scene, 16-bit and linear: 0.27451 emitted plus e^-1 of the white background.
  const SceneDesc scene = onePixel(R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right x * 2 up y * 2 }
background { rgb 1 }
box { <-5, -5, -1>, <5, 5, 1> hollow pigment { rgbt 1 } interior { media { absorption 0.5 emission 0.2 } } }
)");
  checkColor(centre(scene), Color(float(0.27451 + std::exp(-1.0))));
}

TEST_CASE("Several media in one interior add up, as POV-Ray draws them", "[render][media]") {
  // POV-Ray 3.7's picture of this scene, 16-bit and linear: the sum of samples 1 (the first medium's) over
  // absorption 0.75 and emission 0.2, 0.2 · (1 + e^−0.75), plus e^−1.5 of the white background.
  const SceneDesc scene = onePixel(R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right x * 2 up y * 2 }
background { rgb 1 }
box { <-5, -5, -1>, <5, 5, 1> hollow pigment { rgbt 1 }
      interior { media { absorption 0.5 emission 0.2 samples 1 } media { absorption 0.25 samples 10 } } }
)");
  CHECK_THAT(centre(scene).r, Catch::Matchers::WithinAbs(0.51760, 2e-5));
  CHECK_THAT(centre(scene).r, Catch::Matchers::WithinAbs(0.2 * (1 + std::exp(-0.75)) + std::exp(-1.5), 2e-5));
  // Where a scene's medium and an object's overlap, the object's sampling comes first: POV-Ray's pictures before
  // black, samples 1's sum 0.32131 and samples 10's 0.27451.
  const auto overlapped = [](int object, int scene) {
    return centre(onePixel(
                      "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                      "camera { orthographic location <0, 0, -5> look_at 0 right x * 2 up y * 2 }\n"
                      "background { rgb 0 }\nmedia { samples " + std::to_string(scene) + " density { rgb 1 } }\n"
                      "box { <-5, -5, -1>, <5, 5, 1> hollow pigment { rgbt 1 } interior { media { absorption 0.5 "
                      "emission 0.2 samples " + std::to_string(object) + " density { rgb 1 } } } }\n"))
        .r;
  };
  CHECK_THAT(overlapped(1, 10), Catch::Matchers::WithinAbs(0.32131, 2e-5));
  CHECK_THAT(overlapped(10, 1), Catch::Matchers::WithinAbs(0.27451, 2e-5));
}

TEST_CASE("An eye ray across media with a density gets POV-Ray's colour", "[render][media]") {
  // POV-Ray 3.7's pictures (16-bit, linear) of a hollow box from z = 0.001 to 0.999 before black, whose medium
  // is `emission 1 absorption A intervals I samples S, S density { … }`, by density, A, I and S.
  const struct {
    const char* density;
    double absorption;
    int intervals, samples;
    double povray;
  } measured[] = {{"rgb 0.5", 0, 1, 1, 0.49900},
                  {"rgb 0.5", 2, 1, 1, 0.40098},
                  {"rgb 0.5", 2, 2, 1, 0.35671},
                  {"rgb 0.5", 2, 3, 1, 0.34267},
                  {"gradient z", 0, 1, 1, 0.33300},
                  {"gradient z color_map { [0 rgb 0] [1 rgb 1] }", 0, 1, 3, 0.33300},
                  {"gradient z", 0, 1, 4, 0.37450},
                  {"gradient z", 0, 1, 10, 0.42786},
                  {"gradient z", 0, 2, 1, 0.41601},
                  {"gradient z", 0, 3, 1, 0.44367},
                  {"gradient z", 1, 1, 1, 0.31301},
                  {"gradient z", 1, 2, 1, 0.36477},
                  {"gradient z", 1, 2, 4, 0.37121},
                  // Two densities multiply: 0.5 · z.
                  {"gradient z } density { rgb 0.5", 0, 1, 1, 0.16651}};
  for (const auto& m : measured) {
    INFO(m.density << ", absorption " << m.absorption << ", intervals " << m.intervals << ", samples " << m.samples);
    const SceneDesc scene = onePixel(R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right x * 2 up y * 2 }
background { rgb 0 }
box { <-5, -5, 0.001>, <5, 5, 0.999> hollow pigment { rgbt 1 }
      interior { media { emission 1 absorption )" + std::to_string(m.absorption) +
                                                    " intervals " + std::to_string(m.intervals) + " samples " +
                                                    std::to_string(m.samples) + " density { " + m.density + " } } } }\n");
    CHECK_THAT(centre(scene).r, Catch::Matchers::WithinAbs(m.povray, 2e-5));
  }
}

TEST_CASE("Media are seen along a ray only while every interior it is in is hollow, as POV-Ray draws them",
          "[render][media]") {
  // POV-Ray 3.7's pictures (16-bit, linear) of the centre of a hollow box z = -1 to 1 of `emission 0.1` before
  // black, with the objects below in it, seen from z = -5 or, for the second list, from the origin.
  const std::string box = "box { <-5, -5, -1>, <5, 5, 1> hollow pigment { rgbt 1 } interior { media { emission 0.1 } } }\n";
  const std::string solidBox = "box { <-5, -5, -1>, <5, 5, 1> pigment { rgbt 1 } interior { media { emission 0.1 } } }\n";
  const std::string clear = " pigment { rgbt 1 } ";
  const struct {
    std::string objects;
    double povray;
  } fromFront[] = {
      {box, 0.2},
      {solidBox, 0},  // a medium in a solid object is not seen
      {box + "sphere { 0, 0.5" + clear + "}", 0.10001},  // a solid object inside takes the medium's place
      {box + "sphere { 0, 0.5 hollow" + clear + "}", 0.2},
      {box + "sphere { 0, 0.5" + clear + "interior { media { emission 0.3 } } }", 0.10001},
      {box + "sphere { 0, 0.5 hollow" + clear + "interior { media { emission 0.3 } } }", 0.50001},  // they add up
      {box + "sphere { 0, 0.5 hollow" + clear + "interior { ior 1.5 } }", 0.2},
      {box + "sphere { 0, 0.5 pigment { rgb 0 } }", 0.05000},  // up to an opaque object
      {box + "box { <-6, -6, -3>, <6, 6, 3>" + clear + "}", 0},  // inside a solid object
      {box + "plane { z, 0" + clear + "}", 0.10001},
      {box + "plane { z, 0 hollow" + clear + "}", 0.2},
      // A mirror at z = 0.5: 1.5 there and 1.5 back.
      {box + "box { <-5, -5, 0.5>, <5, 5, 0.6> pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }", 0.29999},
      // A CSG's parts share its medium: in the overlap (z = -0.2 to 0.5) of a union the ray is out of it again.
      {box + "union { sphere { 0, 0.5 } sphere { z * 0.3, 0.5 } hollow" + clear + "interior { media { emission 0.2 } } }", 0.32000},
      {box + "merge { sphere { 0, 0.5 } sphere { z * 0.3, 0.5 } hollow" + clear + "interior { media { emission 0.2 } } }", 0.46000},
      {box + "difference { sphere { 0, 0.5 } sphere { z * 0.3, 0.3 } hollow" + clear + "interior { media { emission 0.2 } } }", 0.30001},
      // A solid difference ends where the ray leaves it through its second part (z = 0).
      {box + "difference { sphere { 0, 0.5 } sphere { z * 0.3, 0.3 }" + clear + "}", 0.14999},
  };
  const auto seen = [](const std::string& camera, const std::string& objects) {
    return centre(onePixel("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n" + camera +
                                          "background { rgb 0 }\n" + objects + "\n"))
        .r;
  };
  for (const auto& m : fromFront) {
    INFO(m.objects);
    CHECK_THAT(seen("camera { orthographic location <0, 0, -5> look_at 0 right x * 2 up y * 2 }\n", m.objects),
               Catch::Matchers::WithinAbs(m.povray, 2e-5));
  }
  // An eye ray starts in the interiors around its origin.
  const struct {
    std::string objects;
    double povray;
  } fromInside[] = {
      {box, 0.10001},
      {solidBox, 0},
      {box + "sphere { 0, 0.5" + clear + "}", 0.05000},
      {box + "sphere { 0, 0.5 hollow" + clear + "}", 0.10001},
      {box + "sphere { 0, 0.1" + clear + "}", 0.09000},
  };
  for (const auto& m : fromInside) {
    INFO(m.objects);
    CHECK_THAT(seen("camera { orthographic location 0 look_at z right x * 2 up y * 2 }\n", m.objects),
               Catch::Matchers::WithinAbs(m.povray, 2e-5));
  }
}

TEST_CASE("Fog is seen only along rays in hollow objects, as POV-Ray draws it", "[render][media]") {
  // A clear sphere z = -2 to 2 before a black wall at z = 5, fog of distance 10: solid, the ray is fogged over
  // 3 before it and 3 after it alone, 1 − e^(−0.3) seen through e^(−0.3) plus 1 − e^(−0.3) (POV-Ray: 0.45119);
  // hollow, over all 10 (POV-Ray: 0.63212).
  const auto seen = [](const char* hollow) {
    return centre(onePixel(std::string(R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right x * 2 up y * 2 }
background { rgb 0 }
fog { color rgb 1 distance 10 }
box { <-9, -9, 5>, <9, 9, 6> pigment { rgb 0 } finish { ambient 0 diffuse 0 } }
sphere { 0, 2 pigment { rgbt 1 } )") + hollow + " }\n")).r;
  };
  const double a = std::exp(-0.3);
  CHECK_THAT(seen(""), Catch::Matchers::WithinAbs((1 - a) * a + (1 - a), 1e-5));
  CHECK_THAT(seen("hollow"), Catch::Matchers::WithinAbs(1 - std::exp(-1.0), 1e-5));
}

TEST_CASE("Scene-level media fill the scene as an outermost hollow interior, as POV-Ray draws them",
          "[render][media]") {
  // POV-Ray 3.7's pictures (16-bit, linear) of these scenes' centres, seen from z = -5 before a black wall at
  // z = 5 (`wall`) or before the background alone.
  const std::string wall = "box { <-9, -9, 5>, <9, 9, 6> pigment { rgb 0 } finish { ambient 0 diffuse 0 } }\n";
  const std::string clear = " pigment { rgbt 1 } ";
  const struct {
    std::string background, objects;
    double povray;
  } measured[] = {
      // A ray that hits nothing crosses 2·10¹⁰ units of the medium: 0.02 emitted, e^(−0.2) of the background.
      {"0", "media { emission 1e-12 }", 0.02000},
      {"1", "media { absorption 1e-11 }", 0.81874},
      {"0", "media { emission 0.05 }" + wall, 0.50001},
      {"0", "media { emission 0.05 } media { emission 0.02 }" + wall, 0.70001},  // several add up
      // A solid object hides the medium along the ray's way through it; a hollow one does not.
      {"0", "media { emission 0.05 }" + wall + "sphere { 0, 2" + clear + "}", 0.29999},
      {"0", "media { emission 0.05 }" + wall + "sphere { 0, 2 hollow" + clear + "}", 0.50001},
      {"0", "media { emission 0.05 }" + wall + "sphere { 0, 2 hollow" + clear + "interior { ior 1.5 } }", 0.50001},
      {"0", "media { emission 0.1 }" + wall + "box { <-9, -9, -9>, <9, 9, 3>" + clear + "}", 0.2},  // camera inside
      // A hollow object's own medium adds to the scene's.
      {"0", "media { emission 0.05 }" + wall + "sphere { 0, 2 hollow" + clear + "interior { media { emission 0.1 } } }",
       0.90001},
      // A mirror at z = 1 before a black wall behind the camera at z = −7: 6 there and 8 back.
      {"0",
       "media { emission 0.05 } box { <-9, -9, 1>, <9, 9, 2> pigment { rgb 0 } finish { ambient 0 diffuse 0 "
       "reflection 1 } } box { <-9, -9, -8>, <9, 9, -7> pigment { rgb 0 } finish { ambient 0 diffuse 0 } }",
       0.70001},
      {"0", "light_source { <0, 10, 0>, rgb 1 } media { scattering { 1, 0.05 } }" + wall, 0.41009},
  };
  for (const auto& m : measured) {
    INFO(m.objects);
    const SceneDesc scene = onePixel(
        "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
        "camera { orthographic location <0, 0, -5> look_at 0 right x * 2 up y * 2 }\nbackground { rgb " +
            m.background + " }\n" + m.objects + "\n");
    CHECK_THAT(centre(scene).r, Catch::Matchers::WithinAbs(m.povray, 2e-5));
  }
}

TEST_CASE("A medium sees each point of an area light's grid, as POV-Ray draws it", "[render][media]") {
  // A 2 × 1 area light has its points at x = ±2; the plate hides the left one, not the centre, from the whole
  // way of the centre's eye ray, so half the light a point light gives is scattered. POV-Ray 3.7's pictures
  // (16-bit, linear): 0.41009 for the point light, 0.20505 for the area light, `adaptive 1` or not.
  const std::string scene = "global_settings { assumed_gamma 1 }\n"
                            "camera { orthographic location <0, 0, -5> look_at 0 right x * 2 up y * 2 }\n"
                            "background { rgb 0 }\n"
                            "media { scattering { 1, 0.05 } }\n"
                            "box { <-9, -9, 5>, <9, 9, 6> pigment { rgb 0 } finish { ambient 0 diffuse 0 } }\n"
                            "box { <-2.5, 9, -9>, <-1.5, 9.1, 9> pigment { rgb 0 } }\n";
  const struct {
    std::string light;
    double povray;
  } measured[] = {{"", 0.41009},
                  {"area_light <4, 0, 0>, <0, 0, 0>, 2, 1", 0.20505},
                  {"area_light <4, 0, 0>, <0, 0, 0>, 2, 1 adaptive 1", 0.20505}};
  for (const auto& m : measured) {
    INFO(m.light);
    const SceneDesc desc = onePixel(
        "#version 3.7;\n" + scene + "light_source { <0, 10, 0>, rgb 1 " + m.light + " }\n");
    CHECK_THAT(centre(desc).r, Catch::Matchers::WithinAbs(m.povray, 2e-5));
  }
}

TEST_CASE("A light with media_attenuation is dimmed by the scene's fogs and media, as POV-Ray draws it",
          "[render][media]") {
  // POV-Ray 3.7's pictures (16-bit, linear) of a white wall at z = 0 lit from z = −4 (rgb 1, or 0.5 where the
  // picture would clip), seen from z = −1 through the same fog or medium: e^(−1/4) from the eye's way alone,
  // e^(−5/4) when the light's way of 4 counts too.
  const std::string box =
      "box { <-1, -1, -3.5>, <1, 1, -1.5> hollow pigment { rgbt 1 } interior { media { absorption 0.25 } } }";
  const struct {
    std::string atmosphere;
    bool attenuated;
    const char* light;
    double povray;
  } measured[] = {
      {"fog { distance 4 rgb 0 }", false, "1", 0.77879},
      {"fog { distance 4 rgb 0 }", true, "1", 0.28650},
      {"media { absorption 0.25 }", false, "1", 0.77879},
      {"media { absorption 0.25 }", true, "1", 0.28650},
      // The light scattered toward the eye is dimmed on its way too.
      {"media { scattering { 1, 0.1 } }", false, "0.5", 0.50039},
      {"media { scattering { 1, 0.1 } }", true, "0.5", 0.33735},
      // An object's medium dims every light, attenuated or not: e^(−0.25·2).
      {box, false, "1", 0.60652},
      {box, true, "1", 0.60652},
  };
  for (const auto& m : measured) {
    INFO(m.atmosphere << ", media_attenuation " << m.attenuated);
    const SceneDesc scene = onePixel(
        "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
        "camera { orthographic location <0, 0, -1> look_at 0 right x * 0.1 up y * 0.1 }\nbackground { rgb 0 }\n"
        "light_source { <0, 0, -4>, rgb " + std::string(m.light) + " media_attenuation " +
            std::string(m.attenuated ? "on" : "off") +
            " }\nplane { -z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n" + m.atmosphere + "\n");
    CHECK_THAT(centre(scene).r, Catch::Matchers::WithinAbs(m.povray, 2e-5));
  }
}

TEST_CASE("A medium inside an object with a patterned pigment is seen as in a plain one", "[render][media]") {
  // hollow3.pov's sphere: its checker made the tracer miss the interior's medium, and draw none.
  const auto seen = [](const char* pigment) {
    return centre(onePixel(std::string("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                                                  "camera { orthographic location <0, 0, -5> look_at 0 right x up y }\n"
                                                  "background { rgb 0 }\nbox { -1, 1 hollow pigment { ") +
                                          pigment + " } interior { media { emission 0.25 } } }\n"));
  };
  const Color plain = seen("rgbt 1");
  checkColor(plain, Color(0.5f));  // emission 0.25 over the box's depth of 2
  checkColor(seen("checker rgbt 1, rgbt 1"), plain);
}

TEST_CASE("A medium's density moves with its object", "[render][media]") {
  // The gradient's ramp, moved by the box's translate, reads from 0 at the box's near side: as unmoved.
  const auto seen = [](const char* box) {
    return centre(onePixel(std::string(R"(#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right x * 2 up y * 2 }
background { rgb 0 }
)") + box)).r;
  };
  const float still = seen("box { <-5, -5, 0.001>, <5, 5, 0.999> hollow pigment { rgbt 1 } "
                           "interior { media { emission 1 samples 1 density { gradient z } } } }\n");
  const float moved = seen("box { <-5, -5, 0.001>, <5, 5, 0.999> hollow pigment { rgbt 1 } "
                           "interior { media { emission 1 samples 1 density { gradient z } } } translate z * 0.5 }\n");
  CHECK_THAT(still, Catch::Matchers::WithinAbs(0.33300, 2e-5));
  CHECK_THAT(moved, Catch::Matchers::WithinAbs(still, 1e-6));
}
