// `raytrace merge -o OUT TILE...`: the tiles of one render (--tile, --region) joined into its image.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rt {

// The arguments after "merge". The tiles must be of the same render (scene contents, size, options, program
// version) and cover the picture exactly once; the image is then what the render on one machine makes, bit for
// bit, in any format (a PNG's bytes converted as that render converts them). Throws Error naming the file at
// fault, having written nothing.
//
// With a request (`--for SCENE WIDTH HEIGHT [render options]`, read by runCommand), every tile must also be a
// tile of that render: what a resumed render on many machines checks, so that no tile of an older request is
// merged. A merged OpenEXR image keeps the tiles' attributes, so it is a tile of its render in turn.
struct TileRequest {
  // tileHeader() of the whole picture; of each image a .cli scene writes, in its order.
  std::vector<std::map<std::string, std::string>> headers;
  int width = 0, height = 0;
  std::string output;               // the image when merge has no -o: a POV-Ray frame's numbered name
  std::vector<std::string> inputs;  // the scene and each file it read, for --manifest
};
int merge(const std::vector<std::string>& args, const std::optional<TileRequest>& request = std::nullopt);

}  // namespace rt
