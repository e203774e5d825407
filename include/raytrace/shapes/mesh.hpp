#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/shapes/bicubic_patch.hpp"
#include "raytrace/shapes/height_field.hpp"
#include "raytrace/shapes/triangle_mesh.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

// What a file says of a shape made of triangles (shapes/triangle_mesh): POV-Ray's `mesh { triangle { … }
// smooth_triangle { … } }` and `mesh2 { vertex_vectors … face_indices … }` (the manual's §3.4.5.2.3, §3.4.5.2.4),
// `height_field` (shapes/height_field) and `bicubic_patch` (shapes/bicubic_patch). The triangles are shared
// by every copy of the description; the faces' textures are each copy's own, moved with it.
struct MeshDesc {
  std::shared_ptr<const MeshData> data;
  std::vector<FaceSurface> surfaces;  // the faces' own textures (MeshData::Face::surface)
  const char* kind = "Mesh";          // the type name reports print

  static bool named(std::string_view word) {
    return word == "mesh" || word == "mesh2" || word == "height_field" || word == "bicubic_patch" ||
           word == "smooth_triangle";
  }
  const char* name() const { return kind; }
  // The triangles' test is the triangle's, but no bound on float's error on their shared edges and on the
  // inside_vector crossings is tested yet.
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static MeshDesc read(Reader& r, std::string_view word) {
    const SourceLoc at = r.here();
    MeshDesc d;
    auto data = std::make_shared<MeshData>();
    if (word == "mesh") {
      readMesh(r, *data, d.surfaces);
    } else if (word == "mesh2") {
      readMesh2(r, *data, d.surfaces);
    } else if (word == "smooth_triangle") {
      d.kind = "SmoothTriangle";  // one, as a mesh of one (the manual's §3.4.5.2.7)
      std::vector<const void*> none;
      triangleReader(true, false, *data, d.surfaces, none)(r);
    } else if (word == "height_field") {
      d.kind = "HeightField";
      *data = readHeightField(r);
    } else {
      d.kind = "BicubicPatch";
      *data = readBicubicPatch(r);
    }
    // POV-Ray's "no triangles in triangle mesh" (and of a height field all under its water level).
    if (data->faces.empty()) throw ParseError(at, "the " + std::string(word) + " has no triangles");
    data->complete();
    d.data = std::move(data);
    return d;
  }
  double smallestFeature() const { return data->smallestEdge(); }
  Ball boundingBall() const { return data->ball(); }
  FlatFaces flatFaces() const { return {}; }  // computed in double (kFloatErrorBound): no offset to check
  void describe(std::ostream& out) const {
    out << "- Triangles: " << data->faces.size() << "\n- Vertices: " << data->vertices.size() << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return makeMeshObject<T>(*data, surfaces, kind, b);
  }

 private:
  // A triangle's `texture { … }`: the index of its FaceSurface, one per texture written (triangles naming the
  // same declared texture share it), or −1 when it has none.
  template <class Reader>
  static int32_t faceTexture(Reader& r, std::vector<FaceSurface>& surfaces, std::vector<const void*>& sources) {
    FaceSurface s;
    const void* source = nullptr;
    if (!r.texture(s, source)) return -1;
    for (size_t i = 0; i < sources.size(); ++i) {
      if (sources[i] == source) return int32_t(i);
    }
    sources.push_back(source);
    surfaces.push_back(std::move(s));
    return int32_t(surfaces.size() - 1);
  }

  // What reads a triangle's corners (and normals when `smooth`) into `m`, and, in a mesh (`textured`), its own
  // texture. A named type rather than a lambda: read() above uses it, which a deduced return type forbids.
  struct TriangleReader {
    bool smooth, textured;
    MeshData& m;
    std::vector<FaceSurface>& surfaces;
    std::vector<const void*>& sources;
    template <class Reader> void operator()(Reader& t) const {
      MeshData::Face f;
      for (size_t k = 0; k < 3; ++k) {
        f.v[k] = uint32_t(m.vertices.size());
        m.vertices.push_back(t.vec3("a triangle corner"));
        if (!smooth) continue;
        f.n[k] = int32_t(m.normals.size());
        m.normals.push_back(t.vec3("a smooth triangle's corner normal"));
      }
      if (textured && t.keyword("uv_vectors")) {
        for (size_t k = 0; k < 3; ++k) {
          f.uv[k] = int32_t(m.uvs.size());
          m.uvs.push_back(glm::dvec2(t.vec3("a corner's uv vector")));
        }
      }
      if (textured) f.surface = faceTexture(t, surfaces, sources);
      m.faces.push_back(f);
    }
  };
  static TriangleReader triangleReader(bool smooth, bool textured, MeshData& m, std::vector<FaceSurface>& surfaces,
                                       std::vector<const void*>& sources) {
    return {smooth, textured, m, surfaces, sources};
  }

