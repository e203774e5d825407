#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <vector>

#include "raytrace/util/error.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/render/renderer.hpp"

TEST_CASE("parallelFor runs every index exactly once, whatever the thread count", "[parallel]") {
  for (int threads : {1, 2, 3, 8}) {
    CAPTURE(threads);
    std::vector<std::atomic<int>> runs(1000);
    rt::parallelFor(1000, threads, [&](int i) { ++runs[size_t(i)]; });
    for (const auto& r : runs) REQUIRE(r == 1);
  }
  rt::parallelFor(0, 4, [](int) { FAIL("no index to run"); });
}

TEST_CASE("a parallelFor inside a task runs every index of its own exactly once", "[parallel]") {
  rt::startHelpers(3);
  std::vector<std::atomic<int>> runs(40 * 25);
  rt::parallelFor(40, 3, [&](int i) { rt::parallelFor(25, 3, [&](int j) { ++runs[size_t(i * 25 + j)]; }); });
  for (const auto& r : runs) REQUIRE(r == 1);
}

TEST_CASE("parallelForChunks hands out whole chunks and a short last one", "[parallel]") {
  for (int threads : {1, 2, 3}) {
    CAPTURE(threads);
    std::vector<std::atomic<int>> chunks(3);
    rt::parallelForChunks(10, 4, threads, [&](size_t begin, size_t end) {
      REQUIRE(begin % 4 == 0);
      REQUIRE(end == std::min<size_t>(begin + 4, 10));
      ++chunks[begin / 4];
    });
    for (const auto& b : chunks) REQUIRE(b == 1);
  }
  rt::parallelForChunks(0, 4, 2, [](size_t, size_t) { FAIL("no item to run"); });
}

TEST_CASE("parallelFor rethrows the first failure once all threads have stopped", "[parallel]") {
  std::atomic<int> started{0};
  const auto task = [&](int i) {
    ++started;
    if (i == 3) throw rt::Error("task 3 failed");
  };
  CHECK_THROWS_WITH(rt::parallelFor(100, 1, task), "task 3 failed");
  CHECK(started == 4);  // nothing after the failure is started
  CHECK_THROWS_WITH(rt::parallelFor(100, 2, task), "task 3 failed");
}

TEST_CASE("render gives the same image on any number of threads", "[parallel]") {
  rt::SceneDesc desc;
  desc.lights.push_back({{-10, 10, 10}, rt::Color(1)});
  for (int i = 0; i < 30; ++i) {
    rt::ObjectDesc o;
    o.shape = rt::SphereDesc{{(i % 6) - 2.5, (i / 6) - 2.0, -5.0 - (i % 4)}, 0.45};
    o.material.pigment = rt::Color(0.2f + 0.02f * float(i), 0.5f, 0.8f);
    o.material.ambient = 0.2f * o.material.pigment;
    o.material.diffuse = 0.7f * o.material.pigment;
    o.material.reflection = i % 3 == 0 ? 0.5f : 0.0f;
    desc.objects.push_back(o);
  }
  rt::RenderOptions one;
  one.threads = 1;
  one.samples = 2;
  const rt::Image reference = rt::render(desc, 67, 45, one);  // sizes that do not divide into tiles
  for (int threads : {2, 3, 7}) {
    CAPTURE(threads);
    rt::RenderOptions many = one;
    many.threads = threads;
    const rt::Image image = rt::render(desc, 67, 45, many);
    for (int y = 0; y < 45; ++y) {
      for (int x = 0; x < 67; ++x) REQUIRE(image.at(x, y) == reference.at(x, y));
    }
  }
}
