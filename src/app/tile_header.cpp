#include "raytrace/app/tile_header.hpp"

#include <cinttypes>
#include <cstdio>
#include <optional>

#include <sys/stat.h>

#include "raytrace/app/arguments.hpp"
#include "raytrace/image/exr_file.hpp"
#include "raytrace/parse/scene_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"

namespace rt {

namespace {

const char* toByteName(Dialect::ToByte mode) {
  switch (mode) {
    case Dialect::ToByte::Round: return "round";
    case Dialect::ToByte::Truncate: return "truncate";
    case Dialect::ToByte::Srgb: return "srgb";
  }
  return "round";
}

// FNV-1a, 64 bits (Fowler, Noll and Vo; IETF draft-eastlake-fnv) over the scene's bytes, then over each file
// it read, its name and bytes: a content check, not a defence against someone forging a scene.
std::string contentHash(const std::string& scenePath, const std::vector<std::string>& inputs) {
  uint64_t h = 0xcbf29ce484222325u;
  const auto add = [&h](std::string_view bytes) {
    for (const char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3u;
  };
  add(readFile(scenePath).view());
  for (const std::string& input : inputs) {
    add(std::string_view("\0", 1));
    add(input);
    add(std::string_view("\0", 1));
    add(readFile(input).view());
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, h);
  return hex;
}

std::string baseName(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

std::map<std::string, std::string> tileHeader(const Invocation& inv, const std::string& command,
                                              const WriteDesc* write) {
  const Region r = inv.region.value_or(wholeImage(inv.width, inv.height));
  std::map<std::string, std::string> header{
      {"raytrace.version", RAYTRACE_VERSION},
      {"raytrace.command", command},
      {"raytrace.scene", baseName(inv.scenePath)},
      {"raytrace.sceneHash", contentHash(inv.scenePath, inv.scene.inputFiles)},
      {"raytrace.size", std::to_string(inv.width) + "x" + std::to_string(inv.height)},
      {"raytrace.options", pixelFlags(inv.options)},
      {kToByteAttribute, toByteName(inv.scene.dialect.toByte())},
      {kTilePartAttribute, inv.tile.empty() ? std::to_string(r.x0) + "," + std::to_string(r.y0) + "," +
                                                  std::to_string(r.x1) + "," + std::to_string(r.y1)
                                            : inv.tile},
  };
  if (write) header[kImageAttribute] = write->path;
  // Only when given, so that the tiles of every other render keep their header.
  std::string declares;
  for (const std::string& d : inv.declares) declares += (declares.empty() ? "" : "\n") + d;
  if (!declares.empty()) header["raytrace.declares"] = declares;
  const povray::Clock& c = inv.clock;
  if (c.on) {
    char clock[256];
    std::snprintf(clock, sizeof clock, "frame %d of %d to %d; clock %.17g, delta %.17g, from %.17g to %.17g",
                  c.frame, c.initialFrame, c.finalFrame, c.clock, c.delta, c.initialClock, c.finalClock);
    header["raytrace.clock"] = clock;
  }
  return header;
}

std::string headerDifference(const std::map<std::string, std::string>& mine,
                             const std::map<std::string, std::string>& wanted, bool ignorePart) {
  auto keys = mine;
  keys.insert(wanted.begin(), wanted.end());
  for (const auto& [key, ignored] : keys) {
    if (ignorePart && key == kTilePartAttribute) continue;
    const auto a = mine.find(key), b = wanted.find(key);
    const std::string have = a == mine.end() ? "none" : quote(a->second);
    const std::string want = b == wanted.end() ? "none" : quote(b->second);
    if (have != want) return "its " + printable(key) + " is " + have + ", not " + want;
  }
  return "";
}

std::string tileStaleness(const Invocation& inv, const std::string& command, const std::string& path,
                          const WriteDesc* write) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return "missing";
  std::optional<ExrImage> read;
  try {
    read.emplace(readExr(path));
  } catch (const Error& e) {
    return "unreadable (" + printable(e.what(), kMaxQuotedPath) + ")";
  }
  const ExrImage& tile = *read;
  const std::string why = headerDifference(tile.attributes, tileHeader(inv, command, write), false);
  if (!why.empty()) return "stale (" + why + ")";
  const Region r = inv.region.value_or(wholeImage(inv.width, inv.height));
  if (tile.width != inv.width || tile.height != inv.height || !(tile.window == r)) {
    return "stale (its pixels are not this tile's)";
  }
  return "";
}

Dialect::ToByte toByteOf(const std::map<std::string, std::string>& header, const std::string& file) {
  const auto it = header.find(kToByteAttribute);
  if (it != header.end() && it->second == "round") return Dialect::ToByte::Round;
  if (it != header.end() && it->second == "truncate") return Dialect::ToByte::Truncate;
  if (it != header.end() && it->second == "srgb") return Dialect::ToByte::Srgb;
  throw Error(quote(file, kMaxQuotedPath) + " is not a raytrace tile: it has no " + kToByteAttribute +
              " of round, truncate or srgb");
}

}  // namespace rt
