#include "raytrace/util/limits.hpp"

#include <catch2/catch.hpp>

TEST_CASE("memoryShortage says nothing while the need fits", "[limits]") {
  CHECK(rt::memoryShortage("x", 0, 0).empty());
  CHECK(rt::memoryShortage("x", 5 << 20, 5 << 20).empty());
}

TEST_CASE("memoryShortage names the need in MiB, rounded up, and what is left, rounded down", "[limits]") {
  CHECK(rt::memoryShortage("a 2x2 image", (3 << 20) + 1, (1 << 20) + 1023) ==
        "a 2x2 image needs 4 MiB of memory, but only 1 MiB are available");
}

TEST_CASE("objectMemoryShortage asks only when the count passes a power of two from 65536 on", "[limits]") {
  // These never look at the machine's memory, so they hold on any machine.
  CHECK(rt::objectMemoryShortage(0, 65535, "a scene").empty());
  CHECK(rt::objectMemoryShortage(65536, 65537, "a scene").empty());
  CHECK(rt::objectMemoryShortage(70000, 131071, "a scene").empty());
  CHECK(rt::objectMemoryShortage(131072, 262143, "a scene").empty());
}
