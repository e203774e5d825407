#include "raytrace/scene/description.hpp"

namespace rt {

SceneDesc sceneAt(const SceneDesc& whole, const WriteDesc& write) {
  SceneDesc scene;
  scene.file = whole.file;
  scene.language = whole.language;
  scene.camera = write.camera;
  scene.lights.assign(whole.lights.begin(), whole.lights.begin() + std::ptrdiff_t(write.lights));
  scene.objects.assign(whole.objects.begin(), whole.objects.begin() + std::ptrdiff_t(write.objects));
  scene.dialect = whole.dialect;
  scene.background = write.background;
  return scene;
}

}  // namespace rt
