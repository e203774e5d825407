// POV-Ray's media: what a ray brings back across them, against POV-Ray 3.7's own pictures.
#include <cmath>

#include <catch2/catch.hpp>

#include "raytrace/surface/media.hpp"

using namespace rt;
using Catch::Matchers::WithinAbs;

namespace {

Media medium(float absorption, float emission, int samples) {
  Media m;
  m.absorption = Color(absorption);
  m.emission = Color(emission);
  m.samples = samples;
  return m;
}

// Across `depth` of the medium along z from the origin.
Color across(const Media& m, const Color& behind, double depth) { return m.through(behind, glm::dvec3(0), glm::dvec3(0, 0, 1), depth); }

}  // namespace

TEST_CASE("Media: the light behind is let through by exactly e^(-absorption * depth)", "[media]") {
  // POV-Ray 3.7, a hollow box 2 deep with `absorption 0.5` before a white background: 0.36788 (16-bit, linear).
  const Color through = across(medium(0.5f, 0, 1), Color(1), 2);
  CHECK_THAT(through.r, WithinAbs(0.36788, 1e-5));
  CHECK_THAT(through.g, WithinAbs(std::exp(-1.0), 1e-6));
  // Channels absorb on their own.
  Media tinted = medium(0, 0, 10);
  tinted.absorption = Color(0, 1, 2);
  const Color c = across(tinted, Color(1, 1, 1), 1);
  CHECK(c.r == 1.0f);
  CHECK_THAT(c.g, WithinAbs(std::exp(-1.0), 1e-6));
  CHECK_THAT(c.b, WithinAbs(std::exp(-2.0), 1e-6));
}

TEST_CASE("Media: emission alone adds emission * depth", "[media]") {
  // POV-Ray 3.7: `emission 0.2` over a depth of 2 gives 0.4 at any samples.
  for (const int samples : {1, 4, 10, 33}) CHECK_THAT(across(medium(0, 0.2f, samples), Color(0), 2).r, WithinAbs(0.4, 1e-6));
}

TEST_CASE("Media: emission under absorption is POV-Ray's method 3 sum, not the exact integral", "[media]") {
  // POV-Ray 3.7, `absorption 0.5 emission 0.2` over a depth of 2 before black, by `samples` (16-bit, linear);
  // the exact integral would be 0.4 * (1 - e^-1) = 0.25285 at every count.
  const struct {
    int samples;
    double povray;
  } measured[] = {{1, 0.32131}, {3, 0.32131}, {4, 0.29732}, {5, 0.29732}, {6, 0.28577}, {8, 0.27898},
                  {10, 0.27451}, {12, 0.27134}, {16, 0.26715}, {32, 0.26036}};
  for (const auto& m : measured) {
    INFO("samples " << m.samples);
    CHECK_THAT(across(medium(0.5f, 0.2f, m.samples), Color(0), 2).r, WithinAbs(m.povray, 1e-5));
  }
  // samples 1: two steps of 1, 0.2 * (1 + e^-0.5) exactly.
  CHECK_THAT(across(medium(0.5f, 0.2f, 1), Color(0), 2).r, WithinAbs(0.2 * (1 + std::exp(-0.5)), 1e-6));
  // Behind and emitted light add: a white background behind the same medium.
  CHECK_THAT(across(medium(0.5f, 0.2f, 10), Color(1), 2).r, WithinAbs(0.27451 + std::exp(-1.0), 1e-5));
}

TEST_CASE("Media: each of the intervals has the steps samples asks for", "[media]") {
  // intervals 2, samples 1: two parts of two steps, four steps of 0.5 over a depth of 2.
  Media m = medium(0.5f, 0.2f, 1);
  m.intervals = 2;
  double sum = 0;
  for (int k = 0; k < 4; ++k) sum += std::exp(-0.25 * k);
  CHECK_THAT(across(m, Color(0), 2).r, WithinAbs(0.2 * 0.5 * sum, 1e-6));
  CHECK_THAT(across(m, Color(1), 0).r, WithinAbs(1.0, 1e-6));
}

TEST_CASE("Media: a density scales absorption and emission where the steps read it", "[media]") {
  // A density of 0.25 everywhere is a quarter of the absorption and emission.
  Media m = medium(2, 0.8f, 1);
  auto quarter = std::make_shared<Pigment>();
  quarter->solid.rgb = Color(0.25f);
  m.densities = {quarter};
  CHECK_THAT(across(m, Color(1), 2).r, WithinAbs(across(medium(0.5f, 0.2f, 1), Color(1), 2).r, 1e-6));
}
