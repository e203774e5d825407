// POV-Ray's media: what a ray brings back across them, against POV-Ray 3.7's own pictures.
#include <cmath>
#include <functional>
#include <vector>

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

TEST_CASE("Media: several media add up, sampled as the first with the most intervals", "[media]") {
  const auto all = [](const std::vector<Media>& media, const Color& behind) {
    std::vector<const Media*> pointers;
    for (const Media& m : media) pointers.push_back(&m);
    return Media::through(pointers.data(), pointers.size(), behind, glm::dvec3(0), glm::dvec3(0, 0, 1), 2);
  };
  // Two absorbing media let through the product of what each lets through, in light and in shadow.
  const std::vector<Media> absorbing = {medium(0.5f, 0, 1), medium(0.25f, 0, 10)};
  CHECK_THAT(all(absorbing, Color(1)).r, WithinAbs(std::exp(-1.5), 1e-6));
  CHECK_THAT(Media::kept(absorbing, glm::dvec3(0), glm::dvec3(0, 0, 1), 2).r, WithinAbs(std::exp(-1.5), 1e-6));
  // Emissions add.
  CHECK_THAT(all({medium(0, 0.2f, 1), medium(0, 0.1f, 1)}, Color(0)).r, WithinAbs(0.6, 1e-6));
  // POV-Ray 3.7's pictures (16-bit, linear) of a hollow box 2 deep before black, whose interior holds these
  // media, each with `density { rgb 1 }`: `absorption 0.5 emission 0.2` and media that add nothing but their
  // samples and intervals, which the sum takes from the first medium with the most intervals.
  const auto sampled = [](int samples, int intervals) {
    Media m = medium(0, 0, samples);
    m.intervals = intervals;
    return m;
  };
  const auto seen = [](Media m, int samples, int intervals) {
    m.samples = samples;
    m.intervals = intervals;
    return m;
  };
  const Media lit = medium(0.5f, 0.2f, 1);
  CHECK_THAT(all({seen(lit, 1, 1), sampled(10, 1)}, Color(0)).r, WithinAbs(0.32131, 1e-5));
  CHECK_THAT(all({sampled(10, 1), seen(lit, 1, 1)}, Color(0)).r, WithinAbs(0.27451, 1e-5));
  CHECK_THAT(all({seen(lit, 4, 1), sampled(10, 2)}, Color(0)).r, WithinAbs(0.26352, 2e-5));
  CHECK_THAT(all({seen(lit, 4, 1), sampled(10, 1), sampled(1, 3)}, Color(0)).r, WithinAbs(0.27451, 2e-5));
}

TEST_CASE("Media: a density scales absorption and emission where the steps read it", "[media]") {
  // A density of 0.25 everywhere is a quarter of the absorption and emission.
  Media m = medium(2, 0.8f, 1);
  auto quarter = std::make_shared<Pigment>();
  quarter->solid.rgb = Color(0.25f);
  m.densities = {quarter};
  CHECK_THAT(across(m, Color(1), 2).r, WithinAbs(across(medium(0.5f, 0.2f, 1), Color(1), 2).r, 1e-6));
}

namespace {

// One light of colour `light(z)` at each point z along the ray, from `toLight`.
struct StubLights final : MediaLights {
  std::function<double(double)> light;
  glm::dvec3 toLight{1, 0, 0};
  void at(const glm::dvec3& point, std::vector<Arrival>& out) override { out.push_back({toLight, Color(float(light(point.z)))}); }
};

Media scattering(int type, float colour, double extinction, int samples) {
  Media m;
  m.scattering = Scattering{type, Color(colour), 0, extinction};
  m.samples = samples;
  return m;
}

}  // namespace

TEST_CASE("Media: scattering phase functions as POV-Ray 3.7 draws them", "[media]") {
  // POV-Ray 3.7: a hollow box 2 deep of `scattering { type, c extinction 0 }`, lit by one far light and seen
  // along +z before black, gives 2·c·phase; cos is that of the angle between the ray and the way to the light.
  const glm::dvec3 dir(0, 0, 1);
  const auto toLight = [](double cosine) { return glm::dvec3(std::sqrt(1 - cosine * cosine), 0, cosine); };
  const struct {
    int type;
    double eccentricity, cosine, povray, tolerance;
  } measured[] = {{1, 0, -1, 1.0, 1e-4},         {1, 0, 0.5, 1.0, 1e-4},          {2, 0, -1, 0.576656, 1e-5},
                  {2, 0, 0, 0.596933, 1e-4},     {2, 0, 0.5, 1.096246, 1e-4},     {2, 0, 1, 5.766575, 2e-3},
                  {3, 0, -1, 0.495712, 1e-5},    {3, 0, 0.7071068, 0.651865, 1e-4}, {3, 0, 0.8660254, 3.191043, 1e-3},
                  {3, 0, 1, 25.281147, 2e-2},    {4, 0, -1, 1.598725, 1e-4},      {4, 0, 0, 0.799369, 1e-5},
                  {4, 0, 0.5, 0.999200, 1e-4},   {5, 0.5, -1, 0.222210, 1e-4},    {5, 0.5, 0, 0.536660, 1e-4},
                  {5, 0.5, 1, 6.000038, 2e-3},   {5, -0.3, -1, 2.652972, 1e-3},   {5, -0.3, 0, 0.799649, 1e-4},
                  {5, -0.3, 1, 0.414206, 1e-4}};
  for (const auto& m : measured) {
    INFO("type " << m.type << " eccentricity " << m.eccentricity << " cos " << m.cosine);
    const Scattering s{m.type, Color(1), m.eccentricity, 0};
    CHECK_THAT(s.phase(dir, toLight(m.cosine)), WithinAbs(m.povray, m.tolerance));
  }
}

