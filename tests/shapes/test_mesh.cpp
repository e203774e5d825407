// POV-Ray's mesh and mesh2 (shapes/mesh.hpp, shapes/triangle_mesh): their triangles, smooth normals, the
// faces' own textures, inside_vector, and one copy of the triangles for every object showing them.
#include <memory>
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

std::unique_ptr<Object<double>> made(const ObjectDesc& o) {
  return makeObject<double>(o, SphereMethod::Auto, 1, false);
}

const Interval<double> kAll{};

}  // namespace

TEST_CASE("a mesh's flat and smooth triangles are hit, the smooth one with its corners' normals blended",
          "[mesh]") {
  const SceneDesc s = pov(
      "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> }\n"
      "       smooth_triangle { <0,0,1>, <0,0,-1>, <2,0,1>, <1,0,-1>, <0,2,1>, <0,1,-1> } }\n");
  REQUIRE(s.objects.size() == 1);
  const auto& mesh = std::get<MeshDesc>(s.objects[0].shape);
  CHECK(mesh.data->faces.size() == 2);
  CHECK(std::string(mesh.name()) == "Mesh");
  const auto object = made(s.objects[0]);
  const auto flat = object->intersect({{0.25, 0.25, -5}, {0, 0, 1}}, kAll);
  REQUIRE(flat);
  CHECK(flat->t == 5);
  CHECK(flat->normal == glm::dvec3(0, 0, 1));
  // Past the first triangle's hypotenuse, the ray meets the second one, at u = 0.25, v = 0.5 of its corners.
  const auto smooth = object->intersect({{0.5, 1, -5}, {0, 0, 1}}, kAll);
  REQUIRE(smooth);
  CHECK(smooth->t == 6);
  const glm::dvec3 blended = glm::normalize(0.25 * glm::dvec3(0, 0, -1) + 0.25 * glm::dvec3(1, 0, -1) +
                                            0.5 * glm::dvec3(0, 1, -1));
  CHECK(smooth->normal.x == Approx(blended.x));
  CHECK(smooth->normal.y == Approx(blended.y));
  CHECK(smooth->normal.z == Approx(blended.z));
  CHECK_FALSE(object->intersect({{1.5, 1.5, -5}, {0, 0, 1}}, kAll));
  const auto box = object->bounds();
  REQUIRE(box);
  CHECK(box->min == glm::dvec3(0, 0, 0));
  CHECK(box->max == glm::dvec3(2, 2, 1));
}

TEST_CASE("a mesh triangle's texture is its own, the others take the mesh's", "[mesh]") {
  const SceneDesc s = pov(
      "#declare Red = texture { pigment { rgb <1,0,0> } }\n"
      "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> texture { Red } }\n"
      "       triangle { <0,0,1>, <1,0,1>, <0,1,1> }\n"
      "       triangle { <0,0,2>, <1,0,2>, <0,1,2> texture { Red } }\n"
      "       pigment { rgb <0,0,1> } translate <0,0,-1> }\n");
  const auto& mesh = std::get<MeshDesc>(s.objects[0].shape);
  CHECK(mesh.surfaces.size() == 1);  // the two triangles naming Red share it
  const auto object = made(s.objects[0]);
  Material scratch;
  const auto front = object->intersect({{0.2, 0.2, -5}, {0, 0, 1}}, kAll);
  REQUIRE(front);
  CHECK(front->t == 4);
  CHECK(front->object->materialAt(*front, scratch).pigment == Color(1, 0, 0));
  const auto middle = object->intersect({{0.2, 0.2, -0.5}, {0, 0, 1}}, kAll);
  REQUIRE(middle);
  CHECK(middle->object->materialAt(*middle, scratch).pigment == Color(0, 0, 1));
}

