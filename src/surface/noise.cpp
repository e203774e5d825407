#include "raytrace/surface/noise.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

namespace rt {

namespace {

// Each lattice point's noise is one of 256 entries: a value (half of kTable[i]) and a gradient
// (kTable[i + 1 .. i + 3]); vector noise reads entries i + 4 and i + 8 for its other two components.
// Measured from POV-Ray at lattice points and just beside them (docs/povray-noise.md); 6 digits each.
constexpr double kTable[267] = {
    -1, 0.604974, -0.937102, 0.414115, 0.576226, -0.0161593, 0.432334, 0.103685, 0.590539, 0.0286412, 0.46981,
    -0.84622, -0.0734112, -0.304097, -0.40206, -0.210132, -0.919127, 0.652033, -0.83151, -0.183948, -0.671107,
    0.852476, 0.043595, -0.404532, 0.75494, -0.335653, 0.618433, 0.605707, 0.708583, -0.477195, 0.899474, 0.490623,
    0.221729, -0.400381, -0.853727, -0.932586, 0.659113, 0.961303, 0.325948, -0.750851, 0.842466, 0.734401,
    -0.649866, 0.394491, -0.466056, -0.434073, 0.109026, 0.0847028, -0.738857, 0.241505, 0.16228, -0.71426,
    -0.883665, -0.150408, -0.90396, -0.686549, -0.785214, 0.488548, 0.0246433, 0.142473, -0.602136, 0.375845,
    -0.00779736, 0.498955, -0.268147, 0.856382, -0.386007, -0.596094, -0.867735, -0.570977, -0.914366, 0.28896,
    0.672206, -0.233783, 0.94815, 0.895262, 0.343252, -0.173388, -0.767971, -0.314748, 0.824308, -0.342092, 0.721431,
    -0.24004, -0.63653, 0.553277, 0.376272, 0.158984, -0.452659, 0.396323, -0.420676, -0.454154, 0.122179, 0.295857,
    0.0664225, -0.202075, -0.724788, 0.453513, 0.224567, -0.908812, 0.176349, -0.320516, -0.697139, 0.742702,
    -0.900786, 0.471489, -0.133532, 0.119127, -0.889769, -0.23183, -0.669673, -0.046891, -0.803433, -0.966735,
    0.475578, -0.652644, 0.0112459, -0.730007, 0.128283, 0.145647, -0.619318, 0.272023, 0.392966, 0.646418,
    -0.0207675, -0.315908, 0.480797, 0.535668, -0.250172, -0.83093, -0.653773, -0.443809, 0.119982, -0.897642,
    0.89453, 0.165789, 0.633875, -0.886839, 0.930877, -0.537194, 0.587732, 0.722011, -0.209461, -0.0424659,
    -0.814267, -0.919432, 0.280262, -0.66302, -0.558099, -0.537469, -0.598779, 0.929656, -0.170794, -0.537163,
    0.312581, 0.959442, 0.722652, 0.499931, 0.175616, -0.534874, -0.685115, 0.444999, 0.17171, 0.108202, -0.768704,
    -0.463828, 0.254231, 0.546014, 0.869474, 0.875212, -0.944427, 0.130724, -0.110185, 0.312184, -0.33138, -0.629206,
    0.0606546, 0.722866, -0.0979477, 0.821561, 0.0931258, -0.972808, 0.0318151, -0.867033, -0.387228, 0.280995,
    -0.218189, -0.539178, -0.427359, -0.602075, 0.311971, 0.277974, 0.773159, 0.592493, -0.0331884, -0.630854,
    -0.269947, 0.339132, 0.581079, 0.209461, -0.317433, -0.284993, 0.181323, 0.341634, 0.804959, -0.229572,
    -0.758907, -0.336721, 0.605463, -0.991272, -0.0188754, -0.300191, 0.368307, -0.176135, -0.3832, -0.749569,
    0.62356, -0.573938, 0.278309, -0.971313, 0.839994, -0.830686, 0.439078, 0.66128, 0.694514, 0.0565042, 0.54342,
    -0.438804, -0.0228428, -0.687068, 0.857267, 0.301991, -0.494255, -0.941039, 0.775509, 0.410575, -0.362081,
    -0.671534, -0.348379, 0.932433, 0.886442, 0.868681, -0.225666, -0.062211, -0.0976425, -0.641444, -0.848112,
    0.724697, 0.473503, 0.998749, 0.174701, 0.559625, -0.029099, -0.337392, -0.958129, -0.659785, 0.236042,
    -0.246937, 0.659449, -0.027512, 0.821897, -0.226215, 0.0181735, 0.500481, -0.420127, -0.427878, 0.566186,
};

// POV-Ray's rand() stepped from a seed: bits 16..30 of its 32-bit state (docs/povray-language.md, "Random numbers").
struct PovRand {
  uint32_t state;
  constexpr int operator()() {
    state = state * 1812433253u + 12345u;
    return int(state >> 16 & 0x7fff);
  }
};

// The lattice hash: a permutation of 0..4095 shuffled by rand() seeded with 0, applied to x, then y, then z.
constexpr std::array<uint16_t, 4096> makePermutation() {
  std::array<uint16_t, 4096> t{};
  for (int i = 0; i < 4096; ++i) t[size_t(i)] = uint16_t(i);
  PovRand rand{0};
  for (int i = 4095; i >= 0; --i) {
    const size_t j = size_t(rand() % 4096);
    const uint16_t swapped = t[size_t(i)];
    t[size_t(i)] = t[j];
    t[j] = swapped;
  }
  return t;
}

constexpr std::array<uint16_t, 4096> kPermutation = makePermutation();

int hash(int x, int y, int z) {
  const auto& t = kPermutation;
  return t[t[t[size_t(x & 0xfff)] ^ size_t(y & 0xfff)] ^ size_t(z & 0xfff)];
}

int entry(int x, int y, int z) { return hash(x, y, z) & 0xff; }

// The cells' table: the first outputs of std::mt19937 with its default seed, over 2³², one per hash and two more
// for the last point's y and z.
const std::array<double, 4098>& cellTable() {
  static const std::array<double, 4098> table = [] {
    std::array<double, 4098> t{};
    std::mt19937 twister;
    for (double& v : t) v = double(twister()) / 4294967296.0;
    return t;
  }();
  return table;
}

double sCurve(double a) { return a * a * (3 - 2 * a); }

// Generator 3's tables, both drawn from rand() seeded with 1 (docs/povray-noise.md, "Generator 3"): 2048 unit
// gradients, each the first triple of draws (mod 4096, less 2048) no longer than 2048, then a permutation of
// 0..2047 shuffled at its even places from 2048 down, where place 2048 starts as 0; it is stored twice over so
// that a lookup's sum of two entries needs no wrap.
struct PerlinTables {
  std::array<glm::dvec3, 2048> gradient;
  std::array<uint16_t, 4096> permutation;
};

const PerlinTables& perlinTables() {
  static const PerlinTables tables = [] {
    PerlinTables t{};
    PovRand rand{1};
    for (glm::dvec3& g : t.gradient) {
      int v[3], length2;
      do {
        for (int& c : v) c = rand() % 4096 - 2048;
        length2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
      } while (length2 > 2048 * 2048);
      const double length = std::sqrt(double(length2));
      g = {v[0] / length, v[1] / length, v[2] / length};
    }
    std::array<uint16_t, 2049> p{};
    for (int i = 0; i < 2048; ++i) p[size_t(i)] = uint16_t(i);
    for (int i = 2048; i > 0; i -= 2) std::swap(p[size_t(i)], p[size_t(rand() % 2048)]);
    for (int i = 0; i < 4096; ++i) t.permutation[size_t(i)] = p[size_t(i & 2047)];
    return t;
  }();
  return tables;
}

// Generator 3: gradient noise without lattice values, on a lattice shifted by 10000000.023157213 (the double
// nearest it, which is also what sets its precision: the noise steps every 2⁻²⁹ near the origin).
double perlinNoise(const glm::dvec3& p) {
  constexpr double kShift = 10000000 + 0xBDB432p-29;
  const PerlinTables& t = perlinTables();
  const glm::dvec3 q = p + glm::dvec3(kShift);
  const glm::dvec3 fl = glm::floor(q);
  const glm::dvec3 f = q - fl;
  const glm::dvec3 s = {sCurve(f.x), sCurve(f.y), sCurve(f.z)};
  const int bx = int(fl.x), by = int(fl.y), bz = int(fl.z);
  double sum = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const int i = corner >> 2 & 1, j = corner >> 1 & 1, k = corner & 1;
    const double w = (i ? s.x : 1 - s.x) * (j ? s.y : 1 - s.y) * (k ? s.z : 1 - s.z);
    const size_t row = t.permutation[size_t((bx + i) & 2047)] + size_t((by + j) & 2047);
    const glm::dvec3& g = t.gradient[(t.permutation[row] + size_t((bz + k) & 2047)) & 2047];
    sum += w * (g.x * (f.x - i) + g.y * (f.y - j) + g.z * (f.z - k));
  }
  // Measured: 0.4925 at every lattice point and 0.795 times the gradient beside it.
  return std::clamp(0.4925 + 0.795 * sum, 0.0, 1.0);
}

// The lattice cell of p, as POV-Ray finds it: coordinates shifted by 10000, then floored.
struct Cell {
  int ix, iy, iz;
  glm::dvec3 f;  // where p lies in the cell, each in [0, 1)
  glm::dvec3 s;  // its smoothed weights
  explicit Cell(const glm::dvec3& p) {
    const glm::dvec3 q = p + glm::dvec3(10000.0);
    const glm::dvec3 fl = glm::floor(q);
    ix = int(fl.x);
    iy = int(fl.y);
    iz = int(fl.z);
    f = q - fl;
    s = {sCurve(f.x), sCurve(f.y), sCurve(f.z)};
  }
};

// Sums weight · (value + gradient · offset) over the eight corners, for each component (table offsets 0, 4, 8).
template <int components> std::array<double, components> latticeSum(const glm::dvec3& p) {
  const Cell c(p);
  std::array<double, components> sum{};
  for (int corner = 0; corner < 8; ++corner) {
    const int i = corner >> 2 & 1, j = corner >> 1 & 1, k = corner & 1;
    const double w = (i ? c.s.x : 1 - c.s.x) * (j ? c.s.y : 1 - c.s.y) * (k ? c.s.z : 1 - c.s.z);
    const glm::dvec3 d = c.f - glm::dvec3(i, j, k);
    const int e = entry(c.ix + i, c.iy + j, c.iz + k);
    for (int n = 0; n < components; ++n) {
      const double* m = kTable + e + 4 * n;
      sum[size_t(n)] += w * (m[0] * 0.5 + m[1] * d.x + m[2] * d.y + m[3] * d.z);
    }
  }
  return sum;
}

}  // namespace

