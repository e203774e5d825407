#include "raytrace/app/commands.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <optional>

#include <unistd.h>

#include "raytrace/app/arguments.hpp"
#include "raytrace/app/invocation.hpp"
#include "raytrace/app/merge.hpp"
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
  const char* summary;          // what `raytrace help <command>` says it does
  bool writesImage = false;     // takes -o, --tile and --region
  bool sizeOptional = false;    // width and height may be left out for kDefaultSide × kDefaultSide
};

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"raycast", "<width> <height>", 2, raycast, "each pixel the colour of the first object its ray hits", true},
      {"sceneinfo", "", 0, sceneinfo, "the camera, lights and objects as parsed"},
      {"pixelray", "<width> <height> <x> <y>", 4, pixelray, "the eye ray of pixel (x, y), y counted upward"},
      {"firsthit", "<width> <height> <x> <y>", 4, firsthit, "the first object the pixel's eye ray hits"},
      {"render", "[<width> <height>]", 2, renderImage,
       "the ray-traced image; a .cli scene's `write`s each their own (default size 300 x 300)", true, true},
      {"pixelcolor", "<width> <height> <x> <y>", 4, pixelcolor, "the pixel's shaded colour and first hit"},
      {"printrays", "<width> <height> <x> <y>", 4, printrays, "every ray the pixel's colour is made of"},
      {"pixeltrace", "<width> <height> <x> <y>", 4, pixeltrace, "printrays with the shadow rays"},
      {"printbvh", "", 0, printbvh, "the bounding volume hierarchy of the scene"},
  };
  return table;
}

constexpr const char* kMergeUsage = "raytrace merge -o <image> <tile.exr>... [--threads N]";
constexpr const char* kMergeSummary =
    "the tiles of one render (--tile, --region) joined into its image, exactly as one machine renders it";

std::string commandUsage(const Command& c) {
  return std::string("raytrace ") + c.name + " <scene>" + (c.args[0] ? " " : "") + c.args;
}

const char* const kRenderOptions =
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
    "  --gi-cache=A                    irradiance caching of the first bounce, accuracy A in (0, 1]\n"
    "                                  (e.g. 0.15; smaller: more records, nearer plain -gi)\n"
    "  -normals                        colour each hit by its normal (debug)\n"
    "  --threads N                     load, build and render on N threads (default: every core); same\n"
    "                                  scene and image for any N\n"
    "  --quiet                         no progress line (shown only while rendering to a terminal)\n"
    "  --stats                         after render, how long loading, building, tracing and writing the\n"
    "                                  image took, and the rays traced by kind (stderr)\n"
    "  -sds                            accepted for the course; a hierarchy is used whenever it pays\n"
    "  --hierarchy=auto|always|never   force the bounding volume hierarchy on or off (same image)\n";

const char* const kImageOptions =
    "image options (raycast, render):\n"
    "  -o, --output FILE               the image file (default output.png); its extension picks the format:\n"
    "                                  .png (8-bit), .hdr (Radiance RGBE) or .exr (OpenEXR, 32-bit float),\n"
    "                                  the last two the linear radiance before clamping. For a .cli scene\n"
    "                                  that writes its own images, the folder to write them into\n"
    "  --allow-write-anywhere          let a .cli scene's 'write' leave its folder (an absolute path, '..', a link)\n"
    "                                  (by default it may only write into the current folder and below)\n"
    "  --tile I/N                      render only the I-th of N bands of rows (0 <= I < N), written to\n"
    "                                  -o NAME.exr as a tile for merge\n"
    "  --region X0,Y0,X1,Y1            render only columns X0 to X1-1 and rows Y0 to Y1-1, rows counted\n"
    "                                  from the top, written to -o NAME.exr as a tile for merge\n";

// The command nearest to `word` by edit distance, if a typo's distance away (at most 2).
const char* nearestCommand(const std::string& word) {
  const char* best = nullptr;
  size_t bestDistance = 3;
  std::vector<const char*> names{"merge", "help"};
  for (const Command& c : commands()) names.push_back(c.name);
  for (const char* candidate : names) {
    const std::string name(candidate);
    // Levenshtein distance, one row at a time.
    std::vector<size_t> row(name.size() + 1);
    for (size_t j = 0; j <= name.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= word.size(); ++i) {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= name.size(); ++j) {
        const size_t above = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (word[i - 1] == name[j - 1] ? 0 : 1)});
        diagonal = above;
      }
    }
    if (row[name.size()] < bestDistance) {
      bestDistance = row[name.size()];
      best = candidate;
    }
  }
  return best;
}