  template <class Reader> static void readMesh(Reader& r, MeshData& m, std::vector<FaceSurface>& surfaces) {
    std::vector<const void*> sources;
    const auto triangle = [&](bool smooth) { return triangleReader(smooth, true, m, surfaces, sources); };
    while (r.block("triangle", triangle(false)) || r.block("smooth_triangle", triangle(true))) {
    }
    if (r.keyword("inside_vector")) m.insideVector = r.vec3("the inside vector");
  }

  // A mesh2 list `word { count, items… }`: read(reader) for each of its `count` items.
  template <class Reader, class F> static bool list(Reader& r, std::string_view word, F&& read) {
    return r.block(word, [&](auto& l) {
      const SourceLoc at = l.here();
      const double count = l.number("the number of entries");
      if (!(count >= 0 && count == double(size_t(count)))) {
        throw ParseError(at, "the number of entries of '" + std::string(word) + "' must be a whole number, found " +
                                 shortest(count));
      }
      for (size_t i = 0; i < size_t(count); ++i) read(l, i);
    });
  }

  // An index into a list of `size` entries, located when it is out of range.
  static uint32_t index(double value, size_t size, const SourceLoc& at, const char* list) {
    if (!(value >= 0 && value < double(size) && value == double(size_t(value)))) {
      throw ParseError(at,
                       "index " + shortest(value) + " is out of range for the " + std::to_string(size) + " " + list);
    }
    return uint32_t(value);
  }

  template <class Reader> static void readMesh2(Reader& r, MeshData& m, std::vector<FaceSurface>& surfaces) {
    list(r, "vertex_vectors", [&](auto& l, size_t) { m.vertices.push_back(l.vec3("a vertex")); });
    list(r, "normal_vectors", [&](auto& l, size_t) { m.normals.push_back(l.vec3("a normal")); });
    // The uv coordinates place a uv_mapping texture (the manual's §3.4.6.7.2).
    list(r, "uv_vectors", [&](auto& l, size_t) { m.uvs.push_back(glm::dvec2(l.vec3("a uv vector"))); });
    size_t textures = 0;
    list(r, "texture_list", [&](auto& l, size_t) {
      FaceSurface s;
      const void* source = nullptr;
      const SourceLoc at = l.here();
      if (!l.texture(s, source)) throw ParseError(at, "'texture_list' needs a texture");
      surfaces.push_back(std::move(s));
      ++textures;
    });
    list(r, "face_indices", [&](auto& l, size_t) {
      const SourceLoc at = l.here();
      const glm::dvec3 v = l.vec3("a face's vertex indices");
      MeshData::Face f;
      for (int k = 0; k < 3; ++k) f.v[size_t(k)] = index(v[k], m.vertices.size(), at, "vertex_vectors");
      if (l.moreNumbers()) {
        const SourceLoc t = l.here();
        f.surface = int32_t(index(l.number("a face's texture index"), textures, t, "textures of texture_list"));
        if (l.moreNumbers()) throw ParseError(l.here(), "'three texture indices of a face' is not supported yet");
      }
      m.faces.push_back(f);
    });
    const bool normalIndices = list(r, "normal_indices", [&](auto& l, size_t i) {
      const SourceLoc at = l.here();
      const glm::dvec3 n = l.vec3("a face's normal indices");
      if (i >= m.faces.size()) throw ParseError(at, "'normal_indices' lists more faces than 'face_indices'");
      for (int k = 0; k < 3; ++k) {
        m.faces[i].n[size_t(k)] = int32_t(index(n[k], m.normals.size(), at, "normal_vectors"));
      }
    });
    // Without normal_indices, as many normals as vertices are indexed as the vertices are (the manual's §3.4.5.2.4).
    if (!normalIndices && !m.normals.empty() && m.normals.size() == m.vertices.size()) {
      for (MeshData::Face& f : m.faces) {
        for (size_t k = 0; k < 3; ++k) f.n[k] = int32_t(f.v[k]);
      }
    }
    const bool uvIndices = list(r, "uv_indices", [&](auto& l, size_t i) {
      const SourceLoc at = l.here();
      const glm::dvec3 n = l.vec3("a face's uv indices");
      if (i >= m.faces.size()) throw ParseError(at, "'uv_indices' lists more faces than 'face_indices'");
      for (int k = 0; k < 3; ++k) m.faces[i].uv[size_t(k)] = int32_t(index(n[k], m.uvs.size(), at, "uv_vectors"));
    });
    // Without uv_indices, the uv vectors are indexed as the vertices are when there are enough of them.
    if (!uvIndices && !m.uvs.empty() && m.uvs.size() >= m.vertices.size()) {
      for (MeshData::Face& f : m.faces) {
        for (size_t k = 0; k < 3; ++k) f.uv[k] = int32_t(f.v[k]);
      }
    }
    if (r.keyword("inside_vector")) m.insideVector = r.vec3("the inside vector");
  }
};

}  // namespace rt
