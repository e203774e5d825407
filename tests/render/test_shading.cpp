#include <cmath>
#include <cstring>
#include <random>

#include <catch2/catch.hpp>

#include "raytrace/render/shading.hpp"

using namespace rt;
using Catch::Matchers::WithinAbs;

namespace {

const Vec3<double> up(0, 0, 1);

Vec3<double> unit(double x, double y, double z) { return glm::normalize(Vec3<double>(x, y, z)); }

}  // namespace

TEST_CASE("Blinn-Phong specular is the clamped half-vector cosine to the exponent", "[shading]") {
  // Light straight above, viewer 45° off: h is 22.5° off the normal.
  const Vec3<double> v = unit(0, 1, 1);
  CHECK_THAT(blinnPhongSpecular(up, up, up, 20.0f), WithinAbs(1.0, 1e-6));
  CHECK_THAT(blinnPhongSpecular(up, v, up, 6.0f), WithinAbs(std::pow(std::cos(M_PI / 8), 6.0), 1e-6));
  // Roughness 1 gives exponent 0 and a constant factor 1 (§c.1), even where n·h = 0.
  CHECK(blinnPhongSpecular(up, unit(1, 0, 0), unit(0, 1, 0), 0.0f) == 1.0f);
  // A negative exponent (roughness > 1) is treated as 0 instead of giving 0^p = ∞.
  CHECK(blinnPhongSpecular(up, unit(1, 0, 0), unit(0, 1, 0), -1.5f) == 1.0f);
  // Opposite light and view have no half vector.
  CHECK(blinnPhongSpecular(up, unit(1, 0, 0), unit(-1, 0, 0), 5.0f) == 0.0f);
  CHECK(blinnPhongSpecular(up, unit(1, 0, 1), unit(-1, 0, 1), 5.0f) == 1.0f);
}

TEST_CASE("Blinn-Phong specular is powf's own answer down to its underflow", "[shading]") {
  // The light swept from the viewer's direction to the horizon: n·h = cos(θ/2) covers [0.7, 1], through the
  // tiny and subnormal results near the point where nh^p underflows.
  const Vec3<float> n(0, 0, 1);
  for (const float exponent : {20.0f, 798.0f, 4998.0f, 50000.0f}) {
    int subnormal = 0, zero = 0;
    for (int k = 0; k <= 20000; ++k) {
      const double theta = M_PI / 2 * k / 20000;
      const Vec3<float> l(float(std::sin(theta)), 0.0f, float(std::cos(theta)));
      const Vec3<float> sum = l + n;
      const float nh = glm::clamp(float(glm::dot(n, sum) / glm::length(sum)), 0.0f, 1.0f);
      const float expected = std::pow(nh, exponent);
      const float got = blinnPhongSpecular(n, n, l, exponent);
      INFO("exponent " << exponent << ", nh " << nh);
      REQUIRE(std::memcmp(&got, &expected, sizeof got) == 0);
      subnormal += std::fpclassify(expected) == FP_SUBNORMAL;
      zero += expected == 0.0f;
    }
    if (exponent >= 798.0f) CHECK(subnormal > 0);
    if (exponent >= 798.0f) CHECK(zero > 0);
  }
}

TEST_CASE("Cook-Torrance GGX at normal incidence is F0 / (4 pi alpha^2)", "[shading]") {
  // n = v = l: D = 1/(πα²), G = 1, F = F0, denominator 4·n·v = 4.
  const float roughness = 0.5f, alpha = 0.25f;
  const double f0 = std::pow(0.5 / 2.5, 2);
  CHECK_THAT(cookTorranceSpecular(up, up, up, roughness, 1.5f), WithinAbs(f0 / (4 * M_PI * alpha * alpha), 1e-6));
  // Light or viewer below the surface: nothing.
  CHECK(cookTorranceSpecular(up, up, unit(1, 0, -0.1), roughness, 1.5f) == 0.0f);
  CHECK(cookTorranceSpecular(up, unit(1, 0, -0.1), up, roughness, 1.5f) == 0.0f);
  // Grazing: finite and non-negative.
  const float grazing = cookTorranceSpecular(up, unit(1, 0, 1e-30), unit(-1, 0, 1e-30), 0.001f, 1.5f);
  CHECK(std::isfinite(grazing));
  CHECK(grazing >= 0.0f);
}

