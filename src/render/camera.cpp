#include "raytrace/render/camera.hpp"

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

template class Camera<float>;
template class Camera<double>;

}  // namespace rt