double noise(const glm::dvec3& p, NoiseGenerator g) {
  if (g == NoiseGenerator::Perlin) return perlinNoise(p);
  const double sum = latticeSum<1>(p)[0];
  // The range-corrected generator maps the sum's measured extremes, about -1.05 and 0.99, onto [0, 1].
  const double v = g == NoiseGenerator::Original ? sum + 0.5 : (sum + 1.05242) * 0.48985582;
  return std::clamp(v, 0.0, 1.0);
}

glm::dvec3 vectorNoise(const glm::dvec3& p) {
  const auto s = latticeSum<3>(p);
  return {s[0], s[1], s[2]};
}

glm::dvec3 cellPoint(int x, int y, int z) {
  const double* r = cellTable().data() + hash(x, y, z);
  return {x + r[0], y + r[1], z + r[2]};
}

double cellValue(int x, int y, int z) { return cellTable()[size_t(hash(x, y, z))]; }

glm::dvec3 turbulentOffset(const glm::dvec3& p, const Turbulence& t) {
  glm::dvec3 sum = vectorNoise(p);
  double l = t.lambda, o = t.omega;
  for (int i = 2; i <= t.octaves; ++i) {
    sum += o * vectorNoise(p * l);
    l *= double(t.lambda);
    o *= double(t.omega);
  }
  return sum;
}

double turbulenceSum(const glm::dvec3& p, const Turbulence& t, NoiseGenerator g) {
  // The original generator sums plain noise; the others 2·noise − 0.5, the first octave clamped to [0, 1].
  const bool original = g == NoiseGenerator::Original;
  double sum = original ? noise(p, g) : std::clamp(2 * noise(p, g) - 0.5, 0.0, 1.0);
  double l = t.lambda, o = t.omega;
  for (int i = 2; i <= t.octaves; ++i) {
    const double n = noise(p * l, g);
    sum += o * (original ? n : 2 * n - 0.5);
    l *= double(t.lambda);
    o *= double(t.omega);
  }
  return sum;
}

}  // namespace rt
