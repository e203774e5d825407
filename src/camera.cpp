#include "raytrace/camera.hpp"

namespace rt {

template <class T>
Camera<T>::Camera(const CameraDesc& desc, int width, int height)
    : origin_(desc.location),
      right_(desc.rightFollowsImage ? desc.right * (double(width) / height) : desc.right),
      up_(desc.up),
      forward_(glm::normalize(Vec3<T>(desc.lookAt - desc.location))),
      offset_(desc.pixelOffset),
      width_(width),
      height_(height) {}

// d = Us·right + Vs·up + l̂ with Us = −½ + px/w, Vs = −½ + py/h (lecture 2 via §d); right and up are used as
// given, so `right` carries the aspect ratio and nothing is re-orthogonalized.
template <class T> Ray<T> Camera<T>::ray(T px, T py) const {
  const T us = T(-0.5) + px / T(width_);
  const T vs = T(-0.5) + py / T(height_);
  return Ray<T>{origin_, glm::normalize(us * right_ + vs * up_ + forward_)};
}

template class Camera<float>;
template class Camera<double>;

}  // namespace rt
