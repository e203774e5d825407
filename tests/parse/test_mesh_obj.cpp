// Wavefront OBJ files read for `raytrace convert` (parse/mesh_obj.cpp): vertices, normals and uvs with their
// indices as written, polygons fanned, and each broken file's whole message.
#include <catch2/catch.hpp>
#include <string>

#include "raytrace/parse/mesh_file.hpp"
#include "raytrace/util/error.hpp"

using namespace rt;

namespace {

std::string failure(const std::string& text) {
  try {
    readObj(text, "bad.obj");
  } catch (const MeshFileError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("an OBJ's vertices, normals, uvs and faces are kept as written, polygons fanned", "[mesh_file]") {
  const MeshFile m = readObj(
      "# a square\nv 0 0 0\nv 1 0 0.5\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvn 0 0.6 0.8\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "g top\nusemtl red\nf 1/1/1 2/2/2 3/3/1 -1/-1/-2\n",
      "square.obj");
  REQUIRE(m.vertices.size() == 4);
  CHECK(m.vertices[1] == glm::dvec3(1, 0, 0.5));
  REQUIRE(m.normals.size() == 2);
  CHECK(m.normals[1] == glm::dvec3(0, 0.6, 0.8));
  REQUIRE(m.uvs.size() == 4);
  CHECK(m.uvs[2] == glm::dvec2(1, 1));
  REQUIRE(m.faces.size() == 2);
  CHECK(m.faces[0].v == std::array<uint32_t, 3>{0, 1, 2});
  CHECK(m.faces[1].v == std::array<uint32_t, 3>{0, 2, 3});
  CHECK(m.faces[0].n == std::array<uint32_t, 3>{0, 1, 0});
  CHECK(m.faces[1].n == std::array<uint32_t, 3>{0, 0, 0});  // −2 of 2 normals: the first
  CHECK(m.faces[1].uv == std::array<uint32_t, 3>{0, 2, 3});
  CHECK_FALSE(m.singlePrecision);
}

TEST_CASE("an OBJ face without normals beside faces with them gets its plane's, without uvs uv (0, 0)", "[mesh_file]") {
  const MeshFile m =
      readObj("v 0 0 0\nv 2 0 0\nv 0 0 3\nvn 0 0 1\nvt 0.5 0.5\nf 1/1/1 2/1/1 3/1/1\nf 1 3 2\n", "m.obj");
  REQUIRE(m.normals.size() == 2);
  CHECK(m.normals[1] == glm::dvec3(0, 6, 0));  // (2, 0, 0) × (0, 0, 3) reversed: corners 1, 3, 2
  CHECK(m.faces[1].n == std::array<uint32_t, 3>{1, 1, 1});
  REQUIRE(m.uvs.size() == 2);
  CHECK(m.uvs[1] == glm::dvec2(0, 0));
  CHECK(m.faces[1].uv == std::array<uint32_t, 3>{1, 1, 1});
}

TEST_CASE("an OBJ whose faces name no normals or uvs has none, whatever its lines end with", "[mesh_file]") {
  const MeshFile m = readObj("v 0 0 0\r\nv 1 0 0 # a comment\r\nv 0 1 0 1 0.5 0.25\r\nvt 0.5\rf 1 2 3", "m.obj");
  CHECK(m.faces.size() == 1);
  CHECK(m.vertices[2] == glm::dvec3(0, 1, 0));  // a vertex's colour read past
  CHECK(m.normals.empty());
  CHECK(m.uvs.empty());  // no face names the uv
}

TEST_CASE("a broken OBJ stops at its line with one message", "[mesh_file]") {
  const std::string v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  CHECK(failure(v3 + "f 1 2 4\n") == "bad.obj:4: error: vertex index 4 is not one of the 3 vertices so far");
  CHECK(failure(v3 + "f 0 1 2\n") == "bad.obj:4: error: vertex index 0 is not one of the 3 vertices so far");
  CHECK(failure(v3 + "f -4 1 2\n") == "bad.obj:4: error: vertex index -4 is not one of the 3 vertices so far");
  // A face names only what came before it.
  CHECK(failure("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n") ==
        "bad.obj:3: error: vertex index 3 is not one of the 2 vertices so far");
  CHECK(failure(v3 + "vn 0 0 1\nf 1//1 2//2 3//1\n") ==
        "bad.obj:5: error: normal index 2 is not one of the 1 normals so far");
  CHECK(failure(v3 + "f 1/1 2/1 3/1\n") == "bad.obj:4: error: uv index 1 is not one of the 0 uvs so far");
  CHECK(failure(v3 + "\r\n\n# a comment\r\rf 1 2\n") == "bad.obj:8: error: a face needs 3 corners or more, found 2");
  CHECK(failure("v 0 0 0\nv 1e999 0 0\n") == "bad.obj:2: error: a vertex coordinate is not a finite number");
  CHECK(failure(v3 + "vn 0 -1e999 0\n") == "bad.obj:4: error: a normal coordinate is not a finite number");
  CHECK(failure(v3 + "vt 0 1e999\n") == "bad.obj:4: error: a uv coordinate is not a finite number");
  CHECK(failure("v 0 0 nan\n") == "bad.obj:1: error: a vertex coordinate is not a finite number");
  CHECK(failure("v 0 zero 0\n") == "bad.obj:1: error: expected a number, found 'zero'");
  CHECK(failure("v 0 0\n") == "bad.obj:1: error: a vertex needs 3 numbers, found 2");
  CHECK(failure("vn 0 1 # up\n") == "bad.obj:1: error: a normal needs 3 numbers, found 2");
  CHECK(failure("vt \n") == "bad.obj:1: error: a uv needs 1 number, found 0");
  CHECK(failure(v3) == "bad.obj: error: the mesh has no triangles");
  CHECK(failure("") == "bad.obj: error: the mesh has no triangles");
  // The last line without its line end is still counted.
  CHECK(failure(v3 + "f 1 2 9") == "bad.obj:4: error: vertex index 9 is not one of the 3 vertices so far");
}
