// `raytrace convert` (app/convert.cpp): OBJ and PLY meshes written as mesh2 includes that a scene reads back
// to the same triangles, and the command's refusals, after which no file is written.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "command_error.hpp"
#include "pov_scene.hpp"
#include "raytrace/app/commands.hpp"
#include "raytrace/app/convert.hpp"
#include "raytrace/shapes/mesh.hpp"
#include "temp_dir.hpp"

using namespace rt;
using rt::test::errorOf;
using rt::test::TempDir;

namespace {

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The mesh2 `name` the include at `path` declares, as a scene reads it.
const MeshData& readBack(const std::string& path, const std::string& name, SceneDesc& scene) {
  scene = test::pov("#include \"" + path + "\"\nobject { " + name + " }\n");
  REQUIRE(scene.objects.size() == 1);
  return *std::get<MeshDesc>(scene.objects[0].shape).data;
}

// Every triangle of `m` as the include gives it back: the same corners, normals and uvs.
void checkSame(const MeshFile& m, const MeshData& back) {
  REQUIRE(back.faces.size() == m.faces.size());
  for (size_t i = 0; i < m.faces.size(); ++i) {
    for (size_t k = 0; k < 3; ++k) {
      CHECK(back.vertices[back.faces[i].v[k]] == m.vertices[m.faces[i].v[k]]);
      if (!m.normals.empty()) CHECK(back.normals[size_t(back.faces[i].n[k])] == m.normals[m.faces[i].n[k]]);
      if (!m.uvs.empty()) CHECK(back.uvs[size_t(back.faces[i].uv[k])] == m.uvs[m.faces[i].uv[k]]);
    }
  }
}

}  // namespace

TEST_CASE("convert: an OBJ's include reads back as the same triangles, normals and uvs", "[convert]") {
  const TempDir dir;
  const std::string obj = dir.write("my-model.obj",
                                    "v 0.1 -2.5e-7 3\nv 1e+30 0 1\nv 0.3333333333333333 1 0\nv -0 1 1\n"
                                    "vn 0 0 1\nvn 0.6 0 0.8\nvt 0.25 0.75\nvt 1 0\n"
                                    "f 1/1/1 2/2/2 3/1/1 4/2/2\nf 1 3 4\n");
  CHECK(errorOf({"convert", obj, dir.file("m.inc")}).empty());
  const std::string text = contents(dir.file("m.inc"));
  CHECK(text.find("#declare My_model = mesh2 {\n  vertex_vectors {\n    4,\n    <0.1, -2.5e-07, 3>,\n") !=
        std::string::npos);
  SceneDesc scene;
  const MeshData& back = readBack(dir.file("m.inc"), "My_model", scene);
  checkSame(readObj(contents(obj), obj), back);
  CHECK(back.faces.size() == 3);
  CHECK(back.vertices[2].x == 0.3333333333333333);
}

TEST_CASE("convert: a PLY's include reads back the same, a binary one's floats in a float's digits", "[convert]") {
  const TempDir dir;
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty float u\nproperty float v\nelement face 1\nproperty list uchar int vertex_index\n"
      "end_header\n";
  for (const float f : {0.1f, 0.f, 0.f, 0.5f, 0.25f, 1.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f}) {
    ply.append(reinterpret_cast<const char*>(&f), 4);
  }
  ply += std::string(1, '\3');
  for (const int i : {0, 1, 2}) ply.append(reinterpret_cast<const char*>(&i), 4);
  const std::string path = dir.write("tri.ply", ply);
  CHECK(errorOf({"convert", path, dir.file("tri.inc"), "--name", "Tri2"}).empty());
  const std::string text = contents(dir.file("tri.inc"));
  CHECK(text.find("<0.1, 0, 0>") != std::string::npos);  // 0.1f in the digits it needs as a float
  SceneDesc scene;
  const MeshData& back = readBack(dir.file("tri.inc"), "Tri2", scene);
  REQUIRE(back.faces.size() == 1);
  CHECK(back.vertices[0].x == 0.1);  // what the digits say, as POV-Ray reads them
  CHECK(back.uvs[size_t(back.faces[0].uv[0])] == glm::dvec2(0.5, 0.25));
  CHECK(back.vertices[1] == glm::dvec3(1, 0, 0));
}

TEST_CASE("convert: names from files", "[convert]") {
  CHECK(meshName("a/b.c/model.obj") == "Model");
  CHECK(meshName("my model.v2.ply") == "My_model_v2");
  CHECK(meshName("3d.obj") == "Mesh_3d");
  CHECK(meshName("x/.obj") == "Mesh__obj");
  CHECK(meshName("sphere.obj") == "Sphere");  // not the keyword
}

TEST_CASE("convert: refusals, and no file written after one", "[convert]") {
  const TempDir dir;
  const std::string good = dir.write("good.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string bad = dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  CHECK(errorOf({"convert", bad, dir.file("out.inc")}) ==
        dir.file("bad.obj") + ":4: error: vertex index 4 is not one of the 3 vertices so far");
  CHECK(errorOf({"convert", dir.write("empty.ply", ""), dir.file("out.inc")}) ==
        dir.file("empty.ply") + ":1: error: the header ends before its end_header line");
  CHECK(errorOf({"convert", good, good}) ==
        "cannot write '" + good + "': it is the mesh file, which the include would replace");
  CHECK(errorOf({"convert", good, dir.path() + "/../" + dir.path().substr(dir.path().rfind('/') + 1) + "/good.obj"})
            .find("it is the mesh file") != std::string::npos);
  CHECK(errorOf({"convert", good}) ==
        "convert takes the mesh file and the include to write, found 1 file (see raytrace help convert)");
  CHECK(errorOf({"convert", good, "a.inc", "b.inc"}) ==
        "convert takes the mesh file and the include to write, found 3 files (see raytrace help convert)");
  CHECK(errorOf({"convert", good, "a.inc", "--scale", "2"}) ==
        "unknown option '--scale' for convert (see raytrace help convert)");
  CHECK(errorOf({"convert", good, "a.inc", "--name"}) == "--name needs a value");
  for (const char* name : {"mesh2", "pi", "3D", "my-mesh", ""}) {
    CHECK(errorOf({"convert", good, "a.inc", "--name", name}) ==
          "--name must be a POV-Ray identifier (a letter, then letters, digits and _, not a keyword), found '" +
              std::string(name) + "'");
  }
  CHECK(errorOf({"convert", dir.write("model.stl", ""), dir.file("out.inc")}) ==
        "cannot read '" + dir.file("model.stl") + "': convert reads .obj and .ply files");
  CHECK(errorOf({"convert", dir.file("missing.obj"), dir.file("out.inc")}) ==
        "cannot open '" + dir.file("missing.obj") + "': No such file or directory");
  CHECK(dir.names() == std::vector<std::string>{"bad.obj", "empty.ply", "good.obj", "model.stl"});
}

TEST_CASE("convert: its help", "[convert]") {
  std::ostringstream out, err;
  CHECK(runCommand({"help", "convert"}, out, err) == 0);
  CHECK(out.str() ==
        "usage: raytrace convert <mesh.obj|.ply> <mesh.inc> [--name NAME]\n"
        "an OBJ or PLY mesh written as a POV-Ray mesh2 include, its normals and uv kept\n"
        "options:\n"
        "  --name NAME                     the identifier the include declares (default: the mesh file's name,\n"
        "                                  capitalised: model.obj declares Model)\n");
}
