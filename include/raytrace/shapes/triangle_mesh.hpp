// The triangles of POV-Ray's mesh, mesh2, height_field and bicubic_patch: read once into a MeshData that every
// object showing them shares (`object { MyMesh }` a thousand times holds one copy), with a hierarchy of its own
// made once per precision and shared the same way; each object is that shared geometry under its own matrix
// (shapes/transformed), with its own textures.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"

namespace rt {

template <class T> struct MeshGeometry;

// A texture of a mesh's triangles (`triangle { … texture { T } }`, mesh2's texture_list): its constant material,
// and its texture when the colour varies, in world space as an object's (ObjectDesc::texture).
struct FaceSurface {
  Material material;
  std::shared_ptr<const Texture> texture;
};

// The triangles in the shape's own space. Faces index the vertices and, for a smooth triangle, the normals at
// its corners; `surface` indexes the object's FaceSurface list, or is −1 for the object's own texture.
class MeshData {
 public:
  struct Face {
    std::array<uint32_t, 3> v{};
    std::array<int32_t, 3> n{{-1, -1, -1}};
    std::array<int32_t, 3> uv{{-1, -1, -1}};  // its corners' uv vectors, or −1: uv (0, 0) there
    int32_t surface = -1;
  };
  std::vector<glm::dvec3> vertices, normals;
  std::vector<glm::dvec2> uvs;  // the uv coordinates of uv_mapping (the manual's §3.4.6.7)
  std::vector<Face> faces;
  // POV-Ray's inside_vector: a point is inside when a ray from it this way crosses the triangles an odd number
  // of times (the manual's §3.4.5.2.3.1). Without it the mesh has no inside.
  std::optional<glm::dvec3> insideVector;
  // A height field's water_level: the points of the triangles below this height are not there.
  std::optional<double> waterLevel;

  // The smallest edge and the ball around the vertices, computed once the faces are complete: each object
  // showing the mesh asks for them.
  void complete();
  double smallestEdge() const { return smallest_; }
  Ball ball() const { return ball_; }
  // The triangles in T with their hierarchy, made on the first call and shared by every later one.
  template <class T> std::shared_ptr<const MeshGeometry<T>> geometry() const;

 private:
  // The geometries made, once each. A copy of the triangles makes its own.
  struct Made {
    std::mutex lock;
    std::shared_ptr<const MeshGeometry<float>> inFloat;
    std::shared_ptr<const MeshGeometry<double>> inDouble;
    Made() = default;
    Made(const Made&) {}
    Made& operator=(const Made&) {
      inFloat.reset();
      inDouble.reset();
      return *this;
    }
  };
  double smallest_ = 0;
  Ball ball_{glm::dvec3(0), 0};
  mutable Made made_;
};

template <> std::shared_ptr<const MeshGeometry<float>> MeshData::geometry<float>() const;
template <> std::shared_ptr<const MeshGeometry<double>> MeshData::geometry<double>() const;

// The runtime triangles in T and a binary hierarchy of boxes over them. A node with count > 0 is a leaf of the
// triangles [first, first + count); otherwise its children are the next node and node `first`.
template <class T> struct MeshGeometry {
  struct Tri {
    Vec3<T> a, ab, ac;
    uint32_t face;  // its MeshData face
  };
  struct Node {
    Aabb<T> box;
    uint32_t first = 0, count = 0;
  };
  std::vector<Tri> tris;  // the triangles with an area; a degenerate one is never hit
  std::vector<Node> nodes;
  std::vector<std::array<Vec3<T>, 3>> cornerNormals;  // by face, the normals at its corners (a smooth face's)
  std::vector<int32_t> smoothOf;                       // by face, its entry of cornerNormals or −1
  std::vector<int32_t> surfaceOf;                      // by face, its FaceSurface or −1
  std::vector<std::array<glm::vec<2, T>, 3>> cornerUvs;  // by face, its corners' uv; empty when no face has any
  std::optional<T> waterLevel;                         // MeshData's

  explicit MeshGeometry(const MeshData& data);
  // The closest triangle met strictly inside `range`, with the ray's t and the barycentric u, v of the point.
  bool closest(const Ray<T>& ray, Interval<T> range, T& t, uint32_t& tri, T& u, T& v) const;
  // How many triangles the ray meets for t > 0.
  size_t crossings(const Ray<T>& ray) const;
};

// The object of one mesh: the shared geometry, and the textures of its faces as this object places them.
template <class T> class MeshObject final : public Object<T> {
 public:
  MeshObject(std::shared_ptr<const MeshGeometry<T>> geometry, const std::vector<FaceSurface>& surfaces,
             std::optional<glm::dvec3> insideVector, const char* name, const Material& material, int id);

  // The hit's object is a face's surface when it has one: shading asks it for the material there.
  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override;
  bool inside(const Vec3<T>& p) const override;
  const char* name() const override { return name_; }
  void forEachMaterial(const std::function<void(const Material&)>& f) const override;

 private:
  // A face's texture: what a hit on the face reports as its object. Never hit itself.
  class Surface final : public Object<T> {
   public:
    Surface(const FaceSurface& s, const char* name, int id) : Object<T>(s.material, id), name_(name) {
      this->setTexture(s.texture);
    }
    std::optional<Hit<T>> intersect(const Ray<T>&, Interval<T>) const override { return std::nullopt; }
    std::optional<Aabb<T>> bounds() const override { return std::nullopt; }
    bool inside(const Vec3<T>&) const override { return false; }
    const char* name() const override { return name_; }

   private:
    const char* name_;
  };

  std::shared_ptr<const MeshGeometry<T>> geometry_;
  std::vector<std::unique_ptr<Surface>> surfaces_;
  std::optional<Vec3<T>> insideVector_;
  const char* name_;
};

// The object of `data` with the faces' textures `surfaces`.
template <class T>
std::unique_ptr<Object<T>> makeMeshObject(const MeshData& data, const std::vector<FaceSurface>& surfaces,
                                          const char* name, const ObjectBuild& build) {
  return std::make_unique<MeshObject<T>>(data.geometry<T>(), surfaces, data.insideVector, name, build.material,
                                         build.id);
}

}  // namespace rt
