#include "raytrace/render/camera.hpp"

#include <cmath>

#include "raytrace/util/error.hpp"

namespace rt {

namespace {

template <class T> bool finite(const Vec3<T>& v) { return std::isfinite(v.x + v.y + v.z); }

}  // namespace

template <class T>
Camera<T>::Camera(const CameraDesc& desc, int width, int height)
    : origin_(desc.location),
      right_(desc.rightFollowsImage ? desc.right * (double(width) / height) : desc.right),
      up_(desc.up),
      forward_(glm::normalize(Vec3<T>(desc.lookAt - desc.location))),
      perspective_(desc.projection == &perspectiveProjection()),
      hasBlanks_(desc.projection->blanks),
      projection_(desc.projection->ray),
      frame_{desc.location, desc.rightFollowsImage ? desc.right * (double(width) / height) : desc.right, desc.up,
             glm::normalize(desc.lookAt - desc.location), desc.directionLength, desc.angle, desc.verticalAngle},
      offset_(desc.pixelOffset),
      width_(width),
      height_(height) {
  // Every eye ray must be finite: its origin, and d = Us·right + Vs·up + forward (|Us|, |Vs| ≤ 1) normalized,
  // which needs |d|² finite, and |d| away from 0, which needs forward well out of the plane of right and up.
  const char* problem = nullptr;
  const T reach = glm::length(right_) + glm::length(up_) + T(1);
  if (!finite(origin_)) {
    problem = "its location is too large for the arithmetic";
  } else if (!finite(forward_)) {
    problem = "its look_at is too close to or too far from its location to give a direction";
  } else if (!std::isfinite(reach * reach)) {
    problem = "its up or right vector is too long";
  } else {
    const glm::dvec3 right = glm::normalize(glm::dvec3(right_)), up = glm::normalize(glm::dvec3(up_));
    const double across = std::abs(glm::dot(glm::cross(right, up), glm::dvec3(forward_)));
    if (!(across > 1e-9)) {
      problem = finite(right) && finite(up) ? "it looks along the plane of its up and right vectors"
                                            : "its up or right vector is too short";
    }
  }
  if (problem) throw ParseError(desc.loc, std::string("the camera gives no image: ") + problem);
}

template <class T> Ray<T> Camera<T>::projected(T us, T vs) const {
  const std::optional<EyeRay> eye = projection_(frame_, double(us), double(vs));
  if (!eye) return Ray<T>{origin_, Vec3<T>(0)};
  return Ray<T>{Vec3<T>(eye->origin), Vec3<T>(glm::normalize(eye->dir))};
}

template class Camera<float>;
template class Camera<double>;

}  // namespace rt