TEST_CASE("a mesh2's faces index its vertices, normals and textures", "[mesh]") {
  const SceneDesc s = pov(
      "mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }\n"
      "        normal_vectors { 4, <0,0,-1>, <0,0,-1>, <0,0,-1>, <0,0,-1> }\n"
      "        texture_list { 2, texture { pigment { rgb <1,0,0> } } texture { pigment { rgb <0,1,0> } } }\n"
      "        face_indices { 2, <0,1,2>, 1, <0,2,3> }\n"
      "        pigment { rgb <0,0,1> } }\n");
  const auto& mesh = std::get<MeshDesc>(s.objects[0].shape);
  REQUIRE(mesh.data->faces.size() == 2);
  CHECK(mesh.data->faces[0].surface == 1);
  CHECK(mesh.data->faces[1].surface == -1);
  // As many normals as vertices, and no normal_indices: the vertex indices index the normals.
  CHECK(mesh.data->faces[1].n == std::array<int32_t, 3>{{0, 2, 3}});
  const auto object = made(s.objects[0]);
  Material scratch;
  const auto lower = object->intersect({{0.75, 0.25, -1}, {0, 0, 1}}, kAll);
  REQUIRE(lower);
  CHECK(lower->object->materialAt(*lower, scratch).pigment == Color(0, 1, 0));
  CHECK(lower->normal == glm::dvec3(0, 0, -1));
  const auto upper = object->intersect({{0.25, 0.75, -1}, {0, 0, 1}}, kAll);
  REQUIRE(upper);
  CHECK(upper->object->materialAt(*upper, scratch).pigment == Color(0, 0, 1));
}

TEST_CASE("every object showing a declared mesh shares its triangles and their hierarchy", "[mesh]") {
  const SceneDesc s = pov(
      "#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }\n"
      "object { M translate x }\nobject { M translate 2*x }\nobject { M }\n");
  REQUIRE(s.objects.size() == 3);
  const auto& a = std::get<MeshDesc>(s.objects[0].shape);
  const auto& b = std::get<MeshDesc>(s.objects[1].shape);
  const auto& c = std::get<MeshDesc>(s.objects[2].shape);
  CHECK(a.data == b.data);
  CHECK(a.data == c.data);
  CHECK(a.data->geometry<float>() == c.data->geometry<float>());
  const auto moved = made(s.objects[1]);
  const auto hit = moved->intersect({{2.25, 0.25, -1}, {0, 0, 1}}, kAll);
  REQUIRE(hit);
  CHECK(hit->point == glm::dvec3(2.25, 0.25, 0));
}

TEST_CASE("a mesh with an inside_vector has an inside: where a ray that way crosses it an odd number of times",
          "[mesh]") {
  const std::string tetrahedron =
      "triangle { <0,0,0>, <1,0,0>, <0,1,0> } triangle { <0,0,0>, <0,1,0>, <0,0,1> }\n"
      "triangle { <0,0,0>, <0,0,1>, <1,0,0> } triangle { <1,0,0>, <0,1,0>, <0,0,1> }\n";
  const auto solid = made(pov("mesh { " + tetrahedron + " inside_vector <1, 0.1, 0.2> }\n").objects[0]);
  CHECK(solid->inside({0.1, 0.2, 0.3}));
  CHECK_FALSE(solid->inside({0.5, 0.5, 0.5}));
  CHECK_FALSE(solid->inside({-0.1, 0.2, 0.3}));
  const auto hollow = made(pov("mesh { " + tetrahedron + " }\n").objects[0]);
  CHECK_FALSE(hollow->inside({0.1, 0.2, 0.3}));
}

TEST_CASE("an empty mesh, and a mesh2 index past its list, are errors where they are written", "[mesh]") {
  CHECK(povFailure("mesh { }\n") == "scene.pov:2:1: error: the mesh has no triangles");
  CHECK(povFailure("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
                   "        face_indices { 1, <0,1,3> } }\n") ==
        "scene.pov:3:27: error: index 3 is out of range for the 3 vertex_vectors");
  CHECK(povFailure("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
                   "        face_indices { 1, <0,1,2>, 0 } }\n") ==
        "scene.pov:3:36: error: index 0 is out of range for the 0 textures of texture_list");
  CHECK(povFailure("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n"
                   "        normal_vectors { 1, y } face_indices { 1, <0,1,2> } normal_indices { 1, <0,0,1> } }\n") ==
        "scene.pov:3:81: error: index 1 is out of range for the 1 normal_vectors");
}

