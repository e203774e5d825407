// What a tile's OpenEXR header says of the render it belongs to, so that merge joins only the parts of one
// render: the scene, its contents, the size, the options that change pixels and the byte conversion.
#pragma once

#include <map>
#include <string>

#include "raytrace/app/invocation.hpp"

namespace rt {

// The attribute naming which part of the picture a tile holds ("3/8", or "x0,y0,x1,y1" for --region): for
// people reading the header; merge goes by the data window.
constexpr const char* kTilePartAttribute = "raytrace.part";
// The attribute naming the byte conversion ("round" or "truncate") that turns the tile's floats into a PNG's
// bytes, the scene language's (Dialect::ToByte).
constexpr const char* kToByteAttribute = "raytrace.toByte";

// The attribute naming which of a .cli scene's own images (its `write`) a tile is of.
constexpr const char* kImageAttribute = "raytrace.image";

// Every attribute of a tile of `command` ("render" or "raycast") with `inv`, or of the whole image; of the image
// `write` names if the scene writes its own. The scene file is read again for its hash (FNV-1a, 64 bits).
std::map<std::string, std::string> tileHeader(const Invocation& inv, const std::string& command,
                                              const WriteDesc* write = nullptr);

// The first attribute in which header `mine` differs from `wanted`, the part too unless `ignorePart`:
// "its raytrace.size is '61x43', not '80x60'", or "" if none. Values are quoted and bounded.
std::string headerDifference(const std::map<std::string, std::string>& mine,
                             const std::map<std::string, std::string>& wanted, bool ignorePart);

// Why the file at `path` is not the tile of `command` with `inv` (its header, picture size and data window):
// "" when it is; "missing", "unreadable (<error>)" or "stale (its <attribute> is ..., not ...)".
std::string tileStaleness(const Invocation& inv, const std::string& command, const std::string& path,
                          const WriteDesc* write = nullptr);

// The byte conversion a header names, or an Error naming `file` for another value.
Dialect::ToByte toByteOf(const std::map<std::string, std::string>& header, const std::string& file);

}  // namespace rt
