// Wavefront OBJ through tinyobjloader's callback interface: it splits the lines and the faces' corners, and the
// callbacks here keep the mesh, resolve the 1-based and negative (relative) indices and check them, each
// problem located at its line. A v, vn or vt line's numbers are read again with strtod: tinyobjloader's own
// reading is not correctly rounded (0.6 comes out 0.6000000000000001) and reads a word that is no number as 0.
#include <cstdlib>
#include <istream>
#include <streambuf>

#define TINYOBJLOADER_USE_DOUBLE  // the library Debian builds as libtinyobjloader_double
#include <tiny_obj_loader.h>

#include "raytrace/parse/mesh_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"

namespace rt {

namespace {

using mesh_file::lineOf;

// The file's bytes as a stream, without a copy, telling how far tinyobjloader has read.
class TextBuffer : public std::streambuf {
 public:
  explicit TextBuffer(std::string_view text) {
    char* begin = const_cast<char*>(text.data());  // only ever read: a streambuf's pointers are not const
    setg(begin, begin, begin + text.size());
  }
  size_t offset() const { return size_t(gptr() - eback()); }
};

struct ObjReader {
  std::string_view text;
  const std::string& name;
  const TextBuffer& buffer;
  MeshFile mesh;
  std::vector<bool> faceHasNormals, faceHasUvs;
  // Where counting the lines has reached: the line ends before `scanned` and their count.
  size_t scanned = 0;
  uint64_t lines = 0;

  // "file:line" of the line tinyobjloader has just read: it calls back once past the line's end (\n, \r\n or \r,
  // as it splits them), or at the end of the file.
  std::string here() {
    const size_t end = buffer.offset();
    for (; scanned < end; ++scanned) {
      const char c = text[scanned];
      if (c == '\n' || (c == '\r' && (scanned + 1 == text.size() || text[scanned + 1] != '\n'))) ++lines;
    }
    const bool ended = end > 0 && (text[end - 1] == '\n' || text[end - 1] == '\r');
    return lineOf(name, lines + (ended ? 0 : 1));
  }

  // The line tinyobjloader has just read, without its end.
  std::string_view line() const {
    size_t end = buffer.offset();
    if (end > 0 && text[end - 1] == '\n') --end;
    if (end > 0 && text[end - 1] == '\r') --end;
    size_t start = end;
    while (start > 0 && text[start - 1] != '\n' && text[start - 1] != '\r') --start;
    return text.substr(start, end - start);
  }

  // The numbers after the line's keyword, `least` of them at least (more are read past: a vertex's colour), up
  // to a # comment.
  std::vector<double> numbers(size_t least, const char* what) {
    const std::string_view l = line();
    std::vector<double> out;
    size_t i = 0;
    bool keyword = true;
    for (;;) {
      while (i < l.size() && (l[i] == ' ' || l[i] == '\t')) ++i;
      if (i == l.size() || l[i] == '#') break;
      const size_t start = i;
      while (i < l.size() && l[i] != ' ' && l[i] != '\t') ++i;
      if (keyword) {
        keyword = false;
        continue;
      }
      const std::string word(l.substr(start, i - start));
      char* end = nullptr;
      const double v = std::strtod(word.c_str(), &end);
      if (*end) throw MeshFileError(here(), "expected a number, found " + quote(word));
      out.push_back(v);
    }
    if (out.size() < least) {
      throw MeshFileError(here(), std::string(what) + " needs " + std::to_string(least) +
                                      (least == 1 ? " number" : " numbers") + ", found " + std::to_string(out.size()));
    }
    return out;
  }

  // push_back, with the memory of a larger vector asked for first.
  template <class T>
  void add(std::vector<T>& list, const T& value) {
    if (list.size() == list.capacity()) mesh_file::checkMemory(here(), (2 * list.size() + 1) * sizeof(T));
    list.push_back(value);
  }

  void point(std::vector<glm::dvec3>& list, const glm::dvec3& p, const char* what) {
    mesh_file::checkFinite(here(), p, what);
    add(list, p);
  }

  // The 0-based index an OBJ index names among the `count` items so far (1 is the first, −1 the latest), or
  // a message.
  uint32_t resolve(int index, size_t count, const char* what, const char* whats) {
    const long long i = index > 0 ? index - 1LL : index + (long long)count;
    if (index == 0 || i < 0 || i >= (long long)count) {
      throw MeshFileError(here(), std::string(what) + " index " + std::to_string(index) + " is not one of the " +
                                      std::to_string(count) + " " + whats + " so far");
    }
    return uint32_t(i);
  }

