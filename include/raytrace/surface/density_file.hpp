// POV-Ray's density_file pattern (POV-Ray 3.7 manual, "Density_File Pattern"): the voxels of a df3 file filling
// the unit cube, read by src/surface/patterns/density_file.cpp.
#pragma once

#include <string>
#include <vector>

#include "raytrace/util/error.hpp"

namespace rt {

// A df3 file's voxels, x fastest, then y, then z, each scaled into [0, 1] by its format's largest value.
struct DensityGrid {
  int nx = 0, ny = 0, nz = 0;
  std::vector<float> values;
};

// A df3 file: three big-endian 16-bit sizes, then the voxels as big-endian 8, 16 or 32-bit integers, their width
// told by the file's length. A ParseError at `at` when the file cannot be read, has no voxels, its length fits
// none of the three widths, or its voxels do not fit in memory.
DensityGrid readDensityFile(const std::string& path, const SourceLoc& at);

}  // namespace rt