TEST_CASE("Schlick's Fresnel term matches the course's fresnel1 check", "[shading]") {
  CHECK_THAT(schlick(1.0f, 1.5f), WithinAbs(0.04, 1e-7));
  CHECK_THAT(schlick(0.0f, 1.5f), WithinAbs(1.0, 1e-7));
  // §c.5: ior 1.02, n·v = 0.2158 gives F = 0.2966.
  CHECK_THAT(schlick(0.2158f, 1.02f), WithinAbs(0.2966, 5e-5));
}

TEST_CASE("Weights split a hit between local shading, reflection and transmission", "[shading]") {
  Material glass;
  glass.filter = 0.95f;
  // p4/test4: f = 0.95, F = 0.2966 → 0.0500 Local, 0.2818 Reflection, 0.6682 Transmission.
  const Weights w = weights(glass, 0.2966f, Dialect::course());
  CHECK_THAT(w.local, WithinAbs(0.05, 1e-6));
  CHECK_THAT(w.reflection, WithinAbs(0.2818, 1e-4));
  CHECK_THAT(w.transmission, WithinAbs(0.6682, 1e-4));
  Material mirror;
  mirror.reflection = 0.8f;
  const Weights course = weights(mirror, 0.0f, Dialect::course());
  CHECK_THAT(course.local, WithinAbs(0.2, 1e-6));
  CHECK_THAT(course.reflection, WithinAbs(0.8, 1e-6));
  CHECK(course.transmission == 0.0f);
  // The .cli rule adds the reflection on top of the whole local colour.
  const Weights cs3451 = weights(mirror, 0.0f, Dialect::cs3451());
  CHECK(cs3451.local == 1.0f);
  CHECK_THAT(cs3451.reflection, WithinAbs(0.8, 1e-6));
}

TEST_CASE("Weights: POV-Ray reflects whole however transparent the surface; conserve_energy transmits what "
          "reflection leaves", "[shading]") {
  // POV-Ray 3.7's pixels, a plane of reflection 0.5 over and under two emitters of 0.25 (linear): f = 1 gives
  // 0.376, 0.25 with conserve_energy; f = 0.6 gives 0.275, 0.202.
  Material water;
  water.filter = 0.6f;
  water.reflection = 0.5f;
  const Dialect pov = Dialect::povray(1.0);
  const Weights w = weights(water, 0.0f, pov);
  CHECK_THAT(w.local, WithinAbs(0.4, 1e-6));
  CHECK_THAT(w.reflection, WithinAbs(0.5, 1e-6));
  CHECK_THAT(w.transmission, WithinAbs(0.6, 1e-6));
  SurfaceExtras conserving;
  conserving.conserveEnergy = true;
  water.extras = &conserving;
  const Weights c = weights(water, 0.0f, pov);
  CHECK_THAT(c.local, WithinAbs(0.4, 1e-6));
  CHECK_THAT(c.reflection, WithinAbs(0.5, 1e-6));
  CHECK_THAT(c.transmission, WithinAbs(0.3, 1e-6));
  // The course's rule keeps its reflection to the opaque share.
  CHECK_THAT(weights(water, 0.0f, Dialect::course()).reflection, WithinAbs(0.2, 1e-6));
}

TEST_CASE("Reflection mirrors the direction about the normal", "[shading]") {
  const Vec3<double> r = reflectDirection(unit(1, -1, 0), Vec3<double>(0, 1, 0));
  CHECK_THAT(r.x, WithinAbs(std::sqrt(0.5), 1e-12));
  CHECK_THAT(r.y, WithinAbs(std::sqrt(0.5), 1e-12));
  CHECK_THAT(r.z, WithinAbs(0.0, 1e-12));
  // The normal's orientation does not matter.
  const Vec3<double> flipped = reflectDirection(unit(1, -1, 0), Vec3<double>(0, -1, 0));
  CHECK_THAT(glm::length(flipped - r), WithinAbs(0.0, 1e-12));
}

