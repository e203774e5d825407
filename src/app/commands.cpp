#include "raytrace/app/commands.hpp"

#include <algorithm>
#include <functional>
#include <optional>

#include <unistd.h>

#include "raytrace/app/arguments.hpp"
#include "raytrace/app/convert.hpp"
#include "raytrace/app/invocation.hpp"
#include "raytrace/app/merge.hpp"
#include "raytrace/app/povray_command_line.hpp"
#include "raytrace/app/tile_header.hpp"
#include "raytrace/parse/scene_file.hpp"
#include "raytrace/render/radiosity.hpp"
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
  const char* args;  // after the scene, for usage and messages; for a command of its own words, all of them
  int numbers;       // 0, 2 (width height) or 4 (width height x y)
  std::function<int(const Invocation&, std::ostream&)> run;
  const char* summary;          // what `raytrace help <command>` says it does
  bool writesImage = false;     // takes -o, --tile and --region
  bool sizeOptional = false;    // width and height may be left out for kDefaultSide × kDefaultSide
  // A command that reads no scene and parses its own words (the words after its name), instead of `run`, with
  // the help for its options.
  std::function<int(const std::vector<std::string>&, std::ostream&, std::ostream&)> runWords = nullptr;
  const char* ownOptions = "";
};

int mergeCommand(const std::vector<std::string>& args, std::ostream& err);

std::string commandHelp(const std::string& name);

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
      {"merge", "-o <image> <tile.exr>... [--threads N] [--for <scene> <width> <height> [options]]", 0, nullptr,
       "the tiles of one render (--tile, --region) joined into its image, exactly as one machine renders it",
       false, false,
       [](const std::vector<std::string>& words, std::ostream&, std::ostream& err) {
         return mergeCommand(words, err);
       },
       "options:\n"
       "  -o, --output FILE               the image (.png, .hdr or .exr; an .exr keeps the tiles' attributes)\n"
       "  --threads N                     convert on N threads (default: every core)\n"
       "  --for <scene> <width> <height> [render options]\n"
       "                                  last: every tile must be of this render (the scene's contents,\n"
       "                                  size, options and program version), or merge writes nothing\n"
       "  --for +I<scene> [POV-Ray options]\n"
       "                                  the same in POV-Ray's words, of one frame (+SF = +EF): its clock,\n"
       "                                  and without -o, the frame's numbered image name\n"
       "  --manifest FILE                 list in FILE the scene and the files it read (with --for), the\n"
       "                                  tiles and the image, one a line\n"},
      {"convert", "<mesh.obj|.ply> <mesh.inc> [--name NAME]", 0, nullptr,
       "an OBJ or PLY mesh written as a POV-Ray mesh2 include, its normals and uv kept", false, false,
       [](const std::vector<std::string>& words, std::ostream&, std::ostream&) { return convertCommand(words); },
       "options:\n"
       "  --name NAME                     the identifier the include declares (default: the mesh file's name,\n"
       "                                  capitalised: model.obj declares Model)\n"},
      {"help", "<command>", 0, nullptr, "the usage, summary and options of one command", false, false,
       [](const std::vector<std::string>& words, std::ostream& out, std::ostream&) {
         if (words.size() != 1) throw Error("help takes one command, as in: raytrace help render");
         out << commandHelp(words[0]);
         return 0;
       }},
  };
  return table;
}

std::string commandUsage(const Command& c) {
  return std::string("raytrace ") + c.name + (c.runWords ? "" : " <scene>") + (c.args[0] ? " " : "") + c.args;
}

// The usage line of `raytrace --help` and `raytrace help <command>`.
std::string usageLine(const Command& c) { return commandUsage(c) + (c.runWords ? "" : " [options]"); }

// The command nearest to `word` by edit distance, if a typo's distance away.
const char* nearestCommand(const std::string& word) {
  std::vector<const char*> names;
  for (const Command& c : commands()) names.push_back(c.name);
  return nearestName(word, names);
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
  const Command* c = commandNamed(name);
  if (!c) unknownCommand(name);
  const std::string head = "usage: " + usageLine(*c) + "\n" + c->summary + "\n";
  if (c->runWords) return head + c->ownOptions;
  return head + optionsHelp(Section::General) + (c->writesImage ? optionsHelp(Section::Image) : "");
}

}  // namespace

std::string usage() {
  std::string text = "usage:\n";
  for (const Command& c : commands()) text += "  " + usageLine(c) + "\n";
  text += "  raytrace --version\n  " + std::string(kPovRayUsage) + "\n";
  return text + optionsHelp(Section::General) + optionsHelp(Section::Image);
}

std::vector<CommandSummary> commandSummaries() {
  std::vector<CommandSummary> list;
  for (const Command& c : commands()) {
    list.push_back({c.name, usageLine(c), c.summary, !c.runWords, c.writesImage, std::string(c.name) == "render"});
  }
  return list;
}

