#include "raytrace/cli.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <limits>
#include <utility>

#include <unistd.h>

#include "raytrace/camera.hpp"
#include "raytrace/error.hpp"
#include "raytrace/image.hpp"
#include "raytrace/loader.hpp"
#include "raytrace/parallel.hpp"
#include "raytrace/precision.hpp"
#include "raytrace/ray_tree.hpp"
#include "raytrace/render.hpp"
#include "raytrace/report.hpp"
#include "raytrace/scene.hpp"
#include "raytrace/tracer.hpp"

namespace rt {

namespace {

constexpr int kMaxImageSide = 32768;  // per side; larger is certainly a typo
constexpr int kDefaultSide = 300;     // the CS 3451 starter's size(300, 300) (cs3451-course.md §A.2)
constexpr int kMaxThreads = 1024;

using Options = RenderOptions;

// What a command receives: the loaded scene and its checked numeric arguments.
struct Invocation {
  SceneDesc scene;
  int width = 0, height = 0, x = 0, y = 0;
  Options options;
  std::ostream* stats = nullptr;  // --stats: where render reports how long each step took
  double loadSeconds = 0;         // the reading of the scene file
};

struct Command {
  const char* name;
  const char* args;  // after the scene, for usage and messages
  int numbers;       // 0, 2 (width height) or 4 (width height x y)
  std::function<int(const Invocation&, std::ostream&)> run;
  bool sizeOptional = false;  // width and height may be left out for kDefaultSide × kDefaultSide
};

int parseInt(const std::string& s, const char* what, int lo, int hi) {
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0') {
    throw Error(std::string(what) + " must be a whole number, found '" + s + "'");
  }
  // A number too long for a long (ERANGE) is still a whole number, just out of range.
  if (errno == ERANGE || v < lo || v > hi) {
    throw Error(std::string(what) + " must be between " + std::to_string(lo) + " and " + std::to_string(hi) +
                ", found " + s);
  }
  return int(v);
}

// The value of `--flag=value` among `names`, or an error listing them: "--flag must be a, b or c, found 'v'".
template <class E>
E choice(const char* flag, const std::string& value, std::initializer_list<std::pair<const char*, E>> names) {
  std::string list;
  size_t i = 0;
  for (const auto& [name, e] : names) {
    if (value == name) return e;
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(name);
    ++i;
  }
  throw Error(std::string(flag) + " must be " + list + ", found '" + value + "'");
}

Options parseFlag(const std::string& flag, Options o) {
  const auto value = [&](const std::string& name) -> const char* {
    return flag.rfind(name + "=", 0) == 0 ? flag.c_str() + name.size() + 1 : nullptr;
  };
  if (flag == "-sds") return o;  // the course's "use a hierarchy": ours decides per scene (Scene, Hierarchy)
  if (const char* p = value("--precision")) {
    o.arithmetic.precision = choice<Precision>("--precision", p,
                                               {{"float", Precision::Float}, {"double", Precision::Double},
                                                {"course", Precision::Course}, {"auto", Precision::Auto}});
    return o;
  }
  if (const char* p = value("--sphere")) {
    o.arithmetic.sphere = choice<SphereMethod>("--sphere", p,
                                               {{"textbook", SphereMethod::Textbook},
                                                {"robust", SphereMethod::Robust}, {"auto", SphereMethod::Auto}});
    return o;
  }
  if (const char* p = value("--offset")) {
    o.arithmetic.offset = choice<OffsetPolicy>(
        "--offset", p,
        {{"relative", OffsetPolicy::Relative}, {"course", OffsetPolicy::Course},
         {"normal", OffsetPolicy::FixedNormal}, {"wb", OffsetPolicy::WaechterBinder}});
    return o;
  }
  if (const char* p = value("--hierarchy")) {
    o.hierarchy = choice<Hierarchy>("--hierarchy", p,
                                    {{"auto", Hierarchy::Auto}, {"always", Hierarchy::Always},
                                     {"never", Hierarchy::Never}});
    return o;
  }
  if (const char* p = value("--depth")) {
    o.depth = parseInt(p, "--depth", 0, 64);
    return o;
  }
  if (const char* p = value("-ss")) {
    o.samples = parseInt(p, "-ss", 1, 64);
    return o;
  }
  if (const char* p = value("--threads")) {
    o.threads = parseInt(p, "--threads", 1, kMaxThreads);
    return o;
  }
  if (flag == "-altbrdf") o.brdf = Brdf::CookTorrance;
  else if (flag == "-fresnel") o.fresnel = true;
  else if (flag == "-beers") o.beers = true;
  else if (flag == "-normals") o.normals = true;
  else if (flag == "--quiet") o.progress = nullptr;
  else throw Error("unknown option '" + flag + "' (see raytrace --help)");
  return o;
}

void printPixelRay(std::ostream& out, int x, int y, const glm::dvec3& origin, const glm::dvec3& dir) {
  out << "Pixel: [" << x << ", " << y << "] Ray: " << braces(origin) << " -> " << braces(dir) << "\n";
}

// Runs f(scene, camera) at the precision the scene needs.
template <class F> auto withScene(const Invocation& inv, F&& f) {
  const Arithmetic arithmetic = chooseArithmetic(inv.scene, inv.options.arithmetic);
  return withPrecision(arithmetic.precision, [&](auto tag) {
    using T = decltype(tag);
    const Scene<T> scene(inv.scene, arithmetic, inv.options.hierarchy, inv.options.threads);
    const Camera<T> camera(inv.scene.camera, inv.width, inv.height);
    return f(scene, camera);
  });
}

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
    const auto hit = scene.closestHit(ray, {});
    if (!hit) {
      out << "No Hit\n";
      return 0;
    }
    const ObjectDesc& object = inv.scene.objects[size_t(hit->object->id() - 1)];
    out << "T = " << fixed4(hit->t) << "\nObject Type: " << shapeName(object.shape)
        << "\nColor: " << bare(hit->object->material().pigment) << "\n";
    return 0;
  });
}

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

