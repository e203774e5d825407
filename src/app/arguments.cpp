#include "raytrace/app/arguments.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <limits>
#include <utility>

#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"

namespace rt {

namespace {
// Gather rays per hit and gathering levels: beyond these a render would take years, so they are typos.
constexpr int kMaxGatherSamples = 1 << 16;
constexpr int kMaxBounces = 16;
}  // namespace

int parseInt(const std::string& s, const char* what, int lo, int hi) {
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0') {
    throw Error(std::string(what) + " must be a whole number, found " + quote(s));
  }
  // A number too long for a long (ERANGE) is still a whole number, just out of range.
  if (errno == ERANGE || v < lo || v > hi) {
    throw Error(std::string(what) + " must be between " + std::to_string(lo) + " and " + std::to_string(hi) +
                ", found " + printable(s));
  }
  return int(v);
}

namespace {

template <class E> using Names = std::initializer_list<std::pair<const char*, E>>;

const Names<Tier> kPrecisions = {{"float", Tier::Float}, {"double", Tier::Double},
                                      {"course", Tier::Course}, {"auto", Tier::Auto}};
const Names<SphereMethod> kSpheres = {{"textbook", SphereMethod::Textbook}, {"robust", SphereMethod::Robust},
                                      {"auto", SphereMethod::Auto}};
const Names<OffsetPolicy> kOffsets = {{"relative", OffsetPolicy::Relative}, {"course", OffsetPolicy::Course},
                                      {"normal", OffsetPolicy::FixedNormal}, {"wb", OffsetPolicy::WaechterBinder}};
const Names<Hierarchy> kHierarchies = {{"auto", Hierarchy::Auto}, {"always", Hierarchy::Always},
                                       {"never", Hierarchy::Never}};

// The value of `--flag=value` among `names`, or an error listing them: "--flag must be a, b or c, found 'v'".
template <class E> E choice(const char* flag, const std::string& value, Names<E> names) {
  std::string list;
  size_t i = 0;
  for (const auto& [name, e] : names) {
    if (value == name) return e;
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(name);
    ++i;
  }
  throw Error(std::string(flag) + " must be " + list + ", found " + quote(value));
}

template <class E> std::string nameOf(Names<E> names, E value) {
  for (const auto& [name, e] : names) {
    if (e == value) return name;
  }
  return "?";
}

}  // namespace

std::string pixelFlags(const RenderOptions& o) {
  const RenderOptions defaults;
  std::string flags;
  const auto add = [&](bool differs, const std::string& flag) {
    if (differs) flags += (flags.empty() ? "" : " ") + flag;
  };
  add(o.arithmetic.tier != defaults.arithmetic.tier,
      "--precision=" + nameOf(kPrecisions, o.arithmetic.tier));
  add(o.arithmetic.sphere != defaults.arithmetic.sphere, "--sphere=" + nameOf(kSpheres, o.arithmetic.sphere));
  add(o.arithmetic.offset.has_value(), "--offset=" + nameOf(kOffsets, o.arithmetic.offset.value_or(OffsetPolicy())));
  add(o.depth.has_value(), "--depth=" + std::to_string(o.depth.value_or(0)));
  add(o.samples != defaults.samples, "-ss=" + std::to_string(o.samples));
  add(o.brdf != defaults.brdf, "-altbrdf");
  add(o.fresnel, "-fresnel");
  add(o.beers, "-beers");
  add(o.normals, "-normals");
  add(o.gi.enabled, "-gi");
  std::string counts;
  for (const int n : o.gi.samples) counts += (counts.empty() ? "" : ",") + std::to_string(n);
  add(o.gi.samples != defaults.gi.samples, "-gi_samples=" + counts);
  add(o.gi.bounces.has_value(), "-gi_bounces=" + std::to_string(o.gi.bounces.value_or(0)));
  add(o.gi.seed != defaults.gi.seed, "--seed=" + std::to_string(o.gi.seed));
  char cache[32];
  std::snprintf(cache, sizeof cache, "%.9g", double(o.gi.cache.value_or(0)));  // the float exactly
  add(o.gi.cache.has_value(), std::string("--gi-cache=") + cache);
  return flags;
}

std::vector<int> parseCounts(const std::string& s, const char* what, int lo, int hi) {
  std::vector<int> counts;
  size_t start = 0;
  for (;;) {
    const size_t comma = s.find(',', start);
    counts.push_back(parseInt(s.substr(start, comma - start), what, lo, hi));
    if (comma == std::string::npos) return counts;
    start = comma + 1;
  }
}

RenderOptions parseFlag(const std::string& flag, RenderOptions o) {
  const auto value = [&](const std::string& name) -> const char* {
    return flag.rfind(name + "=", 0) == 0 ? flag.c_str() + name.size() + 1 : nullptr;
  };
  if (flag == "-sds") return o;  // the course's "use a hierarchy": ours decides per scene (Scene, Hierarchy)
  if (const char* p = value("--precision")) {
    o.arithmetic.tier = choice("--precision", p, kPrecisions);
    return o;
  }
  if (const char* p = value("--sphere")) {
    o.arithmetic.sphere = choice("--sphere", p, kSpheres);
    return o;
  }
  if (const char* p = value("--offset")) {
    o.arithmetic.offset = choice("--offset", p, kOffsets);
    return o;
  }
  if (const char* p = value("--hierarchy")) {
    o.hierarchy = choice("--hierarchy", p, kHierarchies);
    return o;
  }
  if (const char* p = value("--depth")) {
    o.depth = parseInt(p, "--depth", 0, 64);
    return o;
  }
  if (const char* p = value("-ss")) {
    o.samples = parseInt(p, "-ss", 1, 64);
    return o;
  }
  if (const char* p = value("-gi_samples")) {
    o.gi.samples = parseCounts(p, "-gi_samples", 1, kMaxGatherSamples);
    return o;
  }
  if (const char* p = value("-gi_bounces")) {
    o.gi.bounces = parseInt(p, "-gi_bounces", 0, kMaxBounces);
    return o;
  }
  if (const char* p = value("--gi-cache")) {
    errno = 0;
    char* end = nullptr;
    const double a = std::strtod(p, &end);
    if (*p == '\0' || *end != '\0' || errno == ERANGE || !(a > 0 && a <= 1)) {
      throw Error("--gi-cache must be a number above 0 and at most 1, found " + quote(p));
    }
    o.gi.cache = float(a);
    return o;
  }
  if (const char* p = value("--seed")) {
    o.gi.seed = uint64_t(parseInt(p, "--seed", 0, std::numeric_limits<int>::max()));
    return o;
  }
  if (const char* p = value("--threads")) {
    o.threads = parseInt(p, "--threads", 1, kMaxThreads);
    return o;
  }
  if (flag == "-gi") o.gi.enabled = true;
  else if (flag == "-altbrdf") o.brdf = Brdf::CookTorrance;
  else if (flag == "-fresnel") o.fresnel = true;
  else if (flag == "-beers") o.beers = true;
  else if (flag == "-normals") o.normals = true;
  else throw Error("unknown option " + quote(flag) + " (see raytrace --help)");
  return o;
}

}  // namespace rt
