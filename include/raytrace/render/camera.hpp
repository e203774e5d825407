// The course camera (docs/reference/csc473.md §d): a ray from `location` through the image plane spanned by `right`
// and `up` at unit distance along the viewing direction. Pixel (x, y) has y growing upward.
#pragma once

#include "raytrace/geometry/ray.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

template <class T> class Camera {
 public:
  Camera(const CameraDesc& desc, int width, int height);

  // The eye ray through a point of the image given in pixel units from the lower-left image corner:
  // d = Us·right + Vs·up + l̂ with Us = −½ + px/w, Vs = −½ + py/h (lecture 2 via §d); right and up are used as
  // given, so `right` carries the aspect ratio and nothing is re-orthogonalized. (Inline: a ray returned
  // through memory and copied on would be read back before its stores settle, once per sample.)
  Ray<T> ray(T px, T py) const {
    const T us = T(-0.5) + px / T(width_);
    const T vs = T(-0.5) + py / T(height_);
    if (perspective_) {
      return Ray<T>{origin_, glm::normalize(us * right_ + vs * up_ + forward_)};
    }
    return projected(us, vs);
  }
  // Whether a ray from ray() is one of the picture's points where the projection draws nothing (outside a
  // fisheye's circle): its direction is zero, and POV-Ray leaves its pixel black.
  static bool blank(const Ray<T>& ray) { return ray.dir == Vec3<T>(0); }
  // The rays a pixel averages: a mesh camera's rays_per_pixel, 1 for every other camera.
  int raysPerPixel() const { return frame_.mesh ? frame_.mesh->raysPerPixel : 1; }
  // Ray k of a mesh camera's pixel (x, y), blank where no face gives one.
  Ray<T> meshRay(int x, int y, int k) const;
  // Whether any of the picture's points can be blank.
  bool hasBlanks() const { return hasBlanks_; }
  // The eye ray of pixel (x, y), through the pixel's own sample point (CameraDesc::pixelOffset).
  Ray<T> pixelRay(int x, int y) const { return sampleRay(x, y, 0, 0, 1); }
  // Sub-sample (i, j) of an n × n grid over pixel (x, y), centred on the pixel's sample point (§c.12: the
  // course's centre offset ½ gives its Us = −½ + (x·n + i + ½)/(w·n)). n = 1 is the pixel's own ray.
  Ray<T> sampleRay(int x, int y, int i, int j, int n) const {
    return ray(T(x) + offset_.x + ((T(i) + T(0.5)) / T(n) - T(0.5)),
               T(y) + offset_.y + ((T(j) + T(0.5)) / T(n) - T(0.5)));
  }

  // The eye ray through the point (dx, dy) pixels away from pixel (x, y)'s sample point: adaptive
  // anti-aliasing's corners and jittered sub-samples (render/antialias).
  Ray<T> offsetRay(int x, int y, T dx, T dy) const { return ray(T(x) + offset_.x + dx, T(y) + offset_.y + dy); }
  // Focal blur (POV-Ray's aperture; manual, "Focal Blur"): whether it is on, its samples, and the ray from
  // a point of the lens (`lens` uniform in the unit square) through where `pinhole` meets the plane of focus,
  // the plane through focal_point facing the view.
  bool blurred() const { return blur_.maxSamples > 0; }
  const CameraDesc::FocalBlur& focalBlur() const { return blur_; }
  Ray<T> throughLens(const Ray<T>& pinhole, glm::vec2 lens) const;

  int width() const { return width_; }
  const Vec3<T>& eye() const { return origin_; }
  // The width of a pixel at unit distance from the eye, at the picture's centre.
  T pixelSize() const { return glm::length(right_) / T(width_); }
  int height() const { return height_; }

 private:
  // The eye ray of the projections other than the perspective one (scene/projection.hpp), in double, bent by
  // the camera's normal if it has one; out of the way of the plain perspective one, which every course scene
  // takes.
  [[gnu::cold]] Ray<T> projected(T us, T vs) const;

  Vec3<T> origin_, right_, up_, forward_;
  bool perspective_, hasBlanks_;
  ProjectionRay projection_;
  std::shared_ptr<const MeshCamera> mesh_;  // held here: frame_ points into it
  std::shared_ptr<const Normal> normal_;
  ProjectionFrame frame_;
  CameraDesc::FocalBlur blur_;
  T lensRadius_, focalDistance_;
  glm::vec<2, T, glm::defaultp> offset_;
  int width_, height_;
};

}  // namespace rt