// The hierarchy the scene's bounded objects get, printed whether or not renders would use it.
int printbvh(const Invocation& inv, std::ostream& out) {
  const Arithmetic arithmetic = chooseArithmetic(inv.scene, inv.options.arithmetic);
  return withPrecision(arithmetic.precision, [&](auto tag) {
    const Scene<decltype(tag)> scene(inv.scene, arithmetic, Hierarchy::Always);
    const size_t bounded = scene.hierarchy()->objects().size();
    out << scene.objects().size() << " objects: " << bounded << " bounded, "
        << scene.objects().size() - bounded << " unbounded (tested one by one). Renders use the hierarchy from "
        << kHierarchyMinObjects << " bounded objects on: " << (bounded >= kHierarchyMinObjects ? "yes" : "no")
        << ".\n";
    scene.hierarchy()->print(out);
    return 0;
  });
}

// The Whitted render of Programs 2-4, written to output.png; a file that names its own images (.cli `write`)
// gets each of them instead, in file order, each showing the scene as it stood at its command.
int renderImage(const Invocation& inv, std::ostream&) {
  RenderTimes times;
  Options options = inv.options;
  options.times = &times;
  double png = 0;
  const auto renderTo = [&](const SceneDesc& scene, const std::string& path) {
    const Rgb8Image image = renderRgb8(scene, inv.width, inv.height, options);
    Stopwatch watch;
    writePng(image, path, options.threads);
    png += watch.lap();
  };
  if (inv.scene.writes.empty()) renderTo(inv.scene, "output.png");
  for (const WriteDesc& w : inv.scene.writes) renderTo(w.scene, w.path);
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
  }
  return 0;
}

// A colour as the course prints it, "(r, g, b)" in bytes (§a.0).
std::string bytes(const Color& c, Conventions::ToByte mode) {
  return "(" + std::to_string(toByte(c.r, mode)) + ", " + std::to_string(toByte(c.g, mode)) + ", " +
         std::to_string(toByte(c.b, mode)) + ")";
}

// The pixel's shaded colour with its eye ray and first hit (§a.2); with -ss, the first sub-sample's ray.
int pixelcolor(const Invocation& inv, std::ostream& out) {
  return withScene(inv, [&](const auto& scene, const auto& camera) {
    Tracer tracer(scene, inv.options);
    std::vector<RayRecord> trees;
    const Color color = tracer.pixel(camera, inv.x, inv.y, &trees);
    const RayRecord& eye = trees.front();
    printPixelRay(out, inv.x, inv.y, eye.origin, eye.dir);
    if (!eye.hit) {
      out << "No Hit\n";
      return 0;
    }
    out << "T = " << fixed4(eye.t) << "\nObject Type: " << eye.objectType
        << "\nBRDF: " << (inv.options.brdf == Brdf::BlinnPhong ? "Blinn-Phong" : "Cook-Torrance")
        << "\nColor: " << bytes(color, inv.scene.conventions.toByte) << "\n";
    return 0;
  });
}

// Every ray the pixel's colour is made of: printrays (§a.3) or, decorated with shadow rays, pixeltrace (§a.9).
int rayTrees(const Invocation& inv, std::ostream& out, bool decorated) {
  return withScene(inv, [&](const auto& scene, const auto& camera) {
    Tracer tracer(scene, inv.options);
    std::vector<RayRecord> trees;
    const Color color = tracer.pixel(camera, inv.x, inv.y, &trees);
    printRayTrees(out, inv.x, inv.y, bytes(color, inv.scene.conventions.toByte), trees, decorated);
    return 0;
  });
}
int printrays(const Invocation& inv, std::ostream& out) { return rayTrees(inv, out, false); }
int pixeltrace(const Invocation& inv, std::ostream& out) { return rayTrees(inv, out, true); }

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"raycast", "<width> <height>", 2, raycast},
      {"sceneinfo", "", 0, sceneinfo},
      {"pixelray", "<width> <height> <x> <y>", 4, pixelray},
      {"firsthit", "<width> <height> <x> <y>", 4, firsthit},
      {"render", "[<width> <height>]", 2, renderImage, true},
      {"pixelcolor", "<width> <height> <x> <y>", 4, pixelcolor},
      {"printrays", "<width> <height> <x> <y>", 4, printrays},
      {"pixeltrace", "<width> <height> <x> <y>", 4, pixeltrace},
      {"printbvh", "", 0, printbvh},
  };
  return table;
}

