#include "raytrace/shapes/triangle_mesh.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "raytrace/shapes/triangle.hpp"

namespace rt {

void MeshData::complete() {
  smallest_ = std::numeric_limits<double>::infinity();
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const Face& f : faces) {
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3& p = vertices[f.v[size_t(k)]];
      const double edge = glm::length(vertices[f.v[size_t((k + 1) % 3)]] - p);
      if (edge > 0) smallest_ = std::min(smallest_, edge);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  if (faces.empty()) lo = hi = glm::dvec3(0);
  if (!(smallest_ < std::numeric_limits<double>::infinity())) smallest_ = 0;
  ball_ = {(lo + hi) / 2.0, glm::length(hi - lo) / 2};
}

template <> std::shared_ptr<const MeshGeometry<float>> MeshData::geometry<float>() const {
  const std::lock_guard<std::mutex> lock(made_.lock);
  if (!made_.inFloat) made_.inFloat = std::make_shared<const MeshGeometry<float>>(*this);
  return made_.inFloat;
}

template <> std::shared_ptr<const MeshGeometry<double>> MeshData::geometry<double>() const {
  const std::lock_guard<std::mutex> lock(made_.lock);
  if (!made_.inDouble) made_.inDouble = std::make_shared<const MeshGeometry<double>>(*this);
  return made_.inDouble;
}

namespace {

constexpr uint32_t kLeafSize = 4;

template <class T> Aabb<T> boxOf(const typename MeshGeometry<T>::Tri& t) {
  Aabb<T> b;
  b.expand(t.a);
  b.expand(t.a + t.ab);
  b.expand(t.a + t.ac);
  return b;
}

// The hierarchy over the triangles order[first, first + count): halves at the median of the centres along the
// axis where they spread most, which keeps it balanced whatever the mesh. Only the indices move while it is built.
template <class T>
void buildNodes(MeshGeometry<T>& g, const std::vector<Vec3<T>>& centres, std::vector<uint32_t>& order,
                uint32_t first, uint32_t count) {
  const size_t at = g.nodes.size();
  g.nodes.emplace_back();
  Aabb<T> box, spread;
  for (uint32_t i = first; i < first + count; ++i) {
    box.expand(boxOf<T>(g.tris[order[i]]));
    spread.expand(centres[order[i]]);
  }
  g.nodes[at].box = box;
  if (count <= kLeafSize) {
    g.nodes[at].first = first;
    g.nodes[at].count = count;
    return;
  }
  const Vec3<T> size = spread.max - spread.min;
  const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
  const uint32_t half = count / 2;
  std::nth_element(order.begin() + first, order.begin() + first + half, order.begin() + first + count,
                   [&](uint32_t a, uint32_t b) { return centres[a][axis] < centres[b][axis]; });
  buildNodes(g, centres, order, first, half);
  g.nodes[at].first = uint32_t(g.nodes.size());
  buildNodes(g, centres, order, first + half, count - half);
}

// The slab test: whether the ray meets the box for some t in (lo, hi).
template <class T> bool meetsBox(const Aabb<T>& b, const Vec3<T>& origin, const Vec3<T>& inv, T lo, T hi) {
  for (int k = 0; k < 3; ++k) {
    T t0 = (b.min[k] - origin[k]) * inv[k], t1 = (b.max[k] - origin[k]) * inv[k];
    if (t0 > t1) std::swap(t0, t1);
    // A NaN (a ray along a face of a flat box) leaves the range as it is.
    if (t0 > lo) lo = t0;
    if (t1 < hi) hi = t1;
  }
  return lo <= hi;
}

// Calls leaf(first, count) for every leaf whose box the ray meets in (range.min, limit()), nearer child first.
template <class T, class Leaf, class Limit>
void walk(const MeshGeometry<T>& g, const Ray<T>& ray, T lo, Limit limit, Leaf leaf) {
  if (g.nodes.empty()) return;
  const Vec3<T> inv = T(1) / ray.dir;
  uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const auto& node = g.nodes[stack[--top]];
    if (!meetsBox(node.box, ray.origin, inv, lo, limit())) continue;
    if (node.count > 0) {
      leaf(node.first, node.count);
      continue;
    }
    const uint32_t left = uint32_t(&node - g.nodes.data()) + 1, right = node.first;
    // Visit first the child on the side the ray comes from along the axis it moves most on.
    const Vec3<T> d = glm::abs(ray.dir);
    const int axis = d.x >= d.y && d.x >= d.z ? 0 : (d.y >= d.z ? 1 : 2);
    const bool leftFirst = (g.nodes[left].box.min[axis] <= g.nodes[right].box.min[axis]) == (ray.dir[axis] >= 0);
    stack[top++] = leftFirst ? right : left;
    stack[top++] = leftFirst ? left : right;
  }
}

}  // namespace

