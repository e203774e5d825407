// A finish's `irid`, against pixels of POV-Ray 3.7's own renders (16-bit, linear: assumed_gamma 1, File_Gamma 1,
// no anti-aliasing) of a plane lit by one parallel light with ambient 0.
#include <catch2/catch.hpp>

#include <cmath>

#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/render/renderer.hpp"
#include "raytrace/surface/iridescence.hpp"

namespace rt {
namespace {

using Catch::Matchers::WithinAbs;

double radians(double degrees) { return degrees * M_PI / 180; }

// A plane of pigment 0.5 and diffuse 1 under a light of 1: the pixel over the pixel without irid is the factor.
TEST_CASE("Iridescence multiplies a light by 1 + amount·cos(2π·thickness·(n·l + n·v) / λ) per channel",
          "[iridescence]") {
  Iridescence irid;
  irid.amount = 0.3;
  irid.thickness = 0.2;
  irid.wavelengths = std::make_shared<const glm::dvec3>(0.70, 0.52, 0.48);
  irid.noise = std::make_shared<const NoiseGenerator>(NoiseGenerator::RangeCorrected);
  struct Case {
    double viewer, light;  // the plane's normal turned from the viewer, the light from the viewer (degrees)
    Color povray;
  };
  const Case cases[] = {{30, 0, {0.70018f, 0.84921f, 0.94693f}},   {30, 30, {0.70648f, 0.93951f, 1.05157f}},
                        {60, -20, {1.10615f, 0.98295f, 0.94253f}}, {45, 80, {0.72387f, 0.74372f, 0.80292f}},
                        {-40, 10, {0.75450f, 0.71030f, 0.74372f}}};
  for (const Case& c : cases) {
    const Color f = irid.factor(glm::dvec3(0), std::cos(radians(c.light - c.viewer)), std::cos(radians(c.viewer)));
    CAPTURE(c.viewer, c.light);
    for (int k = 0; k < 3; ++k) CHECK_THAT(f[k], WithinAbs(c.povray[k], 1e-4));
  }
}

// A 24×24 picture of the plane z = 0 from −z, 6 units across, lit head on; `finish` and `global` are added.
Image wall(const std::string& finish, const std::string& global = "") {
  const std::string text = "#version 3.7;\n"
      "global_settings { assumed_gamma 1 " + global + " }\n"
      "camera { orthographic location <0, 0, -5> look_at 0 right 6*x up 6*y }\n"
      "plane { -z, 0 pigment { rgb 0.5 } finish { ambient 0 diffuse 1 " + finish + " } }\n"
      "light_source { <0, 0, -100> rgb 1 parallel point_at 0 }\n";
  return render(povray::parsePovRay(text, "irid.pov", povray::PovRayOptions{{}, 24, 24, false}), 24, 24, {});
}

struct Pixel {
  int x, y;  // y counted from the top, as in POV-Ray's picture
  Color povray;
};

void checkPixels(const Image& image, std::initializer_list<Pixel> pixels) {
  for (const Pixel& p : pixels) {
    // POV-Ray's file clamps each channel to [0, 1].
    const Color c = glm::clamp(image.at(p.x, image.height() - 1 - p.y), Color(0), Color(1));
    CAPTURE(p.x, p.y, c.r, c.g, c.b);
    for (int k = 0; k < 3; ++k) CHECK_THAT(c[k], WithinAbs(p.povray[k], 1e-4));
  }
}

TEST_CASE("irid's turbulence thickens the film by 1 + turbulence·(2s − 1), s turbulence's sum at the world point",
          "[iridescence]") {
  checkPixels(wall("irid { 1 thickness 0.3 turbulence 0.7 }"),
              {{0, 0, {0.69244f, 0.03464f, 0.19052f}},
               {13, 1, {0.70697f, 0.02725f, 0.20900f}},
               {4, 4, {0.99094f, 0.44717f, 0.98500f}},
               {19, 8, {0.31559f, 0.42228f, 0.01245f}},
               {12, 12, {0.61518f, 0.16440f, 0.55943f}},
               {23, 18, {0.67398f, 0.04506f, 0.16832f}},
               {23, 23, {0.75171f, 0.00958f, 0.27167f}}});
}

TEST_CASE("irid tints highlights too, may take light away, and follows irid_wavelength", "[iridescence]") {
  // Head on the phase is 4π·thickness/λ; with amount 2 red's factor is 1 + 2·cos(4π·0.2/0.7) = −0.80, which
  // takes 0.20 from an ambient 0.15: POV-Ray's red is 0, not 0.15.
  checkPixels(wall("diffuse 0 phong 0.5 irid { 0.3 thickness 0.2 }"), {{12, 12, {0.36486f, 0.51807f, 0.57501f}}});
  checkPixels(wall("ambient 0.3 diffuse 0.5 irid { 2 thickness 0.2 }"), {{12, 12, {0, 0.46027f, 0.65000f}}});
  checkPixels(wall("irid { 0.3 thickness 0.2 }", "irid_wavelength rgb <0.5, 0.4, 0.3>"),
              {{12, 12, {0.54635f, 0.65000f, 0.42499f}}});
}

}  // namespace
}  // namespace rt