TEST_CASE("A normal bent by a texture never reflects into the surface, as in POV-Ray", "[shading]") {
  // A mirror plane y = 0 seen along d, its normal bent towards +z (POV-Ray's pictures of `normal { gradient z }`
  // with a sky coloured by direction: bent by −0.5, d reflected about n goes down at y = −0.0335 and POV-Ray
  // shows y = +0.0334; bent by −0.8, n faces away from d and POV-Ray shows d reflected about y, 0.0996).
  const Vec3<double> d = unit(0, -1, 10);
  const Vec3<double> up(0, 1, 0);
  const Vec3<double> facing = unit(0, 1, 0.07);
  const Vec3<double> naive = reflectDirection(d, facing);
  REQUIRE(naive.y < 0);
  const Vec3<double> mirrored = reflectBent(d, facing, up);
  CHECK_THAT(mirrored.y, WithinAbs(-naive.y, 1e-12));
  CHECK_THAT(mirrored.z, WithinAbs(naive.z, 1e-12));
  const Vec3<double> raw = reflectBent(d, unit(0, 1, 0.2), up);
  CHECK_THAT(raw.y, WithinAbs(-d.y, 1e-12));
  CHECK_THAT(raw.z, WithinAbs(d.z, 1e-12));
  // A bent normal that reflects out of the surface is kept.
  const Vec3<double> out = reflectBent(d, unit(0, 1, -0.3), up);
  CHECK_THAT(glm::length(out - reflectDirection(d, unit(0, 1, -0.3))), WithinAbs(0.0, 1e-12));
}

TEST_CASE("Refraction follows Snell's law entering and leaving, and reports total internal reflection",
          "[shading]") {
  const Vec3<double> n(0, 1, 0);  // outward
  SECTION("normal incidence passes straight through") {
    const auto t = refractDirection(Vec3<double>(0, -1, 0), n, 1.5f);
    REQUIRE(t);
    CHECK_THAT(t->y, WithinAbs(-1.0, 1e-12));
  }
  SECTION("entering at 45 degrees bends toward the normal") {
    const auto t = refractDirection(unit(1, -1, 0), n, 1.5f);
    REQUIRE(t);
    CHECK_THAT(t->x, WithinAbs(std::sin(M_PI / 4) / 1.5, 1e-7));
    CHECK(t->y < 0);
  }
  SECTION("leaving at 30 degrees bends away from the normal") {
    const auto t = refractDirection(Vec3<double>(std::sin(M_PI / 6), std::cos(M_PI / 6), 0), n, 1.5f);
    REQUIRE(t);
    CHECK_THAT(t->x, WithinAbs(1.5 * 0.5, 1e-7));
    CHECK(t->y > 0);
  }
  SECTION("leaving beyond the critical angle is total internal reflection") {
    CHECK_FALSE(refractDirection(Vec3<double>(std::sin(M_PI / 3), std::cos(M_PI / 3), 0), n, 1.5f));
  }
  SECTION("sweep: TIR exactly beyond the critical angle, unit directions otherwise (docs/reference/stability.md T8)") {
    for (const float ior : {1.5f, 1.0f / 1.5f, 2.42f}) {
      for (int step = 0; step < 900; ++step) {
        const double theta = step * 0.1 * M_PI / 180;
        CAPTURE(ior, step);
        const Vec3<double> leaving(std::sin(theta), std::cos(theta), 0);  // from inside, against −n
        const auto t = refractDirection(leaving, n, ior);
        const double s = double(ior) * std::sin(theta);
        if (s > 1 + 1e-6) CHECK_FALSE(t);
        if (s < 1 - 1e-6) {
          REQUIRE(t);
          CHECK_THAT(glm::length(*t), WithinAbs(1.0, 1e-12));
          CHECK_THAT(t->x, WithinAbs(s, 1e-6));
        }
      }
    }
  }
}

TEST_CASE("Beer's law attenuates by the complement of the pigment", "[shading]") {
  const Color kept = beerAttenuation(Color(1.0f, 0.5f, 0.0f), 2.0f);
  CHECK(kept.r == 1.0f);
  CHECK_THAT(kept.g, WithinAbs(std::exp(-0.15), 1e-6));
  CHECK_THAT(kept.b, WithinAbs(std::exp(-0.3), 1e-6));
  // An infinite path absorbs what can be absorbed and nothing becomes NaN.
  const Color far = beerAttenuation(Color(1.0f, 0.5f, 1.5f), std::numeric_limits<float>::infinity());
  CHECK(far == Color(1.0f, 0.0f, 1.0f));
}