const Command* commandNamed(const std::string& name) {
  for (const Command& c : commands()) {
    if (name == c.name) return &c;
  }
  return nullptr;
}

[[noreturn]] void unknownCommand(const std::string& name) {
  const char* near = nearestCommand(name);
  throw Error("unknown command " + quote(name) + (near ? ": did you mean " + quote(near) + "?" : "") +
              " (see raytrace --help)");
}

const Command& findCommand(const std::vector<std::string>& args) {
  if (args.empty()) throw Error("no command given (see raytrace --help)");
  const Command* command = commandNamed(args[0]);
  if (!command) unknownCommand(args[0]);
  return *command;
}

// `raytrace help <command>` and `raytrace <command> --help`.
std::string commandHelp(const std::string& name) {
  if (name == "merge") return std::string("usage: ") + kMergeUsage + "\n" + kMergeSummary + "\n";
  const Command* c = commandNamed(name);
  if (!c) unknownCommand(name);
  return "usage: " + commandUsage(*c) + " [options]\n" + c->summary + "\n" + kRenderOptions +
         (c->writesImage ? kImageOptions : "");
}

}  // namespace

std::string usage() {
  std::string text = "usage:\n";
  for (const Command& c : commands()) text += "  " + commandUsage(c) + " [options]\n";
  text += std::string("  ") + kMergeUsage + "\n  raytrace help <command>\n  raytrace --version\n";
  return text + kRenderOptions + kImageOptions;
}

