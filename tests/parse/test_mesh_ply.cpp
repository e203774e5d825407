// PLY files read for `raytrace convert` (parse/mesh_ply.cpp): ascii and both binary byte orders, the vertex
// element's positions, normals and uvs, faces fanned, other elements read past, and each broken file's whole
// message (at a line of the header or of an ascii body, at a byte of a binary one).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstring>
#include <limits>
#include <string>

#include "raytrace/parse/mesh_file.hpp"
#include "raytrace/util/error.hpp"

using namespace rt;

namespace {

std::string failure(const std::string& bytes) {
  try {
    readPly(bytes, "bad.ply");
  } catch (const MeshFileError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kHeader =
    "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty float s\n"
    "property float t\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";  // 15 lines

const std::string kVertices = "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n0 1 0 0.6 0 0.8 0 1\n";

// The bytes of `value` in the byte order `big` or not.
template <class T>
std::string bytes(T value, bool big) {
  std::string out(sizeof value, '\0');
  std::memcpy(out.data(), &value, sizeof value);
  if (big) std::reverse(out.begin(), out.end());
  return out;
}

std::string binaryTriangle(bool big, float x = 0) {
  std::string b = "ply\nformat " + std::string(big ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty double z\n"
                  "element face 1\nproperty list uchar uint vertex_indices\nelement edge 1\nproperty short a\n"
                  "end_header\n";
  const auto vertex = [&](float px, float py, double pz) { b += bytes(px, big) + bytes(py, big) + bytes(pz, big); };
  vertex(x, 0, 1);
  vertex(1, 0, 0);
  vertex(0, 1, 0.1);
  b += bytes(uint8_t(3), big) + bytes(uint32_t(0), big) + bytes(uint32_t(1), big) + bytes(uint32_t(2), big);
  return b + bytes(int16_t(-7), big);
}

}  // namespace

TEST_CASE("an ascii PLY's vertices, normals, uvs and polygons", "[mesh_file]") {
  const MeshFile m = readPly(kHeader + kVertices + "4 0 1 2 3\n", "square.ply");
  REQUIRE(m.vertices.size() == 4);
  CHECK(m.vertices[2] == glm::dvec3(1, 1, 0));
  REQUIRE(m.normals.size() == 4);
  CHECK(m.normals[3] == glm::dvec3(0.6, 0, 0.8));
  REQUIRE(m.uvs.size() == 4);
  CHECK(m.uvs[1] == glm::dvec2(1, 0));
  REQUIRE(m.faces.size() == 2);
  CHECK(m.faces[1].v == std::array<uint32_t, 3>{0, 2, 3});
  CHECK(m.faces[1].n == m.faces[1].v);
  CHECK(m.faces[1].uv == m.faces[1].v);
  CHECK_FALSE(m.singlePrecision);  // the text's numbers, read as doubles
}

TEST_CASE("a binary PLY in either byte order, other elements read past", "[mesh_file]") {
  for (const bool big : {false, true}) {
    const MeshFile m = readPly(binaryTriangle(big), "triangle.ply");
    REQUIRE(m.vertices.size() == 3);
    CHECK(m.vertices[0] == glm::dvec3(0, 0, 1));
    CHECK(m.vertices[1] == glm::dvec3(1, 0, 0));
    CHECK(m.vertices[2] == glm::dvec3(0, 1, 0.1));  // z a double property
    REQUIRE(m.faces.size() == 1);
    CHECK(m.faces[0].v == std::array<uint32_t, 3>{0, 1, 2});
    CHECK(m.normals.empty());
    CHECK_FALSE(m.singlePrecision);  // z is a double
  }
}

TEST_CASE("a broken PLY header stops at its line with one message", "[mesh_file]") {
  CHECK(failure("PLY\n") == "bad.ply:1: error: a PLY file begins with the line \"ply\"");
  CHECK(failure("ply\nformat ascii 1.0\nelement vertex 3\n") ==
        "bad.ply:4: error: the header ends before its end_header line");
  CHECK(failure("ply\nformat ascii 2.0\n") ==
        "bad.ply:2: error: the format line must be: format <ascii | binary_little_endian | binary_big_endian> 1.0");
  CHECK(failure("ply\nformat binary 1.0\n") ==
        "bad.ply:2: error: unknown format 'binary' (ascii, binary_little_endian, binary_big_endian)");
  CHECK(failure("ply\nformat ascii 1.0\nelement vertex -3\n") ==
        "bad.ply:3: error: an element count must be a whole number, found '-3'");
  CHECK(failure("ply\nformat ascii 1.0\nproperty float x\n") == "bad.ply:3: error: a property before any element");
  CHECK(failure("ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\n") ==
        "bad.ply:4: error: unknown property type 'real' (char, uchar, short, ushort, int, uint, float, double)");
  CHECK(failure("ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\n") ==
        "bad.ply:4: error: a list's count type must be an integer type, found 'float'");
  CHECK(failure("ply\nformat ascii 1.0\nelement vertex 1\nelement vertex 1\n") ==
        "bad.ply:4: error: a second 'vertex' element");
  CHECK(failure("ply\nformat ascii 1.0\nCreated by hand\n") ==
        "bad.ply:3: error: a header line begins with format, element, property, comment, obj_info or end_header, "
        "found 'Created'");
  CHECK(failure("ply\nelement vertex 0\nend_header\n") == "bad.ply:3: error: the header has no format line");
  CHECK(failure("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n") ==
        "bad.ply:3: error: the vertex element has no x, y and z properties");
  // An absurd count is refused before anything is allocated for it.
  CHECK(failure("ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
                "property float y\nproperty float z\nend_header\n0123456789ab") ==
        "bad.ply:3: error: 4000000000 vertex elements need more bytes than the file has after its header");
  CHECK(failure("ply\nformat ascii 1.0\nelement nothing 99999999999\nend_header\n") ==
        "bad.ply:3: error: the element 'nothing' has no properties");
}

TEST_CASE("a broken PLY body stops at its line, or its byte when binary, with one message", "[mesh_file]") {
  CHECK(failure(kHeader + kVertices) == "bad.ply:20: error: the file ends inside an element");
  CHECK(failure(kHeader + kVertices + "3 0 1 4\n") ==
        "bad.ply:20: error: vertex index 4 is not one of the 4 vertices (counted from 0)");
  CHECK(failure(kHeader + kVertices + "3 0 1 -1\n") ==
        "bad.ply:20: error: vertex index -1 is not one of the 4 vertices (counted from 0)");
  CHECK(failure(kHeader + kVertices + "\n\n2 0 1\n") == "bad.ply:22: error: a face needs 3 corners or more, found 2");
  CHECK(failure(kHeader + kVertices + "3 0 1 2.5\n") ==
        "bad.ply:20: error: expected a whole number (int), found '2.5'");
  CHECK(failure(kHeader + kVertices + "3 0 1 two\n") == "bad.ply:20: error: expected a number, found 'two'");
  CHECK(failure(kHeader + kVertices + "3 0 1 2\n3 0 1 2\n") ==
        "bad.ply:21: error: there is more after the last element's values");
  CHECK(failure(kHeader + kVertices + "200 0 1 2\n") ==
        "bad.ply:20: error: a list of 200 values is longer than the rest of the file");
  CHECK(failure(kHeader + "0 0 0 0 0 1 0 0\n1 inf 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n0 1 0 0 0 1 0 1\n3 0 1 2\n") ==
        "bad.ply:17: error: a vertex coordinate is not a finite number");
  CHECK(failure(kHeader + "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 nan 1 1 1\n0 1 0 0 0 1 0 1\n3 0 1 2\n") ==
        "bad.ply:18: error: a normal coordinate is not a finite number");
  CHECK(failure(kHeader + "0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n0 1 0 0 0 1 0 -inf\n3 0 1 2\n") ==
        "bad.ply:19: error: a uv coordinate is not a finite number");
  CHECK(failure("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                "end_header\n") == "bad.ply: error: the mesh has no triangles");
  // Binary: the header is 203 bytes, the vertices 3 × 16 (the last one's z at 243), the face 13 (from 251).
  const std::string good = binaryTriangle(false);
  REQUIRE(good.size() == 203 + 48 + 13 + 2);
  CHECK(failure(good.substr(0, 203 + 47)) == "bad.ply:byte 243: error: the file ends inside an element");
  std::string index = good;
  index[251 + 9] = 3;  // the last corner
  CHECK(failure(index) == "bad.ply:byte 251: error: vertex index 3 is not one of the 3 vertices (counted from 0)");
  std::string count = good;
  count[251] = 2;
  CHECK(failure(count) == "bad.ply:byte 251: error: a face needs 3 corners or more, found 2");
  // binary_big_endian is 3 letters shorter than binary_little_endian.
  CHECK(failure(binaryTriangle(true, std::numeric_limits<float>::quiet_NaN())) ==
        "bad.ply:byte 200: error: a vertex coordinate is not a finite number");
}
