// The commands that print what the renderer sees: the scene as parsed, one pixel's rays, hits and colour, and
// the hierarchy.
#include <string>
#include <vector>

#include "raytrace/app/hierarchy_report.hpp"
#include "raytrace/app/invocation.hpp"
#include "raytrace/app/report.hpp"
#include "raytrace/image/image.hpp"
#include "raytrace/render/irradiance_prepass.hpp"
#include "raytrace/render/ray_tree.hpp"
#include "raytrace/render/tracer.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

namespace {

// The tracer of the pixel commands: with --gi-cache it reads the cache the render would make of the whole
// picture, built here the same way (as long as the render's own passes take), so the pixel is the rendered one.
template <class T, class F>
auto withTracer(const Invocation& inv, const Scene<T>& scene, const Camera<T>& camera, F&& f) {
  Tracer<T> tracer(scene, inv.options);
  if (!inv.options.gi.enabled || !inv.options.gi.cache) return f(tracer);
  const IrradianceCache<T> cache = prepareIrradianceCache(scene, camera, inv.options);
  tracer.useCache(&cache);
  return f(tracer);
}

void printPixelRay(std::ostream& out, int x, int y, const glm::dvec3& origin, const glm::dvec3& dir) {
  out << "Pixel: [" << x << ", " << y << "] Ray: " << braces(origin) << " -> " << braces(dir) << "\n";
}

// A colour as the course prints it, "(r, g, b)" in bytes (§a.0).
std::string bytes(const Color& c, Dialect::ToByte mode) {
  return "(" + std::to_string(toByte(c.r, mode)) + ", " + std::to_string(toByte(c.g, mode)) + ", " +
         std::to_string(toByte(c.b, mode)) + ")";
}

}  // namespace

// The pixel's shaded colour with its eye ray and first hit (§a.2); with -ss, the first sub-sample's ray. With
// -gi the colour is the pixel's estimate in the rendered image, the same random numbers included.
int pixelcolor(const Invocation& inv, std::ostream& out) {
  return withScene(inv, [&](const auto& scene, const auto& camera) {
    std::vector<RayRecord> trees;
    const Color color =
        withTracer(inv, scene, camera, [&](auto& tracer) { return tracer.pixel(camera, inv.x, inv.y, &trees); });
    const RayRecord& eye = trees.front();
    printPixelRay(out, inv.x, inv.y, eye.origin, eye.dir);
    if (!eye.hit) {
      out << "No Hit\n";
      return 0;
    }
    out << "T = " << fixed4(eye.t) << "\nObject Type: " << eye.objectType
        << "\nBRDF: " << (inv.options.brdf == Brdf::BlinnPhong ? "Blinn-Phong" : "Cook-Torrance")
        << "\nColor: " << bytes(color, inv.scene.dialect.toByte()) << "\n";
    return 0;
  });
}

// Every ray the pixel's colour is made of: printrays (§a.3) or, decorated with shadow rays, pixeltrace (§a.9).
// With -gi the gather rays are summed up per bounce after the trees (their ambient is the gathered light).
int rayTrees(const Invocation& inv, std::ostream& out, bool decorated) {
  return withScene(inv, [&](const auto& scene, const auto& camera) {
    std::vector<RayRecord> trees;
    std::vector<GatherSummary> gathers;
    const Color color = withTracer(inv, scene, camera, [&](auto& tracer) {
      return tracer.pixel(camera, inv.x, inv.y, &trees, &gathers);
    });
    printRayTrees(out, inv.x, inv.y, bytes(color, inv.scene.dialect.toByte()), trees, decorated, gathers);
    return 0;
  });
}
int printrays(const Invocation& inv, std::ostream& out) { return rayTrees(inv, out, false); }
int pixeltrace(const Invocation& inv, std::ostream& out) { return rayTrees(inv, out, true); }


int sceneinfo(const Invocation& inv, std::ostream& out) {
  printSceneInfo(out, inv.scene);
  return 0;
}

int pixelray(const Invocation& inv, std::ostream& out) {
  return withScene(inv, [&](const auto& scene, const auto& camera) {
    (void)scene;
    const auto ray = camera.pixelRay(inv.x, inv.y);
    printPixelRay(out, inv.x, inv.y, glm::dvec3(ray.origin), glm::dvec3(ray.dir));
    return 0;
  });
}

int firsthit(const Invocation& inv, std::ostream& out) {
  return withScene(inv, [&](const auto& scene, const auto& camera) {
    const auto ray = camera.pixelRay(inv.x, inv.y);
    printPixelRay(out, inv.x, inv.y, glm::dvec3(ray.origin), glm::dvec3(ray.dir));
    const auto hit = scene.closestHit(ray, {}, Sight::Image);
    if (!hit) {
      out << "No Hit\n";
      return 0;
    }
    Material textured;
    out << "T = " << fixed4(hit->t) << "\nObject Type: " << hit->object->name()
        << "\nColor: " << bare(hit->object->materialAt(*hit, textured).pigment) << "\n";
    return 0;
  });
}

// The hierarchy the scene's bounded objects get, printed whether or not renders would use it.
int printbvh(const Invocation& inv, std::ostream& out) {
  const View grid = eyeRayGrid(inv.width, inv.height, inv.options);
  return withSceneAlone(inv.scene, grid, inv.options, Hierarchy::Always, [&](const auto& scene) {
    const size_t bounded = scene.hierarchy()->objects().size();
    out << scene.objects().size() << " objects: " << bounded << " bounded, "
        << scene.objects().size() - bounded << " unbounded (tested one by one). Renders use the hierarchy from "
        << kHierarchyMinObjects << " bounded objects on: " << (bounded >= kHierarchyMinObjects ? "yes" : "no")
        << ".\n";
    printHierarchy(out, *scene.hierarchy());
    return 0;
  });
}

}  // namespace rt
