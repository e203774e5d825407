// POV-Ray's bicubic_patch (shapes/bicubic_patch): the Bézier surface at its grid's corners, in 2^u_steps by
// 2^v_steps pieces of two smooth triangles.
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/shapes/make_object.hpp"
#include "raytrace/shapes/mesh.hpp"

#include "pov_scene.hpp"

using namespace rt;
using rt::test::pov;
using rt::test::povFailure;

namespace {

// The manual's example patch, its corners at z = 2, 2, -2, -2 and its inner points at z = 0.
const std::string kPoints =
    "<0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0,-2>, <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,\n"
    "<0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>, <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>";

}  // namespace

TEST_CASE("a bicubic patch is 2^u_steps by 2^v_steps pieces of two triangles on its surface", "[bicubic_patch]") {
  const SceneDesc s = pov("bicubic_patch { type 1 flatness 0.01 u_steps 2 v_steps 1\n" + kPoints + " }\n");
  const auto& mesh = std::get<MeshDesc>(s.objects[0].shape);
  CHECK(std::string(mesh.name()) == "BicubicPatch");
  const MeshData& m = *mesh.data;
  REQUIRE(m.vertices.size() == 5 * 3);
  CHECK(m.faces.size() == 4 * 2 * 2);
  // The corners are the corner points. u runs across the rows (y here), v along them (x); the vertices go
  // along u first.
  CHECK(m.vertices[0] == glm::dvec3(0, 0, 2));
  CHECK(m.vertices[4] == glm::dvec3(0, 3, 2));
  CHECK(m.vertices[10] == glm::dvec3(3, 0, -2));
  CHECK(m.vertices[14] == glm::dvec3(3, 3, -2));
  // The middle of the first row, where B(1/2) weights 1/8, 3/8, 3/8, 1/8: x = 1.5, z = (2 − 2)/8 = 0.
  CHECK(m.vertices[5] == glm::dvec3(1.5, 0, 0));
  // Every face is smooth: the surface's normal is defined at every grid point of this patch.
  for (const MeshData::Face& f : m.faces) CHECK(f.n[0] >= 0);
  const auto object = makeObject<double>(s.objects[0], SphereMethod::Auto, 1, false);
  const auto hit = object->intersect({{1.5, 1.5, -5}, {0, 0, 1}}, Interval<double>{});
  REQUIRE(hit);
  CHECK(hit->t == Approx(5));  // the patch's centre, a grid point: z = (2 − 2 + 2 − 2)/64 = 0
}

TEST_CASE("a bicubic patch without its type, or with a type or steps POV-Ray refuses, is an error",
          "[bicubic_patch]") {
  CHECK(povFailure("bicubic_patch { u_steps 2\n" + kPoints + " }\n") ==
        "scene.pov:2:17: error: 'bicubic_patch' needs its type");
  CHECK(povFailure("bicubic_patch { type 2\n" + kPoints + " }\n") ==
        "scene.pov:2:17: error: the patch type must be 0 or 1, found 2");
  CHECK(povFailure("bicubic_patch { type 0 u_steps 11\n" + kPoints + " }\n") ==
        "scene.pov:2:32: error: the patch steps must be a whole number from 0 to 10, found 11");
}
