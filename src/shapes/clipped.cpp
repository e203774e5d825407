#include "raytrace/shapes/clipped.hpp"

#include <algorithm>

namespace rt {

template <class T>
Clipped<T>::Clipped(std::unique_ptr<Object<T>> inner, std::vector<std::unique_ptr<Object<T>>> clips,
                    const Material& material, int id)
    : Object<T>(material, id), inner_(std::move(inner)), clips_(std::move(clips)) {}

template <class T> bool Clipped<T>::insideClips(const Vec3<T>& p) const {
  return std::all_of(clips_.begin(), clips_.end(), [&](const auto& c) { return c->inside(p); });
}

// The intervals are open, so each call moves strictly past the last crossing (as in Csg).
template <class T> std::optional<Hit<T>> Clipped<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  for (auto hit = inner_->intersect(ray, range); hit; hit = inner_->intersect(ray, {hit->t, range.max})) {
    if (insideClips(hit->point)) return hit;
  }
  return std::nullopt;
}

// What remains lies in the object's box and in every bounded clip's.
template <class T> std::optional<Aabb<T>> Clipped<T>::bounds() const {
  std::optional<Aabb<T>> box = inner_->bounds();
  for (const auto& c : clips_) {
    const auto b = c->bounds();
    if (!b) continue;
    box = box ? Aabb<T>{glm::max(box->min, b->min), glm::min(box->max, b->max)} : *b;
    box->max = glm::max(box->max, box->min);  // disjoint boxes: nothing remains, a point's box
  }
  return box;
}

template class Clipped<float>;
template class Clipped<double>;

}  // namespace rt