  void face(const tinyobj::index_t* corners, int count) {
    if (count < 3) throw MeshFileError(here(), "a face needs 3 corners or more, found " + std::to_string(count));
    std::vector<MeshFile::Face> corner(static_cast<size_t>(count));
    bool normals = true, uvs = true;
    for (int k = 0; k < count; ++k) {
      const tinyobj::index_t& c = corners[k];
      corner[size_t(k)].v[0] = resolve(c.vertex_index, mesh.vertices.size(), "vertex", "vertices");
      // tinyobjloader gives 0 for a corner without a normal or uv (OBJ counts from 1).
      normals = normals && c.normal_index != 0;
      if (c.normal_index != 0)
        corner[size_t(k)].n[0] = resolve(c.normal_index, mesh.normals.size(), "normal", "normals");
      uvs = uvs && c.texcoord_index != 0;
      if (c.texcoord_index != 0) corner[size_t(k)].uv[0] = resolve(c.texcoord_index, mesh.uvs.size(), "uv", "uvs");
    }
    // A polygon is a fan of triangles from its first corner.
    for (size_t k = 1; k + 1 < corner.size(); ++k) {
      MeshFile::Face f;
      for (size_t j = 0; j < 3; ++j) {
        const MeshFile::Face& c = corner[j == 0 ? 0 : k + j - 1];
        f.v[j] = c.v[0];
        f.n[j] = c.n[0];
        f.uv[j] = c.uv[0];
      }
      add(mesh.faces, f);
      faceHasNormals.push_back(normals);
      faceHasUvs.push_back(uvs);
    }
  }

  // When some faces have normals (uvs), the others are given ones that change nothing: the face's own plane's
  // normal at each corner, uv (0, 0), which is the uv of a corner without one in mesh2 (the manual's §3.4.5.2.4).
  void complete() {
    const auto some = [](const std::vector<bool>& has) {
      for (const bool b : has) {
        if (b) return true;
      }
      return false;
    };
    if (!some(faceHasNormals)) mesh.normals.clear();
    if (!some(faceHasUvs)) mesh.uvs.clear();
    bool zeroUv = false;
    for (size_t i = 0; i < mesh.faces.size(); ++i) {
      MeshFile::Face& f = mesh.faces[i];
      if (!mesh.normals.empty() && !faceHasNormals[i]) {
        const glm::dvec3 n =
            glm::cross(mesh.vertices[f.v[1]] - mesh.vertices[f.v[0]], mesh.vertices[f.v[2]] - mesh.vertices[f.v[0]]);
        f.n.fill(uint32_t(mesh.normals.size()));
        add(mesh.normals, n == glm::dvec3(0) ? glm::dvec3(0, 1, 0) : n);  // a line or point: never hit
      }
      if (!mesh.uvs.empty() && !faceHasUvs[i]) {
        if (!zeroUv) add(mesh.uvs, glm::dvec2(0));
        zeroUv = true;
        f.uv.fill(uint32_t(mesh.uvs.size() - 1));
      }
    }
  }
};

}  // namespace

MeshFile readObj(std::string_view text, const std::string& name) {
  TextBuffer buffer(text);
  std::istream stream(&buffer);
  ObjReader reader{text, name, buffer, {}, {}, {}};
  tinyobj::callback_t callback;
  callback.vertex_cb = [](void* r, double, double, double, double) {
    auto& o = *static_cast<ObjReader*>(r);
    const std::vector<double> p = o.numbers(3, "a vertex");
    o.point(o.mesh.vertices, {p[0], p[1], p[2]}, "a vertex coordinate");
  };
  callback.normal_cb = [](void* r, double, double, double) {
    auto& o = *static_cast<ObjReader*>(r);
    const std::vector<double> n = o.numbers(3, "a normal");
    o.point(o.mesh.normals, {n[0], n[1], n[2]}, "a normal coordinate");
  };
  // A uv's v is 0 when not given (the OBJ format's default).
  callback.texcoord_cb = [](void* r, double, double, double) {
    auto& o = *static_cast<ObjReader*>(r);
    const std::vector<double> uv = o.numbers(1, "a uv");
    const glm::dvec2 p(uv[0], uv.size() > 1 ? uv[1] : 0);
    mesh_file::checkFinite(o.here(), {p, 0}, "a uv coordinate");
    o.add(o.mesh.uvs, p);
  };
  callback.index_cb = [](void* r, tinyobj::index_t* corners, int count) {
    static_cast<ObjReader*>(r)->face(corners, count);
  };
  // No material reader: an `mtllib` names a file that is not read (a mesh2 has no materials of its own).
  std::string warnings, errors;
  tinyobj::LoadObjWithCallback(stream, callback, &reader, nullptr, &warnings, &errors);
  reader.complete();
  mesh_file::checkNotEmpty(name, reader.mesh);
  return std::move(reader.mesh);
}

}  // namespace rt
