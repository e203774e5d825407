// `raytrace merge -o OUT TILE...`: the tiles of one render (--tile, --region) joined into its image.
#pragma once

#include <string>
#include <vector>

namespace rt {

// The arguments after "merge". The tiles must be of the same render (scene contents, size, options, program
// version) and cover the picture exactly once; the image is then what the render on one machine makes, bit for
// bit, in any format (a PNG's bytes converted as that render converts them). Throws Error naming the file at
// fault, having written nothing.
int merge(const std::vector<std::string>& args);

}  // namespace rt
