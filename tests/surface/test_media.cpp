// POV-Ray's homogeneous media: what a ray brings back across it, against POV-Ray 3.7's own pictures.
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

}  // namespace

TEST_CASE("Media: the light behind is let through by exactly e^(-absorption * depth)", "[media]") {
  // POV-Ray 3.7, a hollow box 2 deep with `absorption 0.5` before a white background: 0.36788 (16-bit, linear).
  const Color through = medium(0.5f, 0, 1).through(Color(1), 2);
  CHECK_THAT(through.r, WithinAbs(0.36788, 1e-5));
  CHECK_THAT(through.g, WithinAbs(std::exp(-1.0), 1e-6));
  // Channels absorb on their own.
  Media tinted = medium(0, 0, 10);
  tinted.absorption = Color(0, 1, 2);
  const Color c = tinted.through(Color(1, 1, 1), 1);
  CHECK(c.r == 1.0f);
  CHECK_THAT(c.g, WithinAbs(std::exp(-1.0), 1e-6));
  CHECK_THAT(c.b, WithinAbs(std::exp(-2.0), 1e-6));
}

TEST_CASE("Media: emission alone adds emission * depth", "[media]") {
  // POV-Ray 3.7: `emission 0.2` over a depth of 2 gives 0.4 at any samples.
  for (const int samples : {1, 4, 10, 33}) CHECK_THAT(medium(0, 0.2f, samples).through(Color(0), 2).r, WithinAbs(0.4, 1e-6));
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
    CHECK_THAT(medium(0.5f, 0.2f, m.samples).through(Color(0), 2).r, WithinAbs(m.povray, 1e-5));
  }
  // samples 1: two steps of 1, 0.2 * (1 + e^-0.5) exactly.
  CHECK_THAT(medium(0.5f, 0.2f, 1).through(Color(0), 2).r, WithinAbs(0.2 * (1 + std::exp(-0.5)), 1e-6));
  // Behind and emitted light add: a white background behind the same medium.
  CHECK_THAT(medium(0.5f, 0.2f, 10).through(Color(1), 2).r, WithinAbs(0.27451 + std::exp(-1.0), 1e-5));
}
