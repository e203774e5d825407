#include "raytrace/app/report.hpp"


#include "raytrace/util/format.hpp"

namespace rt {

namespace {

// The material in the file's own terms: POV's pigment and finish scalars (§a.1); a .cli `surface`'s colours,
// which no scalar can stand for, with its power and reflection coefficient.
void printMaterial(std::ostream& out, const ObjectDesc& o, SceneLanguage language) {
  const Material& m = o.material;
  if (language == SceneLanguage::Cs3451) {
    out << "- Material:\n  - Ambient: " << braces(m.ambient) << "\n  - Diffuse: " << braces(m.diffuse)
        << "\n  - Specular: " << braces(m.specular) << "\n  - Power: " << fixed4(m.exponent)
        << "\n  - Reflection: " << fixed4(m.reflection) << "\n";
    return;
  }
  out << "- Color: " << braces(m.pigment) << "\n- Material:\n  - Ambient: " << fixed4(o.finish->ambient)
      << "\n  - Diffuse: " << fixed4(o.finish->diffuse) << "\n";
}

}  // namespace

void printSceneInfo(std::ostream& out, const SceneDesc& scene) {
  const CameraDesc& c = scene.camera;
  out << "Camera:\n- Location: " << braces(c.location) << "\n- Up: " << braces(c.up) << "\n- Right: "
      << braces(c.right) << "\n- Look at: " << braces(c.lookAt) << "\n\n---\n\n";
  out << scene.lights.size() << " light(s)\n";
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const LightDesc& l = scene.lights[i];
    out << "\nLight[" << i << "]:\n- Location: " << braces(l.position) << "\n- Color: " << braces(l.color) << "\n";
  }
  out << "\n---\n\n" << scene.objects.size() << " object(s)\n";
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const ObjectDesc& o = scene.objects[i];
    out << "\nObject[" << i << "]:\n- Type: " << shapeName(o.shape) << "\n";
    std::visit([&](const auto& s) { s.describe(out); }, o.shape);
    // Only when given, so that the course's scenes print as they always have.
    if (o.inverse) out << "- Inverse: yes\n";
    if (!o.clip.empty()) out << "- Clipped by: " << o.clip.size() << "\n";
    printMaterial(out, o, scene.language);
  }
}

}  // namespace rt