TEST_CASE("a mesh2's uv vectors are blended over a face, and a uv_mapping texture reads them, not the point",
          "[mesh][uv]") {
  const SceneDesc s = pov(
      "mesh2 { vertex_vectors { 3, <0,0,0>, <4,0,0>, <0,4,0> }\n"
      "        uv_vectors { 3, <0.5,0>, <0,0.5>, <0.25,1> }\n"
      "        face_indices { 1, <0,1,2> }\n"
      "        uv_indices { 1, <2,1,0> }\n"
      "        uv_mapping pigment { gradient x color_map { [0 rgb 0] [1 rgb <1,0,0>] } }\n"
      "        translate <10,0,0> }\n");
  const auto object = made(s.objects[0]);
  // At a quarter of the way to corner 1 and half to corner 2: 0.25·(0, 0.5) + 0.5·(0.5, 0) + 0.25·(0.25, 1).
  const auto hit = object->intersect({{11, 2, -1}, {0, 0, 1}}, kAll);
  REQUIRE(hit);
  CHECK(hit->uv.x == Approx(0.3125));
  CHECK(hit->uv.y == Approx(0.375));
  Material scratch;
  CHECK(hit->object->materialAt(*hit, scratch).pigment.r == Approx(0.3125));
}

TEST_CASE("a mesh triangle's uv_vectors, and a bicubic patch's corners' uv, default or given", "[mesh][uv]") {
  const SceneDesc s = pov(
      "mesh { triangle { <0,0,0>, <2,0,0>, <0,2,0> uv_vectors <0,0>, <1,0>, <0,1> } }\n"
      "bicubic_patch { type 1 u_steps 2 v_steps 2\n"
      "  <0,0,0>, <1,0,0>, <2,0,0>, <3,0,0>, <0,1,0>, <1,1,0>, <2,1,0>, <3,1,0>,\n"
      "  <0,2,0>, <1,2,0>, <2,2,0>, <3,2,0>, <0,3,0>, <1,3,0>, <2,3,0>, <3,3,0> }\n"
      "bicubic_patch { type 1 u_steps 2 v_steps 2 uv_vectors <0,0>, <2,0>, <2,4>, <0,4>\n"
      "  <0,0,0>, <1,0,0>, <2,0,0>, <3,0,0>, <0,1,0>, <1,1,0>, <2,1,0>, <3,1,0>,\n"
      "  <0,2,0>, <1,2,0>, <2,2,0>, <3,2,0>, <0,3,0>, <1,3,0>, <2,3,0>, <3,3,0> }\n");
  REQUIRE(s.objects.size() == 3);
  const auto triangle = made(s.objects[0])->intersect({{0.5, 1, -1}, {0, 0, 1}}, kAll);
  REQUIRE(triangle);
  CHECK(triangle->uv.x == Approx(0.25));
  CHECK(triangle->uv.y == Approx(0.5));
  // The patch is the square of side 3 in x and y, evenly spaced: u runs along a row of control points (x).
  // With uv_vectors <0,0>, <2,0>, <2,4>, <0,4>, u is twice as large and v four times.
  const glm::dvec2 scale[] = {{1, 1}, {2, 4}};
  for (size_t i : {size_t(1), size_t(2)}) {
    const auto patch = made(s.objects[i])->intersect({{0.75, 2.25, -1}, {0, 0, 1}}, kAll);
    REQUIRE(patch);
    CHECK(patch->uv.x == Approx(0.25 * scale[i - 1].x));
    CHECK(patch->uv.y == Approx(0.75 * scale[i - 1].y));
  }
}

TEST_CASE("uv_mapping is refused on a shape without uv coordinates and with a normal", "[mesh][uv]") {
  CHECK(povFailure("sphere { 0, 1 uv_mapping pigment { checker } }\n") ==
        "scene.pov:2:1: error: 'uv_mapping on a Sphere' is not supported yet");
  CHECK(povFailure("mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } texture { uv_mapping normal { bumps } } }\n") ==
        "scene.pov:2:1: error: 'uv_mapping of a normal' is not supported yet");
}