template <class T> MeshGeometry<T>::MeshGeometry(const MeshData& data) {
  if (data.waterLevel) waterLevel = T(*data.waterLevel);
  smoothOf.assign(data.faces.size(), -1);
  surfaceOf.resize(data.faces.size());
  if (!data.uvs.empty()) cornerUvs.resize(data.faces.size());
  for (size_t i = 0; i < data.faces.size(); ++i) {
    const MeshData::Face& f = data.faces[i];
    surfaceOf[i] = f.surface;
    for (size_t k = 0; k < 3 && !cornerUvs.empty(); ++k) {
      if (f.uv[k] >= 0) cornerUvs[i][k] = glm::vec<2, T>(data.uvs[size_t(f.uv[k])]);
    }
    const Vec3<T> a(data.vertices[f.v[0]]), b(data.vertices[f.v[1]]), c(data.vertices[f.v[2]]);
    const T area = glm::length(glm::cross(b - a, c - a));
    if (!(area > T(0) && area < std::numeric_limits<T>::infinity())) continue;
    tris.push_back({a, b - a, c - a, uint32_t(i)});
    if (f.n[0] < 0) continue;
    smoothOf[i] = int32_t(cornerNormals.size());
    cornerNormals.push_back({Vec3<T>(data.normals[size_t(f.n[0])]), Vec3<T>(data.normals[size_t(f.n[1])]),
                             Vec3<T>(data.normals[size_t(f.n[2])])});
  }
  std::vector<Vec3<T>> centres(tris.size());
  for (size_t i = 0; i < tris.size(); ++i) centres[i] = tris[i].a + (tris[i].ab + tris[i].ac) / T(3);
  if (tris.empty()) return;
  std::vector<uint32_t> order(tris.size());
  std::iota(order.begin(), order.end(), 0);
  buildNodes(*this, centres, order, 0, uint32_t(tris.size()));
  std::vector<Tri> placed(tris.size());
  for (size_t k = 0; k < order.size(); ++k) placed[k] = tris[order[k]];
  tris = std::move(placed);
}

template <class T>
bool MeshGeometry<T>::closest(const Ray<T>& ray, Interval<T> range, T& t, uint32_t& tri, T& u, T& v) const {
  bool found = false;
  walk(*this, ray, range.min, [&] { return range.max; }, [&](uint32_t first, uint32_t count) {
    for (uint32_t i = first; i < first + count; ++i) {
      T ti, ui, vi;
      if (!Triangle<T>::solve(tris[i].a, tris[i].ab, tris[i].ac, ray, range, ti, ui, vi)) continue;
      if (waterLevel && tris[i].a.y + ui * tris[i].ab.y + vi * tris[i].ac.y < *waterLevel) continue;
      range.max = t = ti;
      u = ui;
      v = vi;
      tri = i;
      found = true;
    }
  });
  return found;
}

template <class T> size_t MeshGeometry<T>::crossings(const Ray<T>& ray) const {
  size_t n = 0;
  const Interval<T> range{T(0), std::numeric_limits<T>::infinity()};
  walk(*this, ray, T(0), [] { return std::numeric_limits<T>::infinity(); }, [&](uint32_t first, uint32_t count) {
    for (uint32_t i = first; i < first + count; ++i) {
      T t, u, v;
      if (!Triangle<T>::solve(tris[i].a, tris[i].ab, tris[i].ac, ray, range, t, u, v)) continue;
      if (!(waterLevel && tris[i].a.y + u * tris[i].ab.y + v * tris[i].ac.y < *waterLevel)) ++n;
    }
  });
  return n;
}

template <class T>
MeshObject<T>::MeshObject(std::shared_ptr<const MeshGeometry<T>> geometry, const std::vector<FaceSurface>& surfaces,
                          std::optional<glm::dvec3> insideVector, const char* name, const Material& material, int id)
    : Object<T>(material, id), geometry_(std::move(geometry)), name_(name) {
  for (const FaceSurface& s : surfaces) surfaces_.push_back(std::make_unique<Surface>(s, name, id));
  if (insideVector) insideVector_ = Vec3<T>(*insideVector);
}

template <class T>
std::optional<Hit<T>> MeshObject<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  T t, u, v;
  uint32_t i;
  if (!geometry_->closest(ray, range, t, i, u, v)) return std::nullopt;
  const auto& tri = geometry_->tris[i];
  Hit<T> hit;
  hit.t = t;
  hit.point = tri.a + u * tri.ab + v * tri.ac;
  // A smooth triangle's normal is its corners' interpolated at the point (the manual's §3.4.5.2.7).
  const int32_t smooth = geometry_->smoothOf[tri.face];
  if (smooth >= 0) {
    const auto& n = geometry_->cornerNormals[size_t(smooth)];
    hit.normal = glm::normalize((T(1) - u - v) * n[0] + u * n[1] + v * n[2]);
  }
  if (smooth < 0 || !hit.hasNormal()) hit.normal = glm::normalize(glm::cross(tri.ab, tri.ac));
  if (!geometry_->cornerUvs.empty()) {
    const auto& c = geometry_->cornerUvs[tri.face];
    hit.uv = (T(1) - u - v) * c[0] + u * c[1] + v * c[2];
  }
  const int32_t surface = geometry_->surfaceOf[tri.face];
  hit.object = surface >= 0 ? static_cast<const Object<T>*>(surfaces_[size_t(surface)].get()) : this;
  return hit;
}

template <class T> std::optional<Aabb<T>> MeshObject<T>::bounds() const {
  if (geometry_->nodes.empty()) return Aabb<T>{Vec3<T>(0), Vec3<T>(0)};
  return geometry_->nodes[0].box;
}

template <class T> bool MeshObject<T>::inside(const Vec3<T>& p) const {
  return insideVector_ && geometry_->crossings({p, *insideVector_}) % 2 == 1;
}

template <class T> void MeshObject<T>::forEachMaterial(const std::function<void(const Material&)>& f) const {
  Object<T>::forEachMaterial(f);
  for (const auto& s : surfaces_) s->forEachMaterial(f);
}

template struct MeshGeometry<float>;
template struct MeshGeometry<double>;
template class MeshObject<float>;
template class MeshObject<double>;

}  // namespace rt