std::string commandUsage(const Command& c) {
  return std::string("raytrace ") + c.name + " <scene>" + (c.args[0] ? " " : "") + c.args;
}

}  // namespace

std::string usage() {
  std::string text = "usage:\n";
  for (const Command& c : commands()) text += "  " + commandUsage(c) + " [options]\n";
  text +=
      "options:\n"
      "  --precision=float|double|course|auto\n"
      "                                  arithmetic for geometry (default auto: chosen per scene); course\n"
      "                                  is the course reference's float arithmetic and 0.001 offsets\n"
      "  --sphere=textbook|robust|auto   ray-sphere formula (default auto: chosen per scene)\n"
      "  --offset=relative|course|normal|wb\n"
      "                                  spawned-ray origins (default: the arithmetic's): relative normal\n"
      "                                  offset, the course's 0.001 along the normal, a fixed 1e-4 along\n"
      "                                  the normal, or Waechter-Binder's ulp offset\n"
      "  --depth=N                       deepest reflection/refraction level (default: the scene language's)\n"
      "  -altbrdf                        Cook-Torrance (GGX) instead of Blinn-Phong\n"
      "  -fresnel                        Schlick-weighted reflection and refraction\n"
      "  -beers                          Beer's-law absorption inside transparent objects\n"
      "  -ss=N                           N x N stratified samples per pixel (1 to 64)\n"
      "  -normals                        colour each hit by its normal (debug)\n"
      "  --threads N                     load, build and render on N threads (default: every core); same\n"
      "                                  scene and image for any N\n"
      "  --quiet                         no progress line (shown only while rendering to a terminal)\n"
      "  --stats                         after render, how long loading, building, tracing and writing the\n"
      "                                  PNG took (stderr)\n"
      "  -sds                            accepted for the course; a hierarchy is used whenever it pays\n"
      "  --hierarchy=auto|always|never   force the bounding volume hierarchy on or off (same image)\n";
  return text;
}

int runCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.empty()) throw Error("no command given\n" + usage());
  if (args[0] == "--help" || args[0] == "-h") {
    out << usage();
    return 0;
  }
  const Command* command = nullptr;
  for (const Command& c : commands()) {
    if (args[0] == c.name) command = &c;
  }
  if (!command) throw Error("unknown command '" + args[0] + "'\n" + usage());

  // Flags start with '-' and a letter; anything else (a negative number too) is positional.
  std::vector<std::string> positional;
  Options options;
  bool stats = false;
  if (isatty(STDERR_FILENO)) options.progress = &err;  // only render() shows it, and only to a person
  for (size_t i = 1; i < args.size(); ++i) {
    std::string a = args[i];
    if (a == "--stats") {  // not a render option: the command line reports it
      stats = true;
      continue;
    }
    if (a == "--threads") {  // also written --threads=N
      if (i + 1 == args.size()) throw Error("--threads needs a number of threads");
      a += "=" + args[++i];
    }
    if (a.size() > 1 && a[0] == '-' && (std::isalpha(static_cast<unsigned char>(a[1])) || a[1] == '-')) {
      options = parseFlag(a, options);
    } else {
      positional.push_back(a);
    }
  }
  const bool defaultSize = command->sizeOptional && positional.size() == 1;
  if (positional.size() != size_t(1 + command->numbers) && !defaultSize) {
    throw Error(std::string(command->name) + " takes " + (command->sizeOptional ? "1 or " : "") +
                std::to_string(1 + command->numbers) + " arguments, found " + std::to_string(positional.size()) +
                "\nusage: " + commandUsage(*command));
  }
  if (stats && std::string(command->name) != "render") throw Error("--stats is for the render command only");
  Invocation inv;
  inv.options = options;
  if (stats) inv.stats = &err;
  if (defaultSize) {
    inv.width = inv.height = kDefaultSide;
  } else if (command->numbers >= 2) {
    inv.width = parseInt(positional[1], "width", 1, kMaxImageSide);
    inv.height = parseInt(positional[2], "height", 1, kMaxImageSide);
  }
  if (command->numbers == 4) {
    inv.x = parseInt(positional[3], "pixel x", 0, inv.width - 1);
    inv.y = parseInt(positional[4], "pixel y", 0, inv.height - 1);
  }
  // The image commands render on all their threads: the helpers start while the file is read.
  if (command->numbers == 2) startHelpers(options.threads);
  Stopwatch watch;
  inv.scene = loadScene(positional[0], options.threads);
  inv.loadSeconds = watch.lap();
  for (const std::string& w : inv.scene.warnings) err << w << "\n";
  return command->run(inv, out);
}

}  // namespace rt
