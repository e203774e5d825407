// global_settings' radiosity block (radiosity_reader.cpp), and what radiosity does to a scene's ambient terms.
#include <catch2/catch.hpp>

#include "pov_scene.hpp"

using namespace rt;
using rt::test::pov;
using rt::test::povFailure;

TEST_CASE("povray radiosity: an empty block has the manual's defaults", "[povray][radiosity]") {
  CHECK(!pov("sphere { 0, 1 }\n").radiosity);
  const SceneDesc s = pov("global_settings { radiosity { } }\n");
  REQUIRE(s.radiosity);
  const RadiosityDesc& r = *s.radiosity;
  CHECK(r.adcBailout == 0.01);
  CHECK(!r.alwaysSample);
  CHECK(r.brightness == 1);
  CHECK(r.count == 35);
  CHECK(r.countPool == 0);
  CHECK(r.errorBound == 1.8);
  CHECK(r.grayThreshold == 0);
  CHECK(r.lowErrorFactor == 0.5);
  CHECK(r.maxSample <= 0);
  CHECK(r.maximumReuse == 0.2);
  CHECK(r.minimumReuse == 0.015);
  CHECK(r.nearestCount == 5);
  CHECK(!r.normal);
  CHECK(!r.media);
  CHECK(!r.subsurface);
  CHECK(r.pretraceStart == 0.08);
  CHECK(r.pretraceEnd == 0.04);
  CHECK(r.recursionLimit == 2);
}

TEST_CASE("povray radiosity: every setting of the block is read", "[povray][radiosity]") {
  const SceneDesc s = pov(R"(
global_settings { radiosity {
  adc_bailout 0.005 always_sample on brightness 1.5 count 200, 1600 error_bound 0.5 gray_threshold 0.3
  low_error_factor 0.7 max_sample 2 maximum_reuse 0.1 minimum_reuse 0.01 nearest_count 10, 3 normal on
  media on subsurface off pretrace_start 0.04 pretrace_end 0.01 recursion_limit 3
} }
)");
  REQUIRE(s.radiosity);
  const RadiosityDesc& r = *s.radiosity;
  CHECK(r.adcBailout == 0.005);
  CHECK(r.alwaysSample);
  CHECK(r.brightness == 1.5);
  CHECK(r.count == 200);
  CHECK(r.countPool == 1600);
  CHECK(r.errorBound == 0.5);
  CHECK(r.grayThreshold == 0.3);
  CHECK(r.lowErrorFactor == 0.7);
  CHECK(r.maxSample == 2);
  CHECK(r.maximumReuse == 0.1);
  CHECK(r.minimumReuse == 0.01);
  CHECK(r.nearestCount == 10);
  CHECK(r.nearestCountPretrace == 3);
  CHECK(r.normal);
  CHECK(r.media);
  CHECK(!r.subsurface);
  CHECK(r.pretraceStart == 0.04);
  CHECK(r.pretraceEnd == 0.01);
  CHECK(r.recursionLimit == 3);
}

TEST_CASE("povray radiosity: a count out of its range or a setting without its number stops where it is written",
          "[povray][radiosity]") {
  CHECK(povFailure("global_settings { radiosity { count 0 } }\n") ==
        "scene.pov:2:31: error: radiosity's 'count' must be from 1 to 10000000");
  CHECK(povFailure("global_settings { radiosity { recursion_limit 0 } }\n") ==
        "scene.pov:2:31: error: radiosity's 'recursion_limit' must be from 1 to 10000000");
  CHECK(povFailure("global_settings { radiosity { nearest_count 1e9 } }\n") ==
        "scene.pov:2:31: error: radiosity's 'nearest_count' must be from 1 to 10000000");
  CHECK(povFailure("global_settings { radiosity { brightness } }\n") ==
        "scene.pov:2:31: error: radiosity's 'brightness' needs a number");
}

TEST_CASE("povray radiosity: a 3.7 scene's ambient is 0 and its emission stays; an older scene's ambient stays",
          "[povray][radiosity]") {
  // POV-Ray 3.7 manual, "How Radiosity Works": "when radiosity is used an objects ambient term is effectively
  // set to zero"; measured, a #version 3.6 scene's ambient·ambient_light still lights as emission does.
  const std::string body = R"(
global_settings { ambient_light 0.5 radiosity { } }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.25> } finish { ambient 0.2 emission 0.5 } }
sphere { 0, 1 pigment { rgb 1 } finish { ambient 0.2 } }
)";
  const SceneDesc s = pov(body);
  REQUIRE(s.objects.size() == 2);
  REQUIRE(s.objects[0].texture);
  const Material m = s.objects[0].texture->at(glm::dvec3(0));
  CHECK(m.ambient.r == Approx(0.5f));  // the emission alone, times C
  CHECK(m.ambient.g == Approx(0.25f));
  CHECK(s.objects[1].material.ambient == Color(0));
  const SceneDesc old = povray::parsePovRay("#version 3.6;\n" + body, "scene.pov", povray::PovRayOptions{{}, 320, 240, false});
  CHECK(old.objects[1].material.ambient.r == Approx(0.1f));  // 0.2 · 0.5
  CHECK(old.objects[0].texture->at(glm::dvec3(0)).ambient.r == Approx(0.6f));
}