TEST_CASE("POV-Ray's interior fade: half at the fade distance, tinted by the fade colour", "[shading]") {
  Material m;
  SurfaceExtras e;
  m.extras = &e;
  e.fadeDistance = 1;
  e.fadePower = 2;
  e.fadeColor = Color(1.0f, 0.0f, 0.5f);
  // Through 2 units: a = 1/(1 + 2²) = 0.2, and a + (1 − a)·fadeColor per channel (POV-Ray's picture of a slab
  // 2 thick in front of a wall of 0.8 shows 0.8, 0.159, 0.479).
  const Color slab = interiorFade(m, 2.0f);
  CHECK_THAT(slab.r, WithinAbs(1.0, 1e-6));
  CHECK_THAT(slab.g, WithinAbs(0.2, 1e-6));
  CHECK_THAT(slab.b, WithinAbs(0.6, 1e-6));
  CHECK_THAT(interiorFade(m, 1.0f).g, WithinAbs(0.5, 1e-6));
  // A ray that hits nothing inside is not faded (POV-Ray's picture through a plane object, fade_power 2 or 1001,
  // shows the background unchanged).
  CHECK(interiorFade(m, std::numeric_limits<float>::infinity()) == Color(1.0f));
}

TEST_CASE("POV-Ray's exponential interior fade is tinted channel by channel", "[shading]") {
  Material m;
  SurfaceExtras e;
  m.extras = &e;
  e.fadeDistance = 2;
  e.fadePower = 1001;
  e.fadeColor = Color(0.0f, 0.5f, 0.9f);
  // POV-Ray's linear picture of a slab 3 thick, fade_distance 2, over a white background: 0.2231 0.4724 0.8607,
  // exp(−(1 − fade_color)·d/fade_distance) per channel.
  const Color slab = interiorFade(m, 3.0f);
  CHECK_THAT(slab.r, WithinAbs(0.2231, 1e-4));
  CHECK_THAT(slab.g, WithinAbs(0.4724, 1e-4));
  CHECK_THAT(slab.b, WithinAbs(0.8607, 1e-4));
  // fade_power 1000 is already exponential; a channel of fade_color 1 keeps everything (POV-Ray: 0.1353 1 0.1353).
  e.fadePower = 1000;
  e.fadeDistance = 1;
  e.fadeColor = Color(0.0f, 1.0f, 0.0f);
  const Color thick = interiorFade(m, 2.0f);
  CHECK_THAT(thick.r, WithinAbs(0.1353, 1e-4));
  CHECK(thick.g == 1.0f);
  CHECK(interiorFade(m, std::numeric_limits<float>::infinity()) == Color(1.0f));
}

TEST_CASE("POV-Ray's faked caustics: up to twice the light where the surface faces it", "[shading]") {
  CHECK(fakedCaustics(1, 1) == 2);
  CHECK(fakedCaustics(1, -1) == 2);  // either side of the surface
  CHECK(fakedCaustics(2, 0) == 1);
  CHECK_THAT(fakedCaustics(0.5f, -0.5f), WithinAbs(1 + std::pow(0.5, 22.5), 1e-6));
}

