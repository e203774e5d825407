// Monte Carlo global illumination (-gi, docs/gi.md): closed-form cases, unbiasedness against a high-sample
// render, and determinism across threads, tile orders and diagnostics.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <catch2/catch.hpp>

#include "raytrace/render/renderer.hpp"
#include "raytrace/render/tracer.hpp"
#include "gi_scenes.hpp"

using namespace rt;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rt::test;

TEST_CASE("GI furnace: inside a sphere lit from its centre each bounce adds the same direct light", "[gi]") {
  // Every point of the inner surface gets the direct light D = Lc·kd·C·(n·l = 1) and gathers only from other
  // such points, so the estimate has no variance: a hit at the last bounce returns D (it gathers nothing), one
  // a bounce before D + D, and the eye ray's hit (B + 1)·D. The material's ambient must not appear.
  SceneDesc scene;
  scene.camera.right = {1, 0, 0};
  scene.lights.push_back({{0, 0, 0}, Color(1)});
  const Color d(0.3f, 0.2f, 0.1f);
  add(scene, SphereDesc{{0, 0, 0}, 10}, matte(Color(0.5f), d));
  const auto centre = [&](const RenderOptions& o) { return render(scene, 3, 3, o).at(1, 1); };
  for (const auto& [options, bounces] : {std::pair{gi({8, 4}), 2}, std::pair{gi({8, 4}, 3), 3},
                                         std::pair{gi({5}), 1}, std::pair{gi({8, 4}, 0), 0}}) {
    CAPTURE(bounces);
    const Color c = centre(options);
    for (int k = 0; k < 3; ++k) CHECK_THAT(c[k], WithinRel(float(bounces + 1) * d[k], 1e-5f));
  }
  // Without -gi the constant ambient is there instead.
  RenderOptions plain;
  CHECK_THAT(centre(plain).r, WithinRel(0.5f + d.r, 1e-5f));
}

TEST_CASE("GI sky: a black sphere above a floor hides sin²α of the cosine-weighted sky", "[gi]") {
  // A point of a black floor under a black sphere of radius r centred at height H sees the sky (the
  // background, 1) except for a cone of half-angle α, sin α = r/H, about its normal. Under the density cos θ/π
  // the cone's share is sin²α; one bounce, so the sphere returns black. A uniform hemisphere would hide
  // 1 − cos α instead (0.134 here, not 0.25).
  SceneDesc scene;
  scene.background = Color(1);
  scene.camera.location = {0, 1, 10};
  scene.camera.lookAt = {0, 0, 0};
  add(scene, PlaneDesc{{0, 1, 0}, 0}, matte(Color(0), Color(0)));
  add(scene, SphereDesc{{0, 2, 0}, 1}, matte(Color(0), Color(0)));
  const Color c = render(scene, 1, 1, gi({4096}, 1)).at(0, 0);
  // 64 × 64 strata: only the row of strata the cone's edge crosses varies, by under 1e-3 (its standard deviation).
  CHECK_THAT(c.r, WithinAbs(0.75, 0.005));
}

TEST_CASE("GI is unbiased: the mean of many low-sample renders agrees with a high-sample render", "[gi]") {
  // 48 renders at 4,2 (seeds 1…48) against one at 256,16 (seed 0), in 4×4-pixel blocks per channel. The low
  // mean's standard error comes from the spread of the 48; the high render's is at most that of a low render
  // times √(4/256) (it has 64 times the first-bounce samples). A block fails beyond 5 combined standard errors.
  const SceneDesc scene = smallRoom();
  constexpr int kW = 16, kH = 12, kBlock = 4, kRuns = 48;
  const std::vector<double> high = blockMeans(render(scene, kW, kH, gi({256, 16})), kBlock);
  const auto worstZ = [&](std::optional<int> bounces) {
    std::vector<std::vector<double>> runs;
    for (int run = 1; run <= kRuns; ++run) {
      runs.push_back(blockMeans(render(scene, kW, kH, gi({4, 2}, bounces, uint64_t(run))), kBlock));
    }
    const Spread low = spreadOf(runs);
    double worst = 0;
    for (size_t i = 0; i < high.size(); ++i) {
      const double se = std::sqrt(low.variance[i] / kRuns + low.variance[i] * 4 / 256) + 1e-7;
      worst = std::max(worst, std::abs(low.mean[i] - high[i]) / se);
    }
    return worst;
  };
  const double z = worstZ({});
  CAPTURE(z);
  CHECK(z < 5);
  // The test can fail: renders that stop one bounce early are rejected.
  const double biased = worstZ(1);
  CAPTURE(biased);
  CHECK(biased > 5);
}

TEST_CASE("GI images are the same for any thread count and any tile order, and pixel() agrees", "[gi]") {
  const SceneDesc scene = smallRoom();
  constexpr int kW = 23, kH = 17;
  RenderOptions options = gi({9, 4});
  options.samples = 2;
  const Image one = render(scene, kW, kH, options);
  options.threads = 2;
  CHECK(sameBits(one, render(scene, kW, kH, options)));
  options.threads = 3;
  CHECK(sameBits(one, render(scene, kW, kH, options)));
  RenderOptions reseeded = options;
  reseeded.gi.seed = 7;
  CHECK_FALSE(sameBits(one, render(scene, kW, kH, reseeded)));

  // Blocks of 5 × 4 pixels in a shuffled order, by one tracer whose caches and buffers carry over, then every
  // pixel alone as pixelcolor computes it.
  const Arithmetic arithmetic = chooseArithmetic(scene, options.arithmetic);
  withPrecision(arithmetic.tier, [&](auto tag) {
    using T = decltype(tag);
    const Scene<T> s(scene, arithmetic);
    const Camera<T> camera(scene.camera, kW, kH);
    Tracer<T> tracer(s, options);
    CHECK(sameBits(one, shuffledTiles(tracer, camera)));
    CHECK(sameBits(one, pixelByPixel(tracer, camera)));
  });
}

TEST_CASE("GI diagnostics sum up the gather rays per bounce", "[gi]") {
  const SceneDesc scene = smallRoom();
  const RenderOptions options = gi({9, 4});
  const Arithmetic arithmetic = chooseArithmetic(scene, options.arithmetic);
  withPrecision(arithmetic.tier, [&](auto tag) {
    using T = decltype(tag);
    const Scene<T> s(scene, arithmetic);
    const Camera<T> camera(scene.camera, 16, 12);
    Tracer<T> tracer(s, options);
    std::vector<RayRecord> trees;
    std::vector<GatherSummary> gathers;
    tracer.pixel(camera, 8, 3, &trees, &gathers);  // the floor: every gather ray leaves a hit
    REQUIRE(gathers.size() == 2);
    CHECK(gathers[0].rays == 9);
    // The second bounce gathers 4 rays from each of the first bounce's hits (those that did not miss).
    CHECK(gathers[1].rays > 0);
    CHECK(gathers[1].rays <= 36);
    CHECK(gathers[1].rays % 4 == 0);
    CHECK(trees.size() == 1);
    CHECK(trees[0].children.empty());
    CHECK(tracer.counts().eye == 1);
    CHECK(tracer.counts().gather == gathers[0].rays + gathers[1].rays);
  });
}