TEST_CASE("Media: scattered light is summed as emission is, and extinction absorbs", "[media]") {
  // POV-Ray 3.7, `scattering { 1, 0.5 }` 2 deep, `samples 1`, lit evenly from the side with no shadow: as
  // `emission 0.5 absorption 0.5`.
  StubLights side;
  side.light = [](double) { return 1.0; };
  const Media m = scattering(1, 0.5f, 1, 1);
  CHECK_THAT(m.through(Color(0), glm::dvec3(0), glm::dvec3(0, 0, 1), 2, &side).r, WithinAbs(0.5 * (1 + std::exp(-0.5)), 1e-6));
  // Without lights, or with extinction 0, it only absorbs, or does nothing.
  CHECK_THAT(across(m, Color(1), 2).r, WithinAbs(std::exp(-1.0), 1e-6));
  CHECK_THAT(across(scattering(1, 0.5f, 0, 1), Color(1), 2).r, WithinAbs(1.0, 1e-6));
}

TEST_CASE("Media: light varying along the way is read at POV-Ray's points, by halves where it varies", "[media]") {
  const glm::dvec3 start(0), dir(0, 0, 1);
  SECTION("a light from the front, dimmed by the medium on its way to each point") {
    // POV-Ray 3.7, `scattering { 1, 0.5 }` 2 deep lit from behind the viewer, by samples.
    StubLights front;
    front.light = [](double z) { return std::exp(-0.5 * z); };
    const struct {
      int samples;
      double povray;
    } measured[] = {{1, 0.610178}, {4, 0.551461}, {6, 0.522026}};
    for (const auto& m : measured) {
      INFO("samples " << m.samples);
      CHECK_THAT(scattering(1, 0.5f, 1, m.samples).through(Color(0), start, dir, 2, &front).r, WithinAbs(m.povray, 2e-5));
    }
  }
  SECTION("a shadow's edge: the points before it are dark") {
    // POV-Ray 3.7, `scattering { 1, 0.5 extinction 0 } samples 4` 2 deep, the light cut off before z = 0.28:
    // steps over [0, 0.5], [0.5, 1], [1, 1.5] read down to a sixteenth of that.
    StubLights edge;
    edge.light = [](double z) { return z < 0.28 ? 0.0 : 1.0; };
    CHECK_THAT(scattering(1, 0.5f, 0, 4).through(Color(0), start, dir, 2, &edge).r, WithinAbs(0.805554, 1e-5));
  }
  SECTION("a thin shadow at a step's middle, seen only if the light varies by more than aa_threshold") {
    // POV-Ray 3.7, `scattering { 1, c extinction 0 } samples 4` 2 deep, the light cut off for 0.24 < z < 0.26:
    // c = 0.5 and 0.02 split the first step, c = 0.01 (0.01·3 channels·2 = 0.06 < 0.1) does not.
    StubLights thin;
    thin.light = [](double z) { return z > 0.24 && z < 0.26 ? 0.0 : 1.0; };
    CHECK_THAT(scattering(1, 0.5f, 0, 4).through(Color(0), start, dir, 2, &thin).r, WithinAbs(34.0 / 36, 1e-5));
    CHECK_THAT(scattering(1, 0.02f, 0, 4).through(Color(0), start, dir, 2, &thin).r, WithinAbs(0.0377813, 2e-5));
    CHECK_THAT(scattering(1, 0.01f, 0, 4).through(Color(0), start, dir, 2, &thin).r, WithinAbs(0.0177768, 2e-5));
    Media level1 = scattering(1, 0.5f, 0, 4);
    level1.aaLevel = 1;
    CHECK_THAT(level1.through(Color(0), start, dir, 2, &thin).r, WithinAbs(1.0 - 1.0 / 9, 1e-6));
  }
}
