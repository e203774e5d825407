// The commands that write images: raycast (Program 1) and render.
#include <algorithm>
#include <cstdio>
#include <string>

#include "raytrace/app/invocation.hpp"
#include "raytrace/image/image.hpp"
#include "raytrace/image/png.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"
#include "raytrace/util/stopwatch.hpp"

namespace rt {

// Each pixel gets the pigment of the closest object, or the background (Program 1's ray cast).
int raycast(const Invocation& inv, std::ostream&) {
  Image image(inv.width, inv.height);
  withScene(inv, [&](const auto& scene, const auto& camera) {
    for (int y = 0; y < inv.height; ++y) {
      for (int x = 0; x < inv.width; ++x) {
        const auto hit = scene.closestHit(camera.pixelRay(x, y), {});
        image.at(x, y) = hit ? hit->object->material().pigment : inv.scene.conventions.background;
      }
    }
    return 0;
  });
  writePng(image, "output.png", inv.scene.conventions.toByte);
  return 0;
}

namespace {

// Whether a path a scene file names stays in the folder it is rendered into: it is relative and never goes
// up. A scene from someone else must not create or replace files elsewhere unless the user says so.
bool staysInFolder(const std::string& path) {
  if (path.empty() || path[0] == '/') return false;
  for (size_t start = 0; start <= path.size();) {
    const size_t end = std::min(path.find('/', start), path.size());
    if (path.compare(start, end - start, "..") == 0) return false;
    start = end + 1;
  }
  return true;
}

}  // namespace

// The Whitted render of Programs 2-4, written to output.png; a file that names its own images (.cli `write`)
// gets each of them instead, in file order, each showing the scene as it stood at its command. A write that
// fails is reported where the file asks for it and the others are still made; the exit status tells.
int renderImage(const Invocation& inv, std::ostream&) {
  for (const WriteDesc& w : inv.scene.writes) {
    if (!inv.writeAnywhere && !staysInFolder(w.path)) {
      throw ParseError(w.loc, "'write' may only name a file in the folder the scene is rendered into and below, "
                              "found " + quote(w.path) + " (--allow-write-anywhere allows it)");
    }
  }
  RenderTimes times;
  RayCounts rays;
  const RenderOptions& options = inv.options;
  double png = 0;
  const auto renderTo = [&](const SceneDesc& scene, const std::string& path) {
    const Rgb8Image image = renderRgb8(scene, inv.width, inv.height, options, {inv.progress, &times, &rays});
    Stopwatch watch;
    writePng(image, path, options.threads);
    png += watch.lap();
  };
  if (inv.scene.writes.empty()) renderTo(inv.scene, "output.png");
  int status = 0;
  for (const WriteDesc& w : inv.scene.writes) {
    try {
      renderTo(sceneAt(inv.scene, w), w.path);
    } catch (const ParseError& e) {
      *inv.errors << e.what() << "\n";
      status = 1;
    } catch (const Error& e) {
      *inv.errors << ParseError(w.loc, e.what()).what() << "\n";
      status = 1;
    }
  }
  if (inv.stats) {
    const auto ms = [](double seconds) {
      char text[32];
      std::snprintf(text, sizeof text, "%.1f ms", seconds * 1000);
      return std::string(text);
    };
    *inv.stats << "raytrace: load " << ms(inv.loadSeconds) << ", build " << ms(times.build) << ", trace "
               << ms(times.trace) << ", png " << ms(png) << ", total "
               << ms(inv.loadSeconds + times.build + times.trace + png) << " (" << inv.width << "x" << inv.height
               << ", " << options.samples * options.samples << (options.samples == 1 ? " eye ray" : " eye rays")
               << " per pixel, " << options.threads << (options.threads == 1 ? " thread)\n" : " threads)\n");
    char line[160];
    std::snprintf(line, sizeof line,
                  "raytrace: rays %llu eye, %llu gather, %llu shadow, %llu secondary; %.2f M rays/s in trace\n",
                  (unsigned long long)rays.eye, (unsigned long long)rays.gather, (unsigned long long)rays.shadow,
                  (unsigned long long)rays.secondary, times.trace > 0 ? double(rays.total()) / times.trace / 1e6 : 0.0);
    *inv.stats << line;
  }
  return status;
}

}  // namespace rt
