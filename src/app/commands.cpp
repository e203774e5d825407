#include "raytrace/app/commands.hpp"

#include <cctype>
#include <functional>

#include <unistd.h>

#include "raytrace/app/arguments.hpp"
#include "raytrace/app/invocation.hpp"
#include "raytrace/parse/scene_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/util/stopwatch.hpp"

namespace rt {

namespace {

constexpr int kMaxImageSide = 32768;  // per side; larger is certainly a typo
constexpr int kDefaultSide = 300;     // the CS 3451 starter's size(300, 300) (docs/reference/cs3451.md §A.2)

struct Command {
  const char* name;
  const char* args;  // after the scene, for usage and messages
  int numbers;       // 0, 2 (width height) or 4 (width height x y)
  std::function<int(const Invocation&, std::ostream&)> run;
  bool sizeOptional = false;  // width and height may be left out for kDefaultSide × kDefaultSide
};

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
      "  --depth=N                       deepest reflection/refraction level, 0 to 64 (default: the scene\n"
      "                                  language's); a ray is traced only while it can still change its\n"
      "                                  pixel, and past depth 12 an eye ray's tree stops at 8191 rays\n"
      "  -altbrdf                        Cook-Torrance (GGX) instead of Blinn-Phong\n"
      "  -fresnel                        Schlick-weighted reflection and refraction\n"
      "  -beers                          Beer's-law absorption inside transparent objects\n"
      "  -ss=N                           N x N stratified samples per pixel (1 to 64)\n"
      "  -gi                             Monte Carlo global illumination: indirect light gathered with\n"
      "                                  stratified cosine-weighted rays instead of the ambient term\n"
      "  -gi_samples=N[,N...]            gather rays per hit at bounce 1, 2, ... (default 64,16)\n"
      "  -gi_bounces=B                   gathering levels (default: one per sample count; past the list,\n"
      "                                  its last count)\n"
      "  --seed N                        -gi's random numbers (default 0); same image for any threads\n"
      "  --gi-adaptive=E                 the first bounce gathers in rounds and stops once the standard\n"
      "                                  error of its light is below E (e.g. 0.01); -gi_samples caps it\n"
      "  -normals                        colour each hit by its normal (debug)\n"
      "  --threads N                     load, build and render on N threads (default: every core); same\n"
      "                                  scene and image for any N\n"
      "  --quiet                         no progress line (shown only while rendering to a terminal)\n"
      "  --stats                         after render, how long loading, building, tracing and writing the\n"
      "                                  PNG took, and the rays traced by kind (stderr)\n"
      "  -sds                            accepted for the course; a hierarchy is used whenever it pays\n"
      "  --hierarchy=auto|always|never   force the bounding volume hierarchy on or off (same image)\n"
      "  --allow-write-anywhere          let a .cli scene's 'write' name an absolute path or go up with '..'\n"
      "                                  (by default it may only write into the current folder and below)\n";
  return text;
}

namespace {

const Command& findCommand(const std::vector<std::string>& args) {
  if (args.empty()) throw Error("no command given (see raytrace --help)");
  for (const Command& c : commands()) {
    if (args[0] == c.name) return c;
  }
  throw Error("unknown command " + quote(args[0]) + " (see raytrace --help)");
}

// The words after the command: flags, which start with '-' and a letter, and the positional arguments
// (a negative number too).
struct Words {
  std::vector<std::string> positional;
  RenderOptions options;
  bool stats = false, quiet = false;  // not render options: they say how a run is watched
  bool writeAnywhere = false;         // nor this: it is about the files render makes
};

Words readWords(const std::vector<std::string>& args) {
  Words words;
  for (size_t i = 1; i < args.size(); ++i) {
    std::string a = args[i];
    if (a == "--stats") {
      words.stats = true;
      continue;
    }
    if (a == "--quiet") {
      words.quiet = true;
      continue;
    }
    if (a == "--allow-write-anywhere") {
      words.writeAnywhere = true;
      continue;
    }
    if (a == "--threads" || a == "--seed") {  // also written --threads=N, --seed=N
      if (i + 1 == args.size()) throw Error(a + (a == "--seed" ? " needs a number" : " needs a number of threads"));
      a += "=" + args[++i];
    }
    if (a.size() > 1 && a[0] == '-' && (std::isalpha(static_cast<unsigned char>(a[1])) || a[1] == '-')) {
      words.options = parseFlag(a, words.options);
    } else {
      words.positional.push_back(a);
    }
  }
  return words;
}

// The invocation the words make, all but the scene, checked before the scene is read.
Invocation invocation(const Command& command, const Words& words, std::ostream& err) {
  const std::vector<std::string>& positional = words.positional;
  const bool defaultSize = command.sizeOptional && positional.size() == 1;
  if (positional.size() != size_t(1 + command.numbers) && !defaultSize) {
    throw Error(std::string(command.name) + " takes " + (command.sizeOptional ? "1 or " : "") +
                std::to_string(1 + command.numbers) + " arguments, found " + std::to_string(positional.size()) +
                " (usage: " + commandUsage(command) + ")");
  }
  if (words.stats && std::string(command.name) != "render") throw Error("--stats is for the render command only");
  Invocation inv;
  inv.options = words.options;
  if (!words.quiet && isatty(STDERR_FILENO)) inv.progress = &err;  // only render() shows it, and only to a person
  if (words.stats) inv.stats = &err;
  inv.errors = &err;
  inv.writeAnywhere = words.writeAnywhere;
  if (defaultSize) {
    inv.width = inv.height = kDefaultSide;
  } else if (command.numbers >= 2) {
    inv.width = parseInt(positional[1], "width", 1, kMaxImageSide);
    inv.height = parseInt(positional[2], "height", 1, kMaxImageSide);
  }
  if (command.numbers == 4) {
    inv.x = parseInt(positional[3], "pixel x", 0, inv.width - 1);
    inv.y = parseInt(positional[4], "pixel y", 0, inv.height - 1);
  }
  return inv;
}

}  // namespace

int runCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    out << usage();
    return 0;
  }
  const Command& command = findCommand(args);
  const Words words = readWords(args);
  Invocation inv = invocation(command, words, err);
  // The image commands render on all their threads: the helpers start while the file is read.
  if (command.numbers == 2) startHelpers(inv.options.threads);
  Stopwatch watch;
  inv.scene = loadScene(words.positional[0], inv.options.threads);
  inv.loadSeconds = watch.lap();
  for (const std::string& w : collapseRepeats(inv.scene.warnings)) err << w << "\n";
  return command.run(inv, out);
}

}  // namespace rt
