#include "raytrace/app/tile_header.hpp"

#include <cinttypes>
#include <cstdio>

#include "raytrace/app/arguments.hpp"
#include "raytrace/parse/scene_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"

namespace rt {

namespace {

// FNV-1a, 64 bits (Fowler, Noll and Vo; IETF draft-eastlake-fnv): a content check, not a defence against
// someone forging a scene.
std::string contentHash(const std::string& path) {
  const FileText text = readFile(path);
  uint64_t h = 0xcbf29ce484222325u;
  for (const char c : text.view()) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3u;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, h);
  return hex;
}

std::string baseName(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

std::map<std::string, std::string> tileHeader(const Invocation& inv, const std::string& command) {
  const Region r = inv.region.value_or(wholeImage(inv.width, inv.height));
  return {
      {"raytrace.version", RAYTRACE_VERSION},
      {"raytrace.command", command},
      {"raytrace.scene", baseName(inv.scenePath)},
      {"raytrace.sceneHash", contentHash(inv.scenePath)},
      {"raytrace.size", std::to_string(inv.width) + "x" + std::to_string(inv.height)},
      {"raytrace.options", pixelFlags(inv.options)},
      {kToByteAttribute, inv.scene.conventions.toByte == Conventions::ToByte::Round ? "round" : "truncate"},
      {kTilePartAttribute, inv.tile.empty() ? std::to_string(r.x0) + "," + std::to_string(r.y0) + "," +
                                                  std::to_string(r.x1) + "," + std::to_string(r.y1)
                                            : inv.tile},
  };
}

Conventions::ToByte toByteOf(const std::map<std::string, std::string>& header, const std::string& file) {
  const auto it = header.find(kToByteAttribute);
  if (it != header.end() && it->second == "round") return Conventions::ToByte::Round;
  if (it != header.end() && it->second == "truncate") return Conventions::ToByte::Truncate;
  throw Error(quote(file, kMaxQuotedPath) + " is not a raytrace tile: it has no " + kToByteAttribute +
              " of round or truncate");
}

}  // namespace rt
