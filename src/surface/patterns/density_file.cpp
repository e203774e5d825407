// density_file df3 "file" [interpolate 0|1|2]: the voxel holding the point, in the unit cube and 0 outside it;
// interpolate 1 blends the eight nearest voxels, 2 the 64 nearest by Catmull-Rom weights, clamped into [0, 1].
// Voxel i of n lies at i / n and the blends wrap round the cube's faces (POV-Ray 3.7 manual, "Density_File
// Pattern"; the positions, the wrapping and the cubic's weights measured on POV-Ray's values, docs/povray-noise.md).
#include "raytrace/surface/density_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "raytrace/surface/patterns.hpp"
#include "raytrace/util/limits.hpp"

namespace rt {

DensityGrid readDensityFile(const std::string& path, const SourceLoc& at) {
  const std::string what = "the density file \"" + path + "\"";
  std::error_code error;
  const std::uintmax_t length = std::filesystem::file_size(path, error);
  std::ifstream in(path, std::ios::binary);
  if (error || !in) throw ParseError(at, "cannot read " + what);
  unsigned char header[6];
  if (length < 6 || !in.read(reinterpret_cast<char*>(header), 6)) throw ParseError(at, what + " has no df3 header");
  DensityGrid grid;
  grid.nx = header[0] << 8 | header[1];
  grid.ny = header[2] << 8 | header[3];
  grid.nz = header[4] << 8 | header[5];
  const std::uint64_t count = std::uint64_t(grid.nx) * std::uint64_t(grid.ny) * std::uint64_t(grid.nz);
  if (count == 0) throw ParseError(at, what + " has no voxels");
  const std::uint64_t bytes = length - 6;
  const std::uint64_t width = bytes / count;
  if (bytes % count != 0 || (width != 1 && width != 2 && width != 4)) {
    throw ParseError(at, what + " holds " + std::to_string(bytes) + " bytes of voxels, which is not 1, 2 or 4 for each of its " +
                             std::to_string(grid.nx) + "x" + std::to_string(grid.ny) + "x" + std::to_string(grid.nz));
  }
  // The file's bytes and the voxels as floats are held at once.
  const std::string shortage = memoryShortage(what, bytes + count * sizeof(float), availableMemory());
  if (!shortage.empty()) throw ParseError(at, shortage);
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (data.size() != bytes) throw ParseError(at, "cannot read " + what);
  const double largest = width == 1 ? 255.0 : width == 2 ? 65535.0 : 4294967295.0;
  grid.values.resize(size_t(count));
  for (size_t i = 0; i < grid.values.size(); ++i) {
    std::uint32_t v = 0;
    for (size_t b = 0; b < width; ++b) v = v << 8 | std::uint8_t(data[i * width + b]);
    grid.values[i] = float(v / largest);
  }
  return grid;
}

namespace {

// The Catmull-Rom weights of the four voxels around a point a fraction t past the second.
void catmullRom(double t, double w[4]) {
  const double t2 = t * t, t3 = t2 * t;
  w[0] = (-t3 + 2 * t2 - t) / 2;
  w[1] = (3 * t3 - 5 * t2 + 2) / 2;
  w[2] = (-3 * t3 + 4 * t2 + t) / 2;
  w[3] = (t3 - t2) / 2;
}

class DensityFile final : public Pattern {
 public:
  DensityFile(std::shared_ptr<const DensityGrid> grid, int interpolation)
      : grid_(std::move(grid)), interpolation_(interpolation) {}

  double value(const glm::dvec3& p) const override {
    if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1 && p.z >= 0 && p.z < 1)) return 0;
    const DensityGrid& g = *grid_;
    const glm::dvec3 u = p * glm::dvec3(g.nx, g.ny, g.nz);
    const int x = int(u.x), y = int(u.y), z = int(u.z);
    if (interpolation_ == 0) return voxel(x, y, z);
    const glm::dvec3 t = u - glm::dvec3(x, y, z);
    if (interpolation_ == 1) {
      double sum = 0;
      for (int k = 0; k < 8; ++k) {
        const int dx = k & 1, dy = k >> 1 & 1, dz = k >> 2;
        sum += (dx ? t.x : 1 - t.x) * (dy ? t.y : 1 - t.y) * (dz ? t.z : 1 - t.z) * voxel(x + dx, y + dy, z + dz);
      }
      return sum;
    }
    double wx[4], wy[4], wz[4];
    catmullRom(t.x, wx);
    catmullRom(t.y, wy);
    catmullRom(t.z, wz);
    double sum = 0;
    for (int k = 0; k < 4; ++k) {
      for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) sum += wx[i] * wy[j] * wz[k] * voxel(x + i - 1, y + j - 1, z + k - 1);
      }
    }
    return std::clamp(sum, 0.0, 1.0);
  }

 private:
  // The voxel at (x, y, z), each index wrapped round its size as an unsigned 64-bit count wraps: the cubic's
  // voxel before the first, index −1, is (2⁶⁴ − 1) mod n, not n − 1 (as POV-Ray's values for n = 3 and 7 show).
  double voxel(int x, int y, int z) const {
    const DensityGrid& g = *grid_;
    const auto wrap = [](int i, int n) { return size_t(std::uint64_t(std::int64_t(i)) % std::uint64_t(n)); };
    return g.values[(wrap(z, g.nz) * size_t(g.ny) + wrap(y, g.ny)) * size_t(g.nx) + wrap(x, g.nx)];
  }

  std::shared_ptr<const DensityGrid> grid_;
  int interpolation_;
};

}  // namespace

std::unique_ptr<Pattern> makeDensityFile(const PatternArgs& a) {
  return std::make_unique<DensityFile>(a.densityFile, a.densityInterpolation);
}

}  // namespace rt