namespace {

// The text --help, --version, `help <command>` or `<command> --help` asks for; nothing when the arguments ask
// for a run.
std::optional<std::string> helpText(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  if (args[0] == "--help" || args[0] == "-h") return usage();
  if (args[0] == "--version") return std::string("raytrace ") + RAYTRACE_VERSION + "\n";
  if (args[0] == "help") {
    if (args.size() != 2) throw Error("help takes one command, as in: raytrace help render");
    return commandHelp(args[1]);
  }
  const bool known = args[0] == "merge" || commandNamed(args[0]);
  if (known && std::find(args.begin() + 1, args.end(), "--help") != args.end()) return commandHelp(args[0]);
  return std::nullopt;
}

// The value of an option written `--name VALUE` or `--name=VALUE` at args[i], moving i past it; nothing if
// args[i] is not that option.
std::optional<std::string> optionValue(const std::vector<std::string>& args, size_t& i,
                                       std::initializer_list<const char*> names) {
  for (const char* name : names) {
    const std::string n(name);
    if (args[i] == n) {
      if (i + 1 == args.size()) throw Error(n + " needs a value");
      return args[++i];
    }
    if (args[i].rfind(n + "=", 0) == 0) return args[i].substr(n.size() + 1);
  }
  return std::nullopt;
}

// The words after the command: flags, which start with '-' and a letter, and the positional arguments
// (a negative number too).
struct Words {
  std::vector<std::string> positional;
  RenderOptions options;
  bool stats = false, quiet = false;  // not render options: they say how a run is watched
  bool writeAnywhere = false;         // nor these: they are about the files render makes
  std::string output, outputWord;     // -o's value and the word that gave it, as written; "" without -o
  std::string tile, region;           // --tile's and --region's values; "" without them
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
    if (const auto v = optionValue(args, i, {"-o", "--output"})) {
      if (v->empty()) throw Error(a + " needs a file name");
      words.outputWord = a;
      words.output = *v;
      continue;
    }
    if (const auto v = optionValue(args, i, {"--tile"})) {
      words.tile = *v;
      continue;
    }
    if (const auto v = optionValue(args, i, {"--region"})) {
      words.region = *v;
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

// "I/N" of --tile: the I-th of N row bands of a picture `height` rows high.
Region parseTile(const std::string& value, int width, int height) {
  const size_t slash = value.find('/');
  if (slash == std::string::npos) throw Error("--tile must be I/N, as 0/4, found " + quote(value));
  const int n = parseInt(value.substr(slash + 1), "--tile's N", 1, height);
  const int i = parseInt(value.substr(0, slash), "--tile's I", 0, n - 1);
  return rowBand(i, n, width, height);
}

// "X0,Y0,X1,Y1" of --region, within the width × height picture.
Region parseRegion(const std::string& value, int width, int height) {
  std::vector<std::string> parts(1);
  for (const char c : value) {
    if (c == ',') parts.emplace_back();
    else parts.back() += c;
  }
  if (parts.size() != 4) throw Error("--region must be X0,Y0,X1,Y1, as 0,0,64,48, found " + quote(value));
  Region r;
  r.x0 = parseInt(parts[0], "--region's X0", 0, width - 1);
  r.y0 = parseInt(parts[1], "--region's Y0", 0, height - 1);
  r.x1 = parseInt(parts[2], "--region's X1", r.x0 + 1, width);
  r.y1 = parseInt(parts[3], "--region's Y1", r.y0 + 1, height);
  return r;
}

// The invocation the words make, all but the scene, checked before the scene is read.
Invocation invocation(const Command& command, const Words& words, std::ostream& err) {
  if (!command.writesImage) {
    const char* const forImages = " is for the commands that write images (raycast, render)";
    if (!words.outputWord.empty()) throw Error(words.outputWord + forImages);
    if (!words.tile.empty()) throw Error(std::string("--tile") + forImages);
    if (!words.region.empty()) throw Error(std::string("--region") + forImages);
  }
  const std::vector<std::string>& positional = words.positional;
  const bool defaultSize = command.sizeOptional && positional.size() == 1;
  if (positional.size() != size_t(1 + command.numbers) && !defaultSize) {
    throw Error(std::string(command.name) + " takes " + (command.sizeOptional ? "1 or " : "") +
                std::to_string(1 + command.numbers) + " arguments, found " + std::to_string(positional.size()) +
                " (usage: " + commandUsage(command) + ")");
  }
  if (words.stats && std::string(command.name) != "render") throw Error("--stats is for the render command only");
  if (!words.tile.empty() && !words.region.empty()) {
    throw Error("--tile and --region both name the part to render: give one");
  }
  Invocation inv;
  inv.scenePath = positional[0];
  inv.options = words.options;
  if (!words.quiet && isatty(STDERR_FILENO)) inv.progress = &err;  // only render() shows it, and only to a person
  if (words.stats) inv.stats = &err;
  inv.errors = &err;
  inv.writeAnywhere = words.writeAnywhere;
  inv.output = words.output;
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
  if (!words.tile.empty()) inv.region = parseTile(words.tile, inv.width, inv.height);
  if (!words.region.empty()) inv.region = parseRegion(words.region, inv.width, inv.height);
  inv.tile = words.tile;
  return inv;
}

// --dialect=course|povray, -L DIR (or -LDIR, +LDIR) and -D name=value (or Declare=name=value): how a .pov
// file is read, where a POV-Ray scene's #include looks, and identifiers it starts with. Taken out of the
// arguments before the others are read.
LoadOptions takeLoadFlags(std::vector<std::string>& args) {
  LoadOptions load;
  std::vector<std::string> rest;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--dialect=", 0) == 0) {
      const std::string d = a.substr(10);
      if (d != "course" && d != "povray") throw Error("--dialect must be course or povray, found " + quote(d));
      load.dialect = d == "course" ? Dialect::Course : Dialect::PovRay;
    } else if (a == "-L") {
      if (i + 1 == args.size()) throw Error("-L needs a folder after it");
      load.libraryPaths.push_back(args[++i]);
    } else if ((a.rfind("-L", 0) == 0 || a.rfind("+L", 0) == 0) && a.size() > 2) {
      load.libraryPaths.push_back(a.substr(2));
    } else if (a == "-D" && i + 1 < args.size() && args[i + 1].find('=') != std::string::npos) {
      load.declares.push_back(args[++i]);
    } else if (a.rfind("Declare=", 0) == 0 && a.find('=', 8) != std::string::npos) {
      load.declares.push_back(a.substr(8));
    } else {
      rest.push_back(a);
    }
  }
  args = rest;
  return load;
}

}  // namespace

int runCommand(const std::vector<std::string>& given, std::ostream& out, std::ostream& err) {
  std::vector<std::string> args = given;
  LoadOptions load = takeLoadFlags(args);
  if (const auto text = helpText(args)) {
    out << *text;
    return 0;
  }
  if (!args.empty() && args[0] == "merge") return merge(std::vector<std::string>(args.begin() + 1, args.end()));
  const Command& command = findCommand(args);
  const Words words = readWords(args);
  Invocation inv = invocation(command, words, err);
  if (command.writesImage) checkOutput(inv);
  // The image commands render on all their threads: the helpers start while the file is read.
  if (command.numbers == 2) startHelpers(inv.options.threads);
  Stopwatch watch;
  if (inv.width > 0 && inv.height > 0) {
    load.width = inv.width;
    load.height = inv.height;
  }
  inv.scene = loadScene(inv.scenePath, inv.options.threads, load);
  inv.loadSeconds = watch.lap();
  for (const std::string& w : collapseRepeats(inv.scene.warnings)) err << w << "\n";
  return command.run(inv, out);
}

}  // namespace rt
