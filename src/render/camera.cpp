#include "raytrace/render/camera.hpp"

#include <algorithm>
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
      perspective_(desc.projection == &perspectiveProjection() && !desc.normal),
      hasBlanks_(desc.projection->blanks),
      projection_(desc.projection->ray),
      mesh_(desc.mesh),
      normal_(desc.normal),
      frame_{desc.location, desc.rightFollowsImage ? desc.right * (double(width) / height) : desc.right, desc.up,
             glm::normalize(desc.lookAt - desc.location), desc.directionLength, desc.angle, desc.verticalAngle,
             mesh_.get(), width, height},
      blur_(desc.focalBlur),
      // The lens's radius is a quarter of the aperture: measured from the discs POV-Ray blurs points into.
      lensRadius_(T(desc.focalBlur.aperture / 4)),
      focalDistance_(T(glm::dot(desc.focalBlur.focalPoint - desc.location, glm::normalize(desc.lookAt - desc.location)))),
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
  if (!(desc.focalBlur.aperture > 0)) blur_.maxSamples = 0;
  if (blur_.minSamples <= 0) blur_.minSamples = blur_.maxSamples < 7 ? 4 : 7;
  blur_.minSamples = std::min(blur_.minSamples, blur_.maxSamples);
}

template <class T> Ray<T> Camera<T>::throughLens(const Ray<T>& pinhole, glm::vec2 lens) const {
  // Uniform on the lens's disc: r = R·√u, φ = 2πv.
  const T r = lensRadius_ * std::sqrt(T(lens.x)), phi = T(2 * M_PI) * T(lens.y);
  const Vec3<T> across = glm::normalize(right_), up = glm::normalize(up_);
  const Vec3<T> from = pinhole.origin + r * (std::cos(phi) * across + std::sin(phi) * up);
  const Vec3<T> focus = pinhole.origin + pinhole.dir * (focalDistance_ / glm::dot(pinhole.dir, forward_));
  return Ray<T>{from, glm::normalize(focus - from)};
}

template <class T> Ray<T> Camera<T>::projected(T us, T vs) const {
  const std::optional<EyeRay> eye = projection_(frame_, double(us), double(vs));
  if (!eye) return Ray<T>{origin_, Vec3<T>(0)};
  glm::dvec3 dir = glm::normalize(eye->dir);
  if (normal_) dir = normal_->bent(dir, glm::dvec3(us, vs, 0), glm::dmat3(1));
  return Ray<T>{Vec3<T>(eye->origin), Vec3<T>(dir)};
}

template <class T> Ray<T> Camera<T>::meshRay(int x, int y, int k) const {
  const std::optional<EyeRay> eye = frame_.mesh->ray(x, height_ - 1 - y, k, width_, height_);
  if (!eye) return Ray<T>{origin_, Vec3<T>(0)};
  return Ray<T>{Vec3<T>(eye->origin), Vec3<T>(glm::normalize(eye->dir))};
}

template class Camera<float>;
template class Camera<double>;

}  // namespace rt