TEST_CASE("POV-Ray's variable reflection: from its minimum to its maximum by the falloff, or by Fresnel",
          "[shading]") {
  Material m;
  SurfaceExtras e;
  m.extras = &e;
  e.reflectionMin = 0.2f;
  m.reflection = 0.8f;
  e.reflectionFalloff = 1;
  m.ior = 1.5f;
  // POV-Ray's picture of a black mirror ball in a white sky, `reflection { 0.2, 0.8 }`: 0.266 at cos θ 0.892.
  CHECK_THAT(variableReflection(m, 1.0f).r, WithinAbs(0.2, 1e-6));
  CHECK_THAT(variableReflection(m, 0.892f).r, WithinAbs(0.2648, 1e-4));
  CHECK_THAT(variableReflection(m, 0.0f).r, WithinAbs(0.8, 1e-6));
  e.reflectionFalloff = 3;  // POV-Ray: 0.209 at cos θ 0.758
  CHECK_THAT(variableReflection(m, 0.758f).r, WithinAbs(0.2 + 0.6 * std::pow(0.242, 3), 1e-5));
  // Fresnel: ((n − 1)/(n + 1))² = 0.04 head-on at n = 1.5, 1 at grazing; `reflection { 0.1, 1 fresnel }` is
  // 0.136 head-on in POV-Ray's picture.
  CHECK_THAT(fresnelReflectance(1.0f, 1.5f), WithinAbs(0.04, 1e-6));
  CHECK_THAT(fresnelReflectance(0.0f, 1.5f), WithinAbs(1.0, 1e-6));
  e.reflectionFresnel = true;
  e.reflectionMin = 0.1f;
  m.reflection = 1;
  CHECK_THAT(variableReflection(m, 1.0f).r, WithinAbs(0.136, 1e-6));
  // Colours, `reflection { rgb <0.5, 0, 0>, rgb <0, 0.25, 0> }`: from the one to the other channel by channel.
  e.reflectionFresnel = false;
  e.reflectionFalloff = 1;
  e.reflectionMin = 0.5f;
  e.reflectionMinTint = Color(1, 0, 0);
  m.reflection = 0.25f;
  e.reflectionTint = Color(0, 1, 0);
  CHECK(variableReflection(m, 0.5f) == Color(0.25f, 0.125f, 0));
}

TEST_CASE("metallic reflection: the pigment's colour facing the viewer, the light's at grazing angles", "[shading]") {
  // POV-Ray's 16-bit pictures of a red plane, `reflection { 1 metallic 1 }`, under a white sky, seen at θ from
  // its normal: the green channel is the share F of the light's own colour.
  const Color red(1, 0, 0);
  const std::pair<double, double> kSeen[] = {{0, 0}, {30, 0.011933}, {60, 0.059266}, {80, 0.261112}, {89, 0.835813}};
  for (const auto& [degrees, f] : kSeen) {
    const Color t = metallicTint(red, 1, float(std::cos(degrees * M_PI / 180)));
    CHECK_THAT(t.r, WithinAbs(1, 1e-6));
    CHECK_THAT(t.g, WithinAbs(f, 2e-5));
    CHECK_THAT(t.b, WithinAbs(f, 2e-5));
  }
  // metallic 0.5: half the tint.
  CHECK_THAT(metallicTint(red, 0.5f, 1).g, WithinAbs(0.5, 1e-6));
}

TEST_CASE("Shading terms stay finite for random unit vectors", "[shading]") {
  const unsigned seed = 473;
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<float> r(0.001f, 1.0f), ior(0.1f, 3.0f);
  for (int i = 0; i < 10000; ++i) {
    const Vec3<double> n = unit(g(rng), g(rng), g(rng)), v = unit(g(rng), g(rng), g(rng)),
                       l = unit(g(rng), g(rng), g(rng));
    const float rough = r(rng), eta = ior(rng);
    CAPTURE(i);
    CHECK(std::isfinite(blinnPhongSpecular(n, v, l, 2 / (rough * rough) - 2)));
    CHECK(std::isfinite(cookTorranceSpecular(n, v, l, rough, eta)));
    const auto t = refractDirection(-v, n, eta);
    if (t) CHECK(std::isfinite(t->x + t->y + t->z));
  }
}

TEST_CASE("Phong specular is the clamped cosine between the light and the view's mirror direction", "[shading]") {
  // Viewer 45° off the normal on one side: its mirror is 45° off on the other side.
  const Vec3<double> v = unit(0, 1, 1);
  CHECK_THAT(phongSpecular(up, v, unit(0, -1, 1), 10.0f), WithinAbs(1.0, 1e-6));
  // The light straight above is 45° from the mirror direction.
  CHECK_THAT(phongSpecular(up, v, up, 4.0f), WithinAbs(std::pow(std::cos(M_PI / 4), 4.0), 1e-6));
  // Beyond 90° from the mirror direction, nothing.
  CHECK(phongSpecular(up, v, unit(0, 1, 0.2), 4.0f) == 0.0f);
  // The same light for Blinn-Phong has its half vector 22.5° off the normal: the lobes differ.
  CHECK(blinnPhongSpecular(up, v, up, 4.0f) > phongSpecular(up, v, up, 4.0f));
}
