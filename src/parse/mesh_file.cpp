#include "raytrace/parse/mesh_file.hpp"

#include <cmath>

#include "raytrace/parse/scene_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/limits.hpp"
#include "raytrace/util/message.hpp"
#include "raytrace/util/path.hpp"

namespace rt {

namespace mesh_file {

std::string lineOf(const std::string& name, uint64_t line) {
  return printable(name, kMaxQuotedPath) + ":" + std::to_string(line);
}

void checkMemory(const std::string& where, uint64_t bytes) {
  const std::string shortage = memoryShortage("the mesh", bytes, availableMemory());
  if (!shortage.empty()) throw MeshFileError(where, shortage);
}

void checkFinite(const std::string& where, const glm::dvec3& value, const char* what) {
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(value[k])) throw MeshFileError(where, std::string(what) + " is not a finite number");
  }
}

void checkNotEmpty(const std::string& name, const MeshFile& mesh) {
  if (mesh.faces.empty()) throw MeshFileError(printable(name, kMaxQuotedPath), "the mesh has no triangles");
}

}  // namespace mesh_file

MeshFile readMeshFile(const std::string& path) {
  const std::string kind = extension(path);
  if (kind != "obj" && kind != "ply") {
    throw Error("cannot read " + quote(path, kMaxQuotedPath) + ": convert reads .obj and .ply files");
  }
  const FileText text = readFile(path);
  return kind == "obj" ? readObj(text.view(), path) : readPly(text.view(), path);
}

}  // namespace rt
