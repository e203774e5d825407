// Kernel benchmarks (Google Benchmark): ray-sphere, ray-box (a packet against a node's four boxes), and closest-hit / shadow queries with and without
// the hierarchy. Figures, not tests: build with -DRAYTRACE_BENCHMARKS=ON and run build/raytrace_bench.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "raytrace/accel/bvh.hpp"
#include "raytrace/render/camera.hpp"
#include "raytrace/accel/scene.hpp"
#include "raytrace/geometry/spawn.hpp"
#include "raytrace/shapes/sphere.hpp"

namespace {

constexpr int kRays = 4096;  // per batch, cycled through; enough to defeat the branch predictor

template <class T> std::vector<rt::Ray<T>> raysToward(const rt::Vec3<T>& target, T spread, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<T> u(-spread, spread);
  std::vector<rt::Ray<T>> rays;
  const rt::Vec3<T> origin(0, 0, 10);
  for (int i = 0; i < kRays; ++i) {
    rays.push_back({origin, glm::normalize(target + rt::Vec3<T>(u(rng), u(rng), u(rng)) - origin)});
  }
  return rays;
}

// About half the rays hit a unit sphere at the origin.
template <class T, rt::SphereMethod Method> void BM_RaySphere(benchmark::State& state) {
  const rt::Sphere<T> sphere({0, 0, 0}, 1, Method, rt::Material{}, 1);
  const auto rays = raysToward<T>({0, 0, 0}, T(1.4), 1);
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sphere.intersect(rays[i++ % kRays], {}));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK_TEMPLATE(BM_RaySphere, float, rt::SphereMethod::Textbook);
BENCHMARK_TEMPLATE(BM_RaySphere, float, rt::SphereMethod::Robust);
BENCHMARK_TEMPLATE(BM_RaySphere, double, rt::SphereMethod::Robust);

// The node test of the hierarchy: a packet of 16 rays against the boxes of four children, about half the rays
// entering each.
template <class T> void BM_RayBox4(benchmark::State& state) {
  using Bvh = rt::Bvh<T>;
  typename Bvh::Node node;
  for (int k = 0; k < 4; ++k) {
    for (int a = 0; a < 3; ++a) node.lo[a][k] = T(-1 + 0.1 * k), node.hi[a][k] = T(1 - 0.1 * k);
  }
  const auto rays = raysToward<T>({0, 0, 0}, T(1.6), 2);
  std::vector<typename Bvh::Packet> packets(kRays / Bvh::kPacket);
  for (size_t r = 0; r < rays.size(); ++r) {
    packets[r / Bvh::kPacket].set(int(r % Bvh::kPacket), rays[r], std::numeric_limits<T>::infinity());
  }
  size_t i = 0;
  uint32_t childRays[Bvh::kWidth];
  T childEntry[Bvh::kWidth];
  for (auto _ : state) {
    Bvh::entries(node, packets[i++ % packets.size()], T(0), 0xffff, childRays, childEntry);
    benchmark::DoNotOptimize(childRays);
    benchmark::DoNotOptimize(childEntry);
  }
  state.SetItemsProcessed(state.iterations() * 4 * Bvh::kPacket);
}
BENCHMARK_TEMPLATE(BM_RayBox4, float);
BENCHMARK_TEMPLATE(BM_RayBox4, double);

// n spheres scattered over a field in front of the camera, like bench/spheres*.pov: with radius ∝ 1/√n the
// spheres cover about the same share of the picture whatever n.
rt::SceneDesc field(int n) {
  std::mt19937 rng{unsigned(n)};
  std::uniform_real_distribution<double> x(-20, 20), z(-40, 0), u(0.5, 1.5);
  rt::SceneDesc desc;
  desc.camera.location = {0, 8, 12};
  desc.camera.lookAt = {0, 0, -12};
  desc.camera.up = glm::normalize(glm::cross(glm::dvec3(1, 0, 0), desc.camera.lookAt - desc.camera.location));
  for (int i = 0; i < n; ++i) {
    rt::ObjectDesc o;
    const double r = u(rng) * 12 / std::sqrt(double(n));
    o.shape = rt::SphereDesc{{x(rng), r, z(rng)}, r};
    desc.objects.push_back(o);
  }
  return desc;
}

// Eye rays of a 64×48 picture: the closest-hit query that dominates a render.
void closestHit(benchmark::State& state, rt::Hierarchy hierarchy) {
  const rt::SceneDesc desc = field(int(state.range(0)));
  const rt::Scene<float> scene(desc, {rt::Tier::Float, rt::SphereMethod::Robust}, hierarchy);
  const rt::Camera<float> camera(desc.camera, 64, 48);
  int pixel = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(scene.closestHit(camera.pixelRay(pixel % 64, pixel / 64 % 48), {}));
    ++pixel;
  }
  state.SetItemsProcessed(state.iterations());
}
void BM_ClosestHitScan(benchmark::State& state) { closestHit(state, rt::Hierarchy::Never); }
void BM_ClosestHitBvh(benchmark::State& state) { closestHit(state, rt::Hierarchy::Always); }
BENCHMARK(BM_ClosestHitScan)->DenseRange(1, 16)->Arg(32)->Arg(64);
BENCHMARK(BM_ClosestHitBvh)->DenseRange(1, 16)->Arg(32)->Arg(64)->Arg(1000)->Arg(100000);

// Shadow rays from the eye-ray hits toward a light: the any-hit query.
void BM_OccludedBvh(benchmark::State& state) {
  const rt::SceneDesc desc = field(int(state.range(0)));
  const rt::Scene<float> scene(desc, {rt::Tier::Float, rt::SphereMethod::Robust}, rt::Hierarchy::Always);
  const rt::Camera<float> camera(desc.camera, 64, 48);
  std::vector<std::pair<rt::Ray<float>, rt::Interval<float>>> shadows;
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      if (const auto hit = scene.closestHit(camera.pixelRay(x, y), {})) {
        shadows.push_back(rt::spawnRayTo(*hit, rt::Vec3<float>(-40, 60, 40), rt::OffsetPolicy::Relative));
      }
    }
  }
  size_t i = 0;
  for (auto _ : state) {
    const auto& [ray, range] = shadows[i++ % shadows.size()];
    benchmark::DoNotOptimize(scene.occluded(ray, range));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OccludedBvh)->Arg(1000)->Arg(100000);

// Building the hierarchy, per object.
void BM_BuildBvh(benchmark::State& state) {
  const rt::SceneDesc desc = field(int(state.range(0)));
  const rt::Scene<float> scene(desc, {rt::Tier::Float, rt::SphereMethod::Robust}, rt::Hierarchy::Never);
  std::vector<const rt::Object<float>*> objects;
  for (const auto& o : scene.objects()) objects.push_back(o.get());
  for (auto _ : state) benchmark::DoNotOptimize(rt::Bvh<float>(objects));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_BuildBvh)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
