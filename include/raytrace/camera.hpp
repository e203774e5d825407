// The course camera (csc473-course.md §d): a ray from `location` through the image plane spanned by `right`
// and `up` at unit distance along the viewing direction. Pixel (x, y) has y growing upward.
#pragma once

#include "raytrace/ray.hpp"
#include "raytrace/scene_desc.hpp"

namespace rt {

template <class T> class Camera {
 public:
  Camera(const CameraDesc& desc, int width, int height);

  // The eye ray through a point of the image given in pixel units from the lower-left image corner.
  Ray<T> ray(T px, T py) const;
  // The eye ray of pixel (x, y), through the pixel's own sample point (CameraDesc::pixelOffset).
  Ray<T> pixelRay(int x, int y) const { return ray(T(x) + offset_.x, T(y) + offset_.y); }

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Vec3<T> origin_, right_, up_, forward_;
  glm::vec<2, T, glm::defaultp> offset_;
  int width_, height_;
};

}  // namespace rt
