// The command line's words turned into values: whole numbers in a range, and the flags of RenderOptions.
#pragma once

#include <string>
#include <vector>

#include "raytrace/render/options.hpp"

namespace rt {

// `s` as a whole number in [lo, hi], or an Error naming `what`.
int parseInt(const std::string& s, const char* what, int lo, int hi);

// A comma-separated list of whole numbers, each in [lo, hi] ("64,16"), or an Error naming `what`.
std::vector<int> parseCounts(const std::string& s, const char* what, int lo, int hi);

// `options` with one flag (`-fresnel`, `--depth=3`, ...) applied, or an Error for an unknown or bad flag.
RenderOptions parseFlag(const std::string& flag, RenderOptions options);

}  // namespace rt
