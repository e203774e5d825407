// The POV transform steps and the matrix they compose to (transform.hpp), in either precision.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/geometry/transform.hpp"

using namespace rt;

namespace {

const char* kCamera = "camera { location <0, 0, 12> up <0, 1, 0> right <1.33333, 0, 0> look_at <0, 0, 0> }\n";
const char* kChain = "rotate <30, -45, 10> scale <0.5, 2, 1.25> translate <1.1, -0.3, 7> rotate <0, 0, -25>";

ObjectDesc parsed(const std::string& modifiers) {
  return parsePov(std::string(kCamera) + "sphere { <0, 0, 0>, 1 " + modifiers + " }", "t.pov").objects.at(0);
}

// The course reference's float composition, written out product by product (docs/reference/csc473.md §c.10).
glm::mat4 referenceRotation(glm::vec3 degrees) {
  glm::mat4 r(1.f);
  r = glm::rotate(glm::mat4(1.f), glm::radians(degrees.z), glm::vec3(0, 0, 1)) * r;
  r = glm::rotate(glm::mat4(1.f), glm::radians(degrees.y), glm::vec3(0, 1, 0)) * r;
  r = glm::rotate(glm::mat4(1.f), glm::radians(degrees.x), glm::vec3(1, 0, 0)) * r;
  return r;
}

}  // namespace

TEST_CASE("transform: the parser keeps the steps in file order", "[transform]") {
  const ObjectDesc o = parsed(kChain);
  REQUIRE(o.transforms.size() == 4);
  CHECK(o.transforms[0].kind == TransformStep::Kind::Rotate);
  CHECK(o.transforms[0].v == glm::dvec3(30, -45, 10));
  CHECK(o.transforms[1].kind == TransformStep::Kind::Scale);
  CHECK(o.transforms[1].v == glm::dvec3(0.5, 2, 1.25));
  CHECK(o.transforms[2].kind == TransformStep::Kind::Translate);
  CHECK(o.transforms[2].v == glm::dvec3(1.1, -0.3, 7));
  CHECK(o.transforms[3].kind == TransformStep::Kind::Rotate);
  CHECK(parsed("scale 3").transforms.at(0).v == glm::dvec3(3));  // POV-Ray's uniform scale
  CHECK(parsed("").transforms.empty());
}

TEST_CASE("transform: worldFromObject is the steps composed in double", "[transform]") {
  // translate, then scale: M = S·T takes the origin to 2·(1, 0, 0).
  CHECK(parsed("translate <1, 0, 0> scale 2").worldFromObject() ==
        glm::scale(glm::dmat4(1.0), glm::dvec3(2)) * glm::translate(glm::dmat4(1.0), glm::dvec3(1, 0, 0)));
  CHECK(parsed("").worldFromObject() == glm::dmat4(1.0));
}

// The course tier needs the reference's float matrix to the last bit: each step multiplied on the left in
// float, every rotation built from Rz, Ry, Rx in that order.
TEST_CASE("transform: the float composition is the course reference's, bit for bit", "[transform]") {
  glm::mat4 expected(1.f);
  expected = referenceRotation({30, -45, 10}) * expected;
  expected = glm::scale(glm::mat4(1.f), glm::vec3(0.5f, 2, 1.25f)) * expected;
  expected = glm::translate(glm::mat4(1.f), glm::vec3(1.1f, -0.3f, 7)) * expected;
  expected = referenceRotation({0, 0, -25}) * expected;
  const glm::mat4 got = composeTransforms<float>(parsed(kChain).transforms);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      CAPTURE(c, r);
      CHECK(got[c][r] == expected[c][r]);
    }
  }
  // Not the double matrix rounded: the float products round differently.
  CHECK(got != glm::mat4(composeTransforms<double>(parsed(kChain).transforms)));
}

TEST_CASE("transform: POV-Ray's matrix takes (x, y, z) to x·row 0 + y·row 1 + z·row 2 + row 3", "[transform]") {
  const auto pov = [](const std::string& body) {
    return povray::parsePovRay("#version 3.7;\n" + body, "scene.pov", povray::PovRayOptions{{}, 320, 240, false});
  };
  // A shear of y into x, then a move: the manual's §3.3.1.12.4 layout.
  const SceneDesc s = pov("sphere { 0, 1 translate z matrix <1,0,0, 0.5,1,0, 0,0,2, 1,2,3> }\n");
  const ObjectDesc& o = s.objects.at(0);
  REQUIRE(o.transforms.size() == 2);
  CHECK(o.transforms[1].kind == TransformStep::Kind::Matrix);
  const glm::dmat4 m = o.worldFromObject();
  CHECK(glm::dvec3(m * glm::dvec4(0, 1, 0, 1)) == glm::dvec3(1.5, 3, 5));  // (0, 1, 1) sheared, then moved
  CHECK(glm::dvec3(m * glm::dvec4(1, 0, 0, 1)) == glm::dvec3(2, 2, 5));
  // In a pigment and a camera too, where every transform is read.
  CHECK_NOTHROW(pov("camera { location -5*z look_at 0 matrix <1,0,0, 0,1,0, 0,0,1, 0,1,0> }\n"
                    "plane { y, 0 pigment { checker matrix <2,0,0, 0,2,0, 0,0,2, 0,0,0> } }\n"));
  std::string message;
  try {
    pov("sphere { 0, 1 matrix <1, 2, 3> }\n");
  } catch (const Error& e) {
    message = e.what();
  }
  CHECK(message == "scene.pov:2:22: error: 'matrix' needs 12 numbers, found 3");
}
