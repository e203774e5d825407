// The commands that write images: raycast (Program 1) and render, whole or one tile of the picture.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <sys/stat.h>

#include "raytrace/app/display_window.hpp"
#include "raytrace/app/invocation.hpp"
#include "raytrace/app/live_picture.hpp"
#include "raytrace/app/preview_file.hpp"
#include "raytrace/app/stats_report.hpp"
#include "raytrace/app/tile_header.hpp"
#include "raytrace/image/exr_file.hpp"
#include "raytrace/image/image.hpp"
#include "raytrace/image/image_file.hpp"
#include "raytrace/image/output_file.hpp"
#include "raytrace/image/png_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"
#include "raytrace/util/path.hpp"
#include "raytrace/util/peak_memory.hpp"
#include "raytrace/util/stopwatch.hpp"

namespace rt {

namespace {

constexpr const char* kDefaultOutput = "output.png";  // the course graders look for it

bool isFolder(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// One image a command makes: the file it goes to and the .cli `write` that asks for it (none: the whole scene).
struct Target {
  std::string path;
  const WriteDesc* write = nullptr;
};

// Where the images go: -o or output.png; for a .cli scene with `write`s (when `sceneWrites`), each to its own
// name, inside the -o folder if there is one, or to the -o file if the scene writes one image; a tile of each
// goes into the -o folder as its name with .exr for its extension. A name the scene gives must stay in the
// folder (staysInFolder, linksOut) unless --allow-write-anywhere.
std::vector<Target> targets(const Invocation& inv, bool sceneWrites) {
  const std::vector<WriteDesc>& writes = inv.scene.writes;
  const bool folder = !inv.output.empty() && isFolder(inv.output);
  std::vector<Target> out;
  if (!sceneWrites || writes.empty()) {
    if (folder) {
      throw Error("-o " + quote(inv.output, kMaxQuotedPath) + " is a folder, but " +
                  quote(inv.scenePath, kMaxQuotedPath) + " names no images of its own: give -o the image's file name");
    }
    out.push_back({inv.output.empty() ? kDefaultOutput : inv.output});
  } else if (!inv.output.empty() && !folder) {
    if (writes.size() != 1) {
      throw Error(quote(inv.scenePath, kMaxQuotedPath) + " writes " + std::to_string(writes.size()) +
                  " images: -o must name a folder to write them into");
    }
    out.push_back({inv.output, &writes[0]});
  } else {
    for (const WriteDesc& w : writes) {
      if (!inv.writeAnywhere && !staysInFolder(w.path)) {
        throw ParseError(w.loc, "'write' may only name a file in the folder the scene is rendered into and below, "
                                "found " + quote(w.path) + " (--allow-write-anywhere allows it)");
      }
      if (!inv.writeAnywhere && linksOut(folder ? inv.output : ".", w.path)) {
        throw ParseError(w.loc, "'write' names " + quote(w.path) + ", but a folder on its way is a symbolic link "
                                "out of the folder the scene is rendered into (--allow-write-anywhere allows it)");
      }
      std::string path = folder && w.path[0] != '/' ? inv.output + "/" + w.path : w.path;
      if (inv.region) {
        const size_t ext = extension(path).size();
        path = path.substr(0, path.size() - (ext ? ext + 1 : 0)) + ".exr";
      }
      for (const Target& t : out) {
        if (t.path == path) throw ParseError(w.loc, "this image's tile would be " + quote(path) + " too");
      }
      out.push_back({path, &w});
    }
  }
  return out;
}

// The image of inv's picture, or of its region, written to `path`. An OpenEXR file carries the render's
// attributes (tile_header.hpp), so that merge takes a whole image as a tile of itself.
void write(const Invocation& inv, const char* command, Image&& image, const Target& target,
           Dialect::ToByte mode) {
  if (imageFormat(target.path) != ImageFormat::Exr) return writeImage(image, target.path, mode, inv.options.threads);
  const Region region = inv.region.value_or(wholeImage(inv.width, inv.height));
  writeExr(ExrImage{inv.width, inv.height, region, std::move(image), tileHeader(inv, command, target.write)},
           target.path);
}

// checkImagePath(path), and that `path` is not the scene file (under any name): the image must not replace it.
void checkTarget(const Invocation& inv, const std::string& path) {
  checkImagePath(path);
  if (sameFile(path, inv.scenePath)) {
    throw Error("cannot write " + quote(path, kMaxQuotedPath) +
                ": it is the scene file, which the image would replace");
  }
}

// Throws, located at its #fopen, the error a file a POV-Ray scene wrote would meet (a folder missing or not
// writable), or if it would replace the scene file or the image.
void checkDataFiles(const Invocation& inv, const std::string& image) {
  for (const DataFileDesc& d : inv.scene.dataFiles) {
    const bool scene = sameFile(d.path, inv.scenePath);
    if (scene || sameFile(d.path, image) || d.path == image) {
      throw ParseError(d.loc, std::string("#fopen would replace ") + (scene ? "the scene file " : "the image ") +
                                  quote(d.path, kMaxQuotedPath));
    }
    try {
      checkWritableFolder(d.path);
    } catch (const Error& e) {
      throw ParseError(d.loc, e.what());
    }
  }
}

// The files a POV-Ray scene wrote, put on disk once its image is, each whole or not at all (output_file.hpp):
// a run that fails leaves none. The diagnostic commands never write them.
void writeDataFiles(const Invocation& inv) {
  for (const DataFileDesc& d : inv.scene.dataFiles) {
    try {
      OutputFile file(d.path);
      file.write(d.text.data(), d.text.size());
      file.commit();
    } catch (const Error& e) {
      throw ParseError(d.loc, e.what());
    }
  }
}

// With --resume, whether the tile at `path` is already the one this render makes, so that it is kept; either
// way the user is told, and why a tile is rendered again.
bool keptTile(const Invocation& inv, const char* command, const Target& target) {
  if (!inv.resume) return false;
  const std::string why = tileStaleness(inv, command, target.path, target.write);
  *inv.errors << "raytrace: " << quote(target.path, kMaxQuotedPath)
              << (why.empty() ? " is already this tile: kept" : " is " + why + ": rendering it") << "\n";
  return why.empty();
}

// --manifest: the scene, each file it read, each image and each file it wrote, one a line, written whole once
// they are all on disk; a frame's stamp is the hash of these files (tools/render-parallel --frames).
void writeManifest(const Invocation& inv, const std::vector<Target>& images) {
  if (inv.manifest.empty()) return;
  std::string text = inv.scenePath + "\n";
  for (const std::string& path : inv.scene.inputFiles) text += path + "\n";
  for (const Target& t : images) text += t.path + "\n";
  for (const DataFileDesc& d : inv.scene.dataFiles) text += d.path + "\n";
  OutputFile file(inv.manifest);
  file.write(text.data(), text.size());
  file.commit();
}

}  // namespace

void checkOutput(const Invocation& inv) {
  if (inv.region) {
    if (inv.output.empty()) throw Error("a tile is written as OpenEXR: name it with -o NAME.exr");
    if (!isFolder(inv.output) && imageFormat(inv.output) != ImageFormat::Exr) {
      throw Error("cannot write " + quote(inv.output, kMaxQuotedPath) +
                  ": a tile is written as OpenEXR (name it .exr)");
    }
  }
  if (!inv.output.empty() && !isFolder(inv.output)) checkImagePath(inv.output);
  if (!inv.preview.empty()) checkImagePath(inv.preview);
  if (!inv.manifest.empty()) checkWritableFolder(inv.manifest);
}

// Each pixel gets the pigment of the closest object, or the background (Program 1's ray cast).
int raycast(const Invocation& inv, std::ostream&) {
  const Target target = targets(inv, false).front();
  checkTarget(inv, target.path);
  checkDataFiles(inv, target.path);
  if (keptTile(inv, "raycast", target)) {
    writeManifest(inv, {target});
    return 0;
  }
  const Region region = inv.region.value_or(wholeImage(inv.width, inv.height));
  Image image(region.width(), region.height());
  // Image::at counts rows upward from the bottom; the region's rows counted from the top.
  const int bottom = inv.height - region.y1;
  withScene(inv, [&](const auto& scene, const auto& camera) {
    for (int y = bottom; y < inv.height - region.y0; ++y) {
      for (int x = region.x0; x < region.x1; ++x) {
        const auto hit = scene.closestHit(camera.pixelRay(x, y), {}, Sight::Image);
        Material textured;
        image.at(x - region.x0, y - bottom) =
            hit ? hit->object->materialAt(*hit, textured).pigment : inv.scene.background;
      }
    }
    return 0;
  });
  write(inv, "raycast", std::move(image), target, inv.scene.dialect.toByte());
  writeDataFiles(inv);
  writeManifest(inv, {target});
  return 0;
}

// The Whitted render of Programs 2-4; a .cli file that names its own images (`write`) gets each of them, in
// file order, each showing the scene as it stood at its command. Every path is checked before anything is
// rendered; a write that fails is reported where the file asks for it and the others are still made, the exit
// status tells.
int renderImage(const Invocation& inv, std::ostream&) {
  RenderTimes times;
  RayCounts rays;
  const RenderOptions& options = inv.options;
  const std::vector<Target> all = targets(inv, true);
  for (const Target& t : all) checkDataFiles(inv, t.path);
  int status = 0;
  // Runs `step` for target t. The Error of a scene's own write is reported at the write and the others go on.
  const auto attempt = [&](const Target& t, const auto& step) {
    try {
      step();
      return true;
    } catch (const ParseError& e) {
      if (!t.write) throw;
      *inv.errors << e.what() << "\n";
    } catch (const Error& e) {
      if (!t.write) throw;
      *inv.errors << ParseError(t.write->loc, e.what()).what() << "\n";
    }
    status = 1;
    return false;
  };
  std::vector<const Target*> writable;
  for (const Target& t : all) {
    if (attempt(t, [&] { checkTarget(inv, t.path); }) && !(inv.region && keptTile(inv, "render", t))) {
      writable.push_back(&t);
    }
  }
  double writing = 0;
  const auto renderTo = [&](const SceneDesc& scene, const Target& target) {
    const std::string& path = target.path;
    // --display and --preview watch the picture fill in. The preview's last write comes before the image's, so
    // that no two files are written at once (one temporary file is removed on an interrupt); the window
    // closes once the image is written.
    const Region region = inv.region.value_or(wholeImage(inv.width, inv.height));
    std::optional<LivePicture> picture;
    if (inv.display || !inv.preview.empty()) picture.emplace(inv.height, region, scene.dialect.toByte());
    std::optional<DisplayWindow> window;
    if (inv.display) window.emplace(*picture, *inv.errors);
    std::optional<PreviewFile> preview;
    if (!inv.preview.empty()) preview.emplace(*picture, inv.preview, scene.dialect.toByte(), *inv.errors);
    RenderMonitor monitor{inv.progress, &times, &rays, picture ? &*picture : nullptr};
    // A whole PNG is rendered straight to bytes; everything else keeps the floats.
    if (!inv.region && imageFormat(path) == ImageFormat::Png) {
      const Rgb8Image image = renderRgb8(scene, inv.width, inv.height, options, monitor);
      preview.reset();
      Stopwatch watch;
      writePng(image, path);
      writing += watch.lap();
    } else {
      Image image = render(scene, inv.width, inv.height, region, options, monitor);
      preview.reset();
      Stopwatch watch;
      write(inv, "render", std::move(image), target, scene.dialect.toByte());
      writing += watch.lap();
    }
  };
  for (const Target* t : writable) {
    attempt(*t, [&] {
      if (t->write) renderTo(sceneAt(inv.scene, *t->write), *t);
      else renderTo(inv.scene, *t);
    });
  }
  writeDataFiles(inv);
  if (status == 0) writeManifest(inv, all);
  if (inv.stats) {
    RenderStats stats;
    stats.width = inv.width;
    stats.height = inv.height;
    // Adaptive anti-aliasing and focal blur trace as many eye rays as each pixel needs: their mean.
    const CameraDesc::FocalBlur& blur = inv.scene.camera.focalBlur;
    if (options.aa.method != 0 || (blur.aperture > 0 && blur.maxSamples > 0)) {
      const Region r = inv.region.value_or(wholeImage(inv.width, inv.height));
      stats.eyeRays = double(rays.eye) / (double(r.width()) * double(r.height()) * double(std::max<size_t>(writable.size(), 1)));
    } else {
      stats.eyeRays = options.samples * options.samples;
    }
    stats.threads = options.threads;
    stats.cache = options.gi.enabled && options.gi.cache;
    stats.load = inv.loadSeconds;
    stats.build = times.build;
    stats.trace = times.trace;
    stats.write = writing;
    stats.rays = rays;
    stats.peakMemory = peakMemory();
    *inv.stats << (inv.statsJson ? statsJson(stats) : statsText(stats));
  }
  return status;
}

}  // namespace rt
