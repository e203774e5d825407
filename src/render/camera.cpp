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
      projection_(desc.projection),
      angle_(T(desc.angle)),
      verticalAngle_(T(desc.verticalAngle)),
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
  using P = CameraDesc::Projection;
  if (projection_ == P::Orthographic) return Ray<T>{origin_ + us * right_ + vs * up_, forward_};
  const Vec3<T> r = glm::normalize(right_), u = glm::normalize(up_);
  if (projection_ == P::UltraWideAngle || projection_ == P::Spherical) {
    // Angles across and up; fitted to POV-Ray's pictures (tests/render/test_camera.cpp).
    const T a = us * angle_, b = vs * verticalAngle_;
    const T across = projection_ == P::Spherical ? std::sin(a) * std::cos(b) : std::sin(a);
    return Ray<T>{origin_, glm::normalize(across * r + std::sin(b) * u + std::cos(a) * std::cos(b) * forward_)};
  }
  // The cylinders: an angle across the picture turns the view about the cylinder's axis (up for 1 and 3,
  // right for 2 and 4); along the axis the ray climbs (1, 2) or its origin moves (3, 4). Fitted to POV-Ray's
  // pictures (tests/render/test_camera.cpp).
  const bool vertical = projection_ == P::Cylinder1 || projection_ == P::Cylinder3;
  const bool moving = projection_ == P::Cylinder3 || projection_ == P::Cylinder4;
  const Vec3<T> across = vertical ? r : u, axis = vertical ? up_ : right_;
  const T turn = (vertical ? us : vs) * angle_, along = vertical ? vs : us;
  const Vec3<T> turned = std::cos(turn) * forward_ + std::sin(turn) * across;
  if (moving) return Ray<T>{origin_ + along * axis, turned};
  return Ray<T>{origin_, glm::normalize(turned + along * axis)};
}

template class Camera<float>;
template class Camera<double>;

}  // namespace rt
