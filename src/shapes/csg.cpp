#include "raytrace/shapes/csg.hpp"

#include <algorithm>
#include <limits>

#include "raytrace/shapes/make_object.hpp"
#include "raytrace/shapes/scale.hpp"

namespace rt {

namespace {

constexpr const char* kOpNames[] = {"union", "merge", "intersection", "difference"};
constexpr const char* kTypeNames[] = {"Union", "Merge", "Intersection", "Difference"};

}  // namespace

std::optional<CsgOp> CsgDesc::opNamed(std::string_view word) {
  for (size_t i = 0; i < std::size(kOpNames); ++i) {
    if (word == kOpNames[i]) return CsgOp(i);
  }
  return std::nullopt;
}

const char* CsgDesc::name() const { return kTypeNames[size_t(op)]; }

double CsgDesc::smallestFeature() const {
  double smallest = std::numeric_limits<double>::infinity();
  for (const ObjectDesc& c : children) smallest = std::min(smallest, worldExtent(c).feature);
  return smallest;
}

Ball CsgDesc::boundingBall() const {
  Aabb<double> box;
  for (const ObjectDesc& c : children) {
    const Ball b = worldExtent(c).ball;
    box.expand(b.center - b.radius);
    box.expand(b.center + b.radius);
  }
  const glm::dvec3 center = (box.min + box.max) / 2.0;
  return {center, glm::length(box.max - box.min) / 2};
}

void CsgDesc::describe(std::ostream& out) const {
  out << "- Children: " << children.size() << "\n";
  for (const ObjectDesc& c : children) out << "  - " << shapeName(c.shape) << "\n";
}

// POV-Ray inverts a union as the intersection of its inverted children (De Morgan), and a difference's later
// children are inverted: there a union shows no surface inside another of its children, as POV-Ray's pictures
// show (qtvr/qtvrpanorama.pov's bored box) — a merge, which is the same solid.
template <class T> std::unique_ptr<Object<T>> CsgDesc::make(const ObjectBuild& b) const {
  std::vector<std::unique_ptr<Object<T>>> made;
  for (size_t i = 0; i < children.size(); ++i) {
    const bool inverted = b.inverted != (op == CsgOp::Difference && i > 0);
    made.push_back(makeObject<T>(children[i], b.sphere, b.id, b.course, inverted));
  }
  const CsgOp madeOp = op == CsgOp::Union && b.inverted ? CsgOp::Merge : op;
  return std::make_unique<Csg<T>>(madeOp, std::move(made), name(), b.material, b.id);
}

template std::unique_ptr<Object<float>> CsgDesc::make<float>(const ObjectBuild&) const;
template std::unique_ptr<Object<double>> CsgDesc::make<double>(const ObjectBuild&) const;

template <class T>
Csg<T>::Csg(CsgOp op, std::vector<std::unique_ptr<Object<T>>> children, const char* name, const Material& material,
            int id)
    : Object<T>(material, id), op_(op), children_(std::move(children)), name_(name) {}

template <class T> bool Csg<T>::insideAnyOther(size_t i, const Vec3<T>& p) const {
  for (size_t j = 0; j < children_.size(); ++j) {
    if (j != i && children_[j]->inside(p)) return true;
  }
  return false;
}

// In the complement of every child of a difference after the first but i.
template <class T> bool Csg<T>::outsideOthers(size_t i, const Vec3<T>& p) const {
  for (size_t j = 1; j < children_.size(); ++j) {
    if (j != i && !children_[j]->insideComplement(p)) return false;
  }
  return true;
}

template <class T> bool Csg<T>::keeps(size_t i, const Vec3<T>& p) const {
  switch (op_) {
    case CsgOp::Union: return true;
    case CsgOp::Merge: return !insideAnyOther(i, p);
    case CsgOp::Intersection:
      for (size_t j = 0; j < children_.size(); ++j) {
        if (j != i && !children_[j]->inside(p)) return false;
      }
      return true;
    case CsgOp::Difference: return (i == 0 || children_[0]->inside(p)) && outsideOthers(i, p);
  }
  return false;
}

// Each child's crossings in order along the ray, up to the best kept so far: the first one kept is that
// child's candidate. The intervals are open, so each call moves strictly past the last crossing.
template <class T> std::optional<Hit<T>> Csg<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  std::optional<Hit<T>> best;
  for (size_t i = 0; i < children_.size(); ++i) {
    const T end = best ? best->t : range.max;
    for (auto hit = children_[i]->intersect(ray, {range.min, end}); hit;
         hit = children_[i]->intersect(ray, {hit->t, end})) {
      if (!keeps(i, hit->point)) continue;
      if (op_ == CsgOp::Difference && i > 0) hit->normal = -hit->normal;
      best = hit;
      break;
    }
  }
  return best;
}

template <class T> bool Csg<T>::inside(const Vec3<T>& p) const {
  switch (op_) {
    case CsgOp::Union:
    case CsgOp::Merge: return insideAnyOther(children_.size(), p);
    case CsgOp::Intersection:
      return std::all_of(children_.begin(), children_.end(), [&](const auto& c) { return c->inside(p); });
    case CsgOp::Difference: return children_[0]->inside(p) && outsideOthers(0, p);
  }
  return false;
}

// A union's box holds every child's; an intersection's lies in each bounded child's; a difference's is its
// first child's.
template <class T> std::optional<Aabb<T>> Csg<T>::bounds() const {
  if (op_ == CsgOp::Difference) return children_[0]->bounds();
  std::optional<Aabb<T>> box;
  for (const auto& c : children_) {
    const auto b = c->bounds();
    if (op_ == CsgOp::Intersection) {
      if (!b) continue;
      box = box ? Aabb<T>{glm::max(box->min, b->min), glm::min(box->max, b->max)} : *b;
      box->max = glm::max(box->max, box->min);  // disjoint children: an empty solid, a point's box
    } else {
      if (!b) return std::nullopt;
      if (!box) box = *b;
      box->expand(b->min);
      box->expand(b->max);
    }
  }
  return box;
}

template class Csg<float>;
template class Csg<double>;

}  // namespace rt