namespace {

// The text --help, --version, `help <command>` or `<command> --help` asks for; nothing when the arguments ask
// for a run.
std::optional<std::string> helpText(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  if (args[0] == "--help" || args[0] == "-h") return usage();
  if (args[0] == "--version") return std::string("raytrace ") + RAYTRACE_VERSION + "\n";
  const Command* command = commandNamed(args[0]);
  if (command && std::find(args.begin() + 1, args.end(), "--help") != args.end()) return commandHelp(args[0]);
  return std::nullopt;
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
  // The options only some commands take, checked in the order of the table's scopes.
  const auto refuse = [&](Scope scope, bool takes, const char* why) {
    for (const std::string& name : words.scoped) {
      const auto option = std::find_if(optionTable().begin(), optionTable().end(), [&](const Option& o) {
        return name == o.name || (o.alias && name == o.alias);
      });
      if (option->scope == scope && !takes) throw Error(name + why);
    }
  };
  refuse(Scope::Image, command.writesImage, " is for the commands that write images (raycast, render)");
  const std::vector<std::string>& positional = words.positional;
  const bool defaultSize = command.sizeOptional && positional.size() == 1;
  if (positional.size() != size_t(1 + command.numbers) && !defaultSize) {
    throw Error(std::string(command.name) + " takes " + (command.sizeOptional ? "1 or " : "") +
                std::to_string(1 + command.numbers) + " arguments, found " + std::to_string(positional.size()) +
                " (usage: " + commandUsage(command) + ")");
  }
  refuse(Scope::Render, std::string(command.name) == "render", " is for the render command only");
  if (words.options.aa.method != 0 && words.options.samples != 1) {
    throw Error("--aa and -ss both choose the rays per pixel: give one");
  }
  if (!words.tile.empty() && !words.region.empty()) {
    throw Error("--tile and --region both name the part to render: give one");
  }
  if (words.resume && words.tile.empty() && words.region.empty()) {
    throw Error("--resume is for tiles: give --tile or --region");
  }
  Invocation inv;
  inv.scenePath = positional[0];
  inv.options = words.options;
  if (!words.quiet && isatty(STDERR_FILENO)) inv.progress = &err;  // only render() shows it, and only to a person
  if (words.stats) inv.stats = &err;
  inv.statsJson = words.statsJson;
  inv.display = words.display;
  inv.preview = words.preview;
  inv.errors = &err;
  inv.writeAnywhere = words.writeAnywhere;
  inv.resume = words.resume;
  inv.manifest = words.manifest;
  inv.declares = words.load.declares;
  inv.clock = words.load.clock;
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

// `merge ... [--for SCENE WIDTH HEIGHT [render options]]`: the words after --for are read as a render's, and
// the header its whole picture would have is what every tile must have.
int mergeCommand(const std::vector<std::string>& args, std::ostream& err) {
  const auto at = std::find(args.begin(), args.end(), "--for");
  const std::vector<std::string> own(args.begin(), at);
  if (at == args.end()) return merge(own);
  std::vector<std::string> request{"render"};
  request.insert(request.end(), at + 1, args.end());
  // The render in POV-Ray's words names one frame (+SF and +EF): its clock, and its name unless -o gives one.
  std::optional<PovRayFrame> frame;
  if (isPovRayCommandLine(std::vector<std::string>(at + 1, args.end()))) {
    const PovRayJob job = readPovRayCommandLine(std::vector<std::string>(at + 1, args.end()));
    if (job.frames.size() != 1) {
      throw Error("merge's --for names one picture, but it renders " + std::to_string(job.frames.size()) +
                  " frames: give one with +SF and +EF");
    }
    frame = job.frames[0];
    request = job.words;
  }
  Words words = readWords(request, 1);
  if (frame) words.load.clock = frame->clock;
  if (!words.output.empty() || !words.tile.empty() || !words.region.empty() || words.resume ||
      !words.manifest.empty()) {
    throw Error("merge's --for names the whole render: its scene, size and render options only");
  }
  if (words.positional.size() != 3) {
    throw Error("merge's --for takes the scene, width and height, then render options (see raytrace help merge)");
  }
  Invocation inv = invocation(*commandNamed("render"), words, err);
  inv.progress = nullptr;
  LoadOptions load = words.load;
  load.width = inv.width;
  load.height = inv.height;
  inv.scene = loadScene(inv.scenePath, inv.options.threads, load);
  useRadiosity(inv.options, inv.scene);
  TileRequest wanted{{}, inv.width, inv.height, frame ? frame->output : "", {inv.scenePath}};
  wanted.inputs.insert(wanted.inputs.end(), inv.scene.inputFiles.begin(), inv.scene.inputFiles.end());
  for (const WriteDesc& w : inv.scene.writes) wanted.headers.push_back(tileHeader(inv, "render", &w));
  if (wanted.headers.empty()) wanted.headers.push_back(tileHeader(inv, "render"));
  return merge(own, wanted);
}

// Runs `command`, one that reads a scene, with what its words say.
int runScene(const Command& command, const Words& words, std::ostream& out, std::ostream& err) {
  Invocation inv = invocation(command, words, err);
  if (command.writesImage) checkOutput(inv);
  // The image commands render on all their threads: the helpers start while the file is read.
  if (command.numbers == 2) startHelpers(inv.options.threads);
  Stopwatch watch;
  LoadOptions load = words.load;
  // A POV-Ray scene's #write files go beside the image (and only the image commands write them).
  const size_t slash = inv.output.rfind('/');
  if (slash != std::string::npos) load.writeFolder = inv.output.substr(0, slash == 0 ? 1 : slash);
  load.writeAnywhere = words.writeAnywhere;
  if (inv.width > 0 && inv.height > 0) {
    load.width = inv.width;
    load.height = inv.height;
  }
  inv.scene = loadScene(inv.scenePath, inv.options.threads, load);
  useRadiosity(inv.options, inv.scene);
  inv.loadSeconds = watch.lap();
  for (const std::string& w : collapseRepeats(inv.scene.warnings)) err << w << "\n";
  return command.run(inv, out);
}

}  // namespace

int runCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (const auto text = helpText(args)) {
    out << *text;
    return 0;
  }
  if (isPovRayCommandLine(args)) return runPovRayCommandLine(args, out, err);
  const Command& command = findCommand(args);
  if (command.runWords) return command.runWords(std::vector<std::string>(args.begin() + 1, args.end()), out, err);
  return runScene(command, readWords(args, 1), out, err);
}

int renderWords(const Words& words, std::ostream& out, std::ostream& err) {
  return runScene(*commandNamed("render"), words, out, err);
}

}  // namespace rt
