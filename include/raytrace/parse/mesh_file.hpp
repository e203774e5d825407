// Triangle meshes from OBJ and PLY files, for `raytrace convert` (src/app/convert.cpp), which writes them as
// POV-Ray mesh2 includes. Any bytes either read into a mesh or throw MeshFileError; nothing else escapes
// (fuzz/fuzz_mesh.cpp checks it).
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/util/error.hpp"

namespace rt {

// A problem at a place of a mesh file: what() reads "file:line: error: …", or "file:byte N: error: …" in a
// binary PLY's values, or "file: error: …" for the whole file. Printed as it is, as a ParseError.
class MeshFileError : public Error {
 public:
  MeshFileError(const std::string& where, const std::string& message) : Error(where + ": error: " + message) {}
};

struct MeshFile {
  // A triangle: its corners' indices into the vertices and, when the mesh has them, into the normals and uvs.
  struct Face {
    std::array<uint32_t, 3> v{}, n{}, uv{};
  };
  std::vector<glm::dvec3> vertices, normals;
  std::vector<glm::dvec2> uvs;
  std::vector<Face> faces;
  // Every value was read as a 32-bit float: written back with the digits a float needs, not a double's.
  bool singlePrecision = false;
};

// A Wavefront OBJ's `v`, `vn`, `vt` and `f` lines, read by tinyobjloader; a polygon is a fan of triangles from its
// first corner. `name` is the file's name, for the messages.
MeshFile readObj(std::string_view text, const std::string& name);

// A PLY file (ascii, binary_little_endian or binary_big_endian): the vertex element's x y z, nx ny nz and u v
// (or s t), the face element's vertex_indices (or vertex_index) lists, polygons fanned.
MeshFile readPly(std::string_view bytes, const std::string& name);

// The OBJ or PLY file at `path`, by its extension.
MeshFile readMeshFile(const std::string& path);

// What the readers share: the place of a problem, and the checks every mesh passes.
namespace mesh_file {

// "name:line" for the messages.
std::string lineOf(const std::string& name, uint64_t line);

// Throws "<where>: error: the mesh needs N MiB of memory, …" unless `bytes` more fit.
void checkMemory(const std::string& where, uint64_t bytes);

// Throws at `where` unless every value is finite and the mesh has a triangle.
void checkFinite(const std::string& where, const glm::dvec3& value, const char* what);
void checkNotEmpty(const std::string& name, const MeshFile& mesh);

}  // namespace mesh_file

}  // namespace rt
