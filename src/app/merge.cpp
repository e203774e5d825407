#include "raytrace/app/merge.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>

#include "raytrace/app/arguments.hpp"
#include "raytrace/app/tile_header.hpp"
#include "raytrace/image/exr_file.hpp"
#include "raytrace/image/image_file.hpp"
#include "raytrace/image/output_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/limits.hpp"
#include "raytrace/util/message.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/util/path.hpp"

namespace rt {

namespace {

constexpr const char* kSeeHelp = " (see raytrace help merge)";

struct MergeArguments {
  std::string output, manifest;
  std::vector<std::string> tiles;
  int threads = defaultThreads();
};

MergeArguments parseMerge(const std::vector<std::string>& args, const std::optional<TileRequest>& request) {
  MergeArguments m;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool valued = a == "-o" || a == "--output" || a == "--threads" || a == "--manifest";
    if (valued && i + 1 == args.size()) throw Error(a + " needs a value");
    if (a == "-o" || a == "--output") m.output = args[++i];
    else if (a == "--manifest") m.manifest = args[++i];
    else if (a.rfind("--output=", 0) == 0) m.output = a.substr(9);
    else if (a == "--threads") m.threads = parseInt(args[++i], "--threads", 1, kMaxThreads);
    else if (a.rfind("--threads=", 0) == 0) m.threads = parseInt(a.substr(10), "--threads", 1, kMaxThreads);
    else if (a.size() > 1 && a[0] == '-') throw Error("unknown option " + quote(a) + " for merge" + kSeeHelp);
    else m.tiles.push_back(a);
  }
  if (m.output.empty() && request) m.output = request->output;
  if (m.output.empty()) throw Error("merge needs -o OUTPUT, the image to write");
  if (m.tiles.empty()) throw Error("merge needs the tiles to join");
  return m;
}

std::string pixel(int x, int y) { return "column " + std::to_string(x) + ", row " + std::to_string(y); }

}  // namespace

int merge(const std::vector<std::string>& args, const std::optional<TileRequest>& request) {
  const MergeArguments m = parseMerge(args, request);
  checkImagePath(m.output);
  if (!m.manifest.empty()) checkWritableFolder(m.manifest);
  for (const std::string& name : m.tiles) {
    if (sameFile(name, m.output)) {
      throw Error("-o " + quote(m.output, kMaxQuotedPath) + " is the tile " + quote(name, kMaxQuotedPath) +
                  ": merge would replace it (name another file)");
    }
  }
  std::optional<ExrImage> first;
  std::optional<Image> image;
  std::vector<int> owner;  // per pixel of the picture, top row first: 1 + the index of the tile holding it
  for (size_t t = 0; t < m.tiles.size(); ++t) {
    const std::string& name = m.tiles[t];
    ExrImage tile = readExr(name);
    if (!tile.attributes.count("raytrace.command")) {
      throw Error(quote(name, kMaxQuotedPath) + " is not a raytrace tile: it has no raytrace.command attribute");
    }
    if (request) {
      // A tile of one of the scene's own images is checked against that image's request.
      const auto& headers = request->headers;
      const auto image = tile.attributes.find(kImageAttribute);
      auto wanted = headers.begin();
      while (image != tile.attributes.end() && wanted + 1 != headers.end() &&
             wanted->at(kImageAttribute) != image->second) {
        ++wanted;
      }
      std::string why = headerDifference(tile.attributes, *wanted, true);
      if (why.empty() && (tile.width != request->width || tile.height != request->height)) {
        why = "its picture is " + std::to_string(tile.width) + "x" + std::to_string(tile.height) + ", not " +
              std::to_string(request->width) + "x" + std::to_string(request->height);
      }
      if (!why.empty()) {
        throw Error(quote(name, kMaxQuotedPath) + " is not a tile of the render asked for: " + why);
      }
    }
    if (!first) {
      toByteOf(tile.attributes, name);
      // The picture and which tile holds each pixel, before taking them: a tile of a few bytes may name a
      // picture of 30000 x 30000.
      const std::uint64_t pixels = std::uint64_t(tile.width) * std::uint64_t(tile.height);
      const std::string shortage =
          memoryShortage("merging into a " + std::to_string(tile.width) + "x" + std::to_string(tile.height) +
                             " picture",
                         pixels * (sizeof(Color) + sizeof(int)), availableMemory());
      if (!shortage.empty()) throw Error(quote(name, kMaxQuotedPath) + ": " + shortage);
      image.emplace(tile.width, tile.height);
      owner.assign(size_t(tile.width) * size_t(tile.height), 0);
    } else {
      std::string why = headerDifference(tile.attributes, first->attributes, true);
      if (why.empty() && (tile.width != first->width || tile.height != first->height)) why = "its size differs";
      if (!why.empty()) {
        throw Error(quote(name, kMaxQuotedPath) + " is a tile of another render than " +
                    quote(m.tiles[0], kMaxQuotedPath) + ": " + why);
      }
    }
    const Region& r = tile.window;
    if (r.x0 < 0 || r.y0 < 0 || r.x1 > tile.width || r.y1 > tile.height) {
      throw Error(quote(name, kMaxQuotedPath) + " holds pixels outside its picture");
    }
    for (int y = r.y0; y < r.y1; ++y) {
      for (int x = r.x0; x < r.x1; ++x) {
        int& o = owner[size_t(y) * size_t(tile.width) + size_t(x)];
        if (o) {
          throw Error(quote(name, kMaxQuotedPath) + " overlaps " + quote(m.tiles[size_t(o - 1)], kMaxQuotedPath) +
                      " at " + pixel(x, y));
        }
        o = int(t) + 1;
      }
      std::copy(tile.pixels.data() + size_t(y - r.y0) * size_t(r.width()),
                tile.pixels.data() + size_t(y - r.y0 + 1) * size_t(r.width()),
                image->data() + size_t(y) * size_t(tile.width) + size_t(r.x0));
    }
    if (!first) first.emplace(std::move(tile));
  }
  const auto gap = std::find(owner.begin(), owner.end(), 0);
  if (gap != owner.end()) {
    const size_t at = size_t(gap - owner.begin());
    throw Error("the tiles leave " + std::to_string(std::count(owner.begin(), owner.end(), 0)) +
                " pixels of the picture uncovered, the first at " + pixel(int(at % size_t(first->width)),
                                                                          int(at / size_t(first->width))));
  }
  if (imageFormat(m.output) == ImageFormat::Exr) {
    // The one-machine render's header: the part is the whole picture.
    auto attributes = first->attributes;
    attributes[kTilePartAttribute] = "0,0," + std::to_string(first->width) + "," + std::to_string(first->height);
    writeExr(ExrImage{first->width, first->height, wholeImage(first->width, first->height), std::move(*image),
                      std::move(attributes)},
             m.output);
  } else {
    writeImage(*image, m.output, toByteOf(first->attributes, m.tiles[0]), m.threads);
  }
  if (!m.manifest.empty()) {
    // As render's --manifest: what was read (the scene and its files, then the tiles) and the image written.
    std::string text;
    for (const std::string& path : request ? request->inputs : std::vector<std::string>{}) text += path + "\n";
    for (const std::string& path : m.tiles) text += path + "\n";
    text += m.output + "\n";
    OutputFile file(m.manifest);
    file.write(text.data(), text.size());
    file.commit();
  }
  return 0;
}

}  // namespace rt
