// Each scene language's shading rules, as its source states them.
#include <catch2/catch.hpp>

#include "raytrace/scene/dialect.hpp"

using namespace rt;

TEST_CASE("dialect: the course's rules (csc473 §a.0, §c.3, §c.5, §c.9)", "[dialect]") {
  const Dialect d = Dialect::course();
  CHECK(d.toByte() == Dialect::ToByte::Round);
  CHECK(d.gamma() == 1);
  CHECK(d.reflectionReplacesLocal());
  CHECK(d.reflectionTint(Color(0.5f, 0.25f, 1)) == Color(0.5f, 0.25f, 1));
  CHECK(d.bounced(Color(2, 0.5f, -1)) == Color(2, 0.5f, -1));
  CHECK(d.bounced(3.0f) == 3.0f);
  CHECK(d.depthLimit() == 5);
  CHECK(d.shadesAtDepthLimit());
  CHECK_FALSE(d.filtersShadows());
}

TEST_CASE("dialect: CS 3451's rules (cs3451 §A.4.2, §A.4.5)", "[dialect]") {
  const Dialect d = Dialect::cs3451();
  CHECK(d.toByte() == Dialect::ToByte::Truncate);
  CHECK(d.gamma() == 1);
  CHECK_FALSE(d.reflectionReplacesLocal());
  CHECK(d.reflectionTint(Color(0.5f, 0.25f, 1)) == Color(1));
  CHECK(d.bounced(Color(2, 0.5f, -1)) == Color(1, 0.5f, 0));
  CHECK(d.bounced(3.0f) == 1.0f);
  CHECK(d.depthLimit() == 9);
  CHECK_FALSE(d.shadesAtDepthLimit());
  CHECK_FALSE(d.filtersShadows());
}

TEST_CASE("dialect: POV-Ray 3.7's rules, with and without an assumed_gamma", "[dialect]") {
  const Dialect d = Dialect::povray(2.2);
  CHECK(d.toByte() == Dialect::ToByte::Srgb);
  CHECK(d.gamma() == 2.2f);
  CHECK_FALSE(d.reflectionReplacesLocal());
  CHECK(d.reflectionTint(Color(0.5f, 0.25f, 1)) == Color(1));
  CHECK(d.bounced(Color(2, 0.5f, -1)) == Color(2, 0.5f, -1));
  CHECK(d.depthLimit() == 5);
  CHECK(d.shadesAtDepthLimit());
  CHECK(d.filtersShadows());
  // Before #version 3.7, without assumed_gamma: the colours as they are, rounded.
  const Dialect old = Dialect::povray(0);
  CHECK(old.toByte() == Dialect::ToByte::Round);
  CHECK(old.gamma() == 1);
  CHECK(old.filtersShadows());
}
