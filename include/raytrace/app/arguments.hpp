// The command line's words turned into values: whole numbers in a range, and the flags of RenderOptions.
#pragma once

#include <string>
#include <vector>

#include "raytrace/render/options.hpp"

namespace rt {

constexpr int kMaxThreads = 1024;  // for --threads

// `s` as a whole number in [lo, hi], or an Error naming `what`.
int parseInt(const std::string& s, const char* what, int lo, int hi);

// A comma-separated list of whole numbers, each in [lo, hi] ("64,16"), or an Error naming `what`.
std::vector<int> parseCounts(const std::string& s, const char* what, int lo, int hi);

// `options` with one flag (`-fresnel`, `--depth=3`, ...) applied, or an Error for an unknown or bad flag.
RenderOptions parseFlag(const std::string& flag, RenderOptions options);

// The flags that give `options` the values that change pixels, in a fixed order, defaults left out: ""
// or "--depth=3 -ss=2 -fresnel". Two renders with the same flags here make the same pixels of the same scene.
std::string pixelFlags(const RenderOptions& options);

}  // namespace rt
