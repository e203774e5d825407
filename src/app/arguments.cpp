#include "raytrace/app/arguments.hpp"

#include <algorithm>
#include <cctype>
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
  char real[32];
  std::snprintf(real, sizeof real, "%.9g", double(o.aa.threshold));  // the float exactly
  add(o.aa.method != 0, "--aa=" + std::to_string(o.aa.method) + " --aa-threshold=" + real + " --aa-depth=" +
                            std::to_string(o.aa.depth));
  std::snprintf(real, sizeof real, "%.9g", double(o.aa.jitter));
  add(o.aa.method != 0 && o.aa.jitter != 0, std::string("--jitter=") + real);
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

namespace {

// A number from lo to hi.
double parseReal(const std::string& v, const char* what, int lo, int hi) {
  errno = 0;
  char* end = nullptr;
  const double a = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || errno == ERANGE || !(a >= lo && a <= hi)) {
    throw Error(std::string(what) + " must be a number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                ", found " + quote(v));
  }
  return a;
}

const char* const kTextOrJson = "text|json";

const std::vector<Option> kOptions = {
    {"--precision", nullptr, "float|double|course|auto", Form::Joined, Scope::Any, Section::General,
     "arithmetic for geometry (default auto: chosen per scene); course\n"
     "is the course reference's float arithmetic and 0.001 offsets",
     [](Words& w, const std::string& v, const std::string&) {
       w.options.arithmetic.tier = choice("--precision", v, kPrecisions);
     }},
    {"--sphere", nullptr, "textbook|robust|auto", Form::Joined, Scope::Any, Section::General,
     "ray-sphere formula (default auto: chosen per scene)",
     [](Words& w, const std::string& v, const std::string&) {
       w.options.arithmetic.sphere = choice("--sphere", v, kSpheres);
     }},
    {"--offset", nullptr, "relative|course|normal|wb", Form::Joined, Scope::Any, Section::General,
     "spawned-ray origins (default: the arithmetic's): relative normal\n"
     "offset, the course's 0.001 along the normal, a fixed 1e-4 along\n"
     "the normal, or Waechter-Binder's ulp offset",
     [](Words& w, const std::string& v, const std::string&) {
       w.options.arithmetic.offset = choice("--offset", v, kOffsets);
     }},
    {"--depth", nullptr, "N", Form::Joined, Scope::Any, Section::General,
     "deepest reflection/refraction level, 0 to 64 (default: the scene\n"
     "language's); a ray is traced only while it can still change its\n"
     "pixel, and past depth 12 an eye ray's tree stops at 8191 rays",
     [](Words& w, const std::string& v, const std::string&) { w.options.depth = parseInt(v, "--depth", 0, 64); }},
    {"-altbrdf", nullptr, nullptr, Form::Switch, Scope::Any, Section::General,
     "Cook-Torrance (GGX) instead of Blinn-Phong",
     [](Words& w, const std::string&, const std::string&) { w.options.brdf = Brdf::CookTorrance; }},
    {"-fresnel", nullptr, nullptr, Form::Switch, Scope::Any, Section::General,
     "Schlick-weighted reflection and refraction",
     [](Words& w, const std::string&, const std::string&) { w.options.fresnel = true; }},
    {"-beers", nullptr, nullptr, Form::Switch, Scope::Any, Section::General,
     "Beer's-law absorption inside transparent objects",
     [](Words& w, const std::string&, const std::string&) { w.options.beers = true; }},
    {"-ss", nullptr, "N", Form::Joined, Scope::Any, Section::General,
     "N x N stratified samples per pixel (1 to 64)",
     [](Words& w, const std::string& v, const std::string&) { w.options.samples = parseInt(v, "-ss", 1, 64); }},
    {"--aa", nullptr, "1|2", Form::Joined, Scope::Render, Section::General,
     "adaptive anti-aliasing: POV-Ray's +AM1 or +AM2",
     [](Words& w, const std::string& v, const std::string&) { w.options.aa.method = parseInt(v, "--aa", 1, 2); }},
    {"--aa-threshold", nullptr, "T", Form::Joined, Scope::Render, Section::General,
     "its threshold, 0 to 3 (default 0.3)",
     [](Words& w, const std::string& v, const std::string&) {
       w.options.aa.threshold = float(parseReal(v, "--aa-threshold", 0, 3));
     }},
    {"--aa-depth", nullptr, "R", Form::Joined, Scope::Render, Section::General,
     "its depth, 1 to 9 (default 3)",
     [](Words& w, const std::string& v, const std::string&) { w.options.aa.depth = parseInt(v, "--aa-depth", 1, 9); }},
    {"--jitter", nullptr, "J", Form::Joined, Scope::Render, Section::General,
     "its jitter, 0 to 1 (default 0)",
     [](Words& w, const std::string& v, const std::string&) {
       w.options.aa.jitter = float(parseReal(v, "--jitter", 0, 1));
     }},
    {"-gi", nullptr, nullptr, Form::Switch, Scope::Any, Section::General,
     "Monte Carlo global illumination: indirect light gathered with\n"
     "stratified cosine-weighted rays instead of the ambient term",
     [](Words& w, const std::string&, const std::string&) { w.options.gi.enabled = true; }},
    {"-gi_samples", nullptr, "N[,N...]", Form::Joined, Scope::Any, Section::General,
     "gather rays per hit at bounce 1, 2, ... (default 64,16)",
     [](Words& w, const std::string& v, const std::string&) {
       w.options.gi.samples = parseCounts(v, "-gi_samples", 1, kMaxGatherSamples);
     }},
    {"-gi_bounces", nullptr, "B", Form::Joined, Scope::Any, Section::General,
     "gathering levels, 0 to 16 (default: one per sample count; past the\n"
     "list, its last count); an eye sample stops at 2^20 rays in all",
     [](Words& w, const std::string& v, const std::string&) {
       w.options.gi.bounces = parseInt(v, "-gi_bounces", 0, kMaxBounces);
     }},
    {"--seed", nullptr, "N", Form::Either, Scope::Any, Section::General,
     "-gi's random numbers (default 0); same image for any threads",
     [](Words& w, const std::string& v, const std::string&) {
       w.options.gi.seed = uint64_t(parseInt(v, "--seed", 0, std::numeric_limits<int>::max()));
     },
     "needs a number"},
    {"--gi-cache", nullptr, "A", Form::Joined, Scope::Any, Section::General,
     "irradiance caching of the first bounce, accuracy A in (0, 1]\n"
     "(e.g. 0.15; smaller: more records, nearer plain -gi)",
     [](Words& w, const std::string& v, const std::string&) {
       errno = 0;
       char* end = nullptr;
       const double a = std::strtod(v.c_str(), &end);
       if (v.empty() || *end != '\0' || errno == ERANGE || !(a > 0 && a <= 1)) {
         throw Error("--gi-cache must be a number above 0 and at most 1, found " + quote(v));
       }
       w.options.gi.cache = float(a);
     }},
    {"-normals", nullptr, nullptr, Form::Switch, Scope::Any, Section::General,
     "colour each hit by its normal (debug)",
     [](Words& w, const std::string&, const std::string&) { w.options.normals = true; }},
    {"--threads", nullptr, "N", Form::Either, Scope::Any, Section::General,
     "load, build and render on N threads (default: every core); same\n"
     "scene and image for any N",
     [](Words& w, const std::string& v, const std::string&) {
       w.options.threads = parseInt(v, "--threads", 1, kMaxThreads);
     },
     "needs a number of threads"},
    {"--quiet", nullptr, nullptr, Form::Switch, Scope::Any, Section::General,
     "no progress line (shown only while rendering to a terminal)",
     [](Words& w, const std::string&, const std::string&) { w.quiet = true; }},
    {"--stats", nullptr, kTextOrJson, Form::Optional, Scope::Render, Section::General,
     "after render, how long loading, building, tracing and writing the\n"
     "image took, and the rays traced by kind (stderr); =json: the same\n"
     "as one JSON object, with the peak memory",
     [](Words& w, const std::string& v, const std::string&) {
       w.stats = true;
       w.statsJson = !v.empty() && choice("--stats", v, Names<bool>{{"text", false}, {"json", true}});
     }},
    {"--display", nullptr, nullptr, Form::Switch, Scope::Render, Section::General,
     "show the picture in a window, tile by tile as they finish (needs\n"
     "SDL2 and a display; without them, says so and renders on)",
     [](Words& w, const std::string&, const std::string&) { w.display = true; }},
    {"--preview", nullptr, "FILE", Form::Either, Scope::Render, Section::General,
     "write the picture so far to FILE every few seconds, replacing it\n"
     "whole, for image viewers that reload",
     [](Words& w, const std::string& v, const std::string& word) {
       if (v.empty()) throw Error(word + " needs a file name");
       w.preview = v;
     }},
    {"--dialect", nullptr, "course|povray", Form::Joined, Scope::Any, Section::General,
     "how a .pov file is read (default: POV-Ray 3.7 when it uses a\n"
     "directive or global_settings, else the course's subset)",
     [](Words& w, const std::string& v, const std::string&) {
       w.load.dialect = choice("--dialect", v,
                               Names<DialectChoice>{{"course", DialectChoice::Course}, {"povray", DialectChoice::PovRay}});
     }},
    {"-L", nullptr, "DIR", Form::Either, Scope::Any, Section::General,
     "a folder a POV-Ray scene's #include searches, after the scene's\n"
     "own and before the standard include library (also +LDIR)",
     [](Words& w, const std::string& v, const std::string& word) {
       if (v.empty()) throw Error(word + " needs a folder");
       w.load.libraryPaths.push_back(v);
     },
     "needs a folder after it"},
    {"-D", nullptr, "NAME=VALUE", Form::Either, Scope::Any, Section::General,
     "declare NAME (a number or a string) before a POV-Ray scene is read\n"
     "(also Declare=NAME=VALUE)",
     [](Words& w, const std::string& v, const std::string& word) {
       if (v.find('=') == std::string::npos || v[0] == '=') throw Error(word + " needs NAME=VALUE, found " + quote(v));
       w.load.declares.push_back(v);
     },
     "needs NAME=VALUE after it"},
    {"-sds", nullptr, nullptr, Form::Switch, Scope::Any, Section::General,
     "accepted for the course; a hierarchy is used whenever it pays",
     // The course's "use a hierarchy": ours decides per scene (Scene, Hierarchy).
     [](Words&, const std::string&, const std::string&) {}},
    {"--hierarchy", nullptr, "auto|always|never", Form::Joined, Scope::Any, Section::General,
     "force the bounding volume hierarchy on or off (same image)",
     [](Words& w, const std::string& v, const std::string&) {
       w.options.hierarchy = choice("--hierarchy", v, kHierarchies);
     }},
    {"-o", "--output", "FILE", Form::Either, Scope::Image, Section::Image,
     "the image file (default output.png); its extension picks the format:\n"
     ".png (8-bit), .hdr (Radiance RGBE) or .exr (OpenEXR, 32-bit float),\n"
     "the last two the linear radiance before clamping. For a .cli scene\n"
     "that writes its own images, the folder to write them into",
     [](Words& w, const std::string& v, const std::string& word) {
       if (v.empty()) throw Error(word + " needs a file name");
       w.output = v;
     }},
    {"--allow-write-anywhere", nullptr, nullptr, Form::Switch, Scope::Any, Section::Image,
     "let a .cli 'write' or a POV-Ray '#fopen' leave the folder of -o (or the\n"
     "current one): an absolute path, '..', a symbolic link on the way",
     [](Words& w, const std::string&, const std::string&) { w.writeAnywhere = true; }},
    {"--tile", nullptr, "I/N", Form::Either, Scope::Image, Section::Image,
     "render only the I-th of N bands of rows (0 <= I < N), written to\n"
     "-o NAME.exr as a tile for merge",
     [](Words& w, const std::string& v, const std::string&) { w.tile = v; }},
    {"--region", nullptr, "X0,Y0,X1,Y1", Form::Either, Scope::Image, Section::Image,
     "render only columns X0 to X1-1 and rows Y0 to Y1-1, rows counted\n"
     "from the top, written to -o NAME.exr as a tile for merge",
     [](Words& w, const std::string& v, const std::string&) { w.region = v; }},
    {"--resume", nullptr, nullptr, Form::Switch, Scope::Image, Section::Image,
     "keep a tile already at -o if it is of this very render",
     [](Words& w, const std::string&, const std::string&) { w.resume = true; }},
    {"--manifest", nullptr, "FILE", Form::Either, Scope::Image, Section::Image,
     "list the files read and written in FILE",
     [](Words& w, const std::string& v, const std::string& word) {
       if (v.empty()) throw Error(word + " needs a file name");
       w.manifest = v;
     }},
};

const Option* optionNamed(const std::string& name) {
  for (const Option& o : kOptions) {
    if (name == o.name || (o.alias && name == o.alias)) return &o;
  }
  return nullptr;
}

[[noreturn]] void unknownOption(const std::string& word, const char* near) {
  throw Error("unknown option " + quote(word) + (near ? ": did you mean " + quote(near) + "?" : "") +
              " (see raytrace --help)");
}

// Applies the option word args[i] to `words`, moving i past its value if the value is the next word.
void readOption(const std::vector<std::string>& args, size_t& i, Words& words) {
  const std::string& word = args[i];
  const size_t equals = word.find('=');
  const std::string name = word.substr(0, equals);
  const bool joined = equals != std::string::npos;
  const Option* option = optionNamed(name);
  if (!option) {
    std::vector<const char*> names;
    for (const Option& o : kOptions) {
      names.push_back(o.name);
      if (o.alias) names.push_back(o.alias);
    }
    unknownOption(word, nearestName(name, names));
  }
  // A switch given a value, or an option that must be joined to its value given none.
  if ((option->form == Form::Switch && joined) || (option->form == Form::Joined && !joined)) {
    unknownOption(word, nullptr);
  }
  std::string value;
  if (joined) {
    value = word.substr(equals + 1);
  } else if (option->form == Form::Either) {
    if (i + 1 == args.size()) throw Error(name + " " + option->missing);
    value = args[++i];
  }
  option->apply(words, value, word);
  if (option->scope != Scope::Any) words.scoped.push_back(name);
}

}  // namespace

const std::vector<Option>& optionTable() { return kOptions; }

Words readWords(const std::vector<std::string>& args, size_t first) {
  Words words;
  for (size_t i = first; i < args.size(); ++i) {
    const std::string& a = args[i];
    // POV-Ray's own spellings of -L and -D: +LDIR or -LDIR, and Declare=NAME=VALUE.
    if (a.size() > 2 && (a.rfind("+L", 0) == 0 || (a.rfind("-L", 0) == 0 && a[2] != '='))) {
      words.load.libraryPaths.push_back(a.substr(2));
    } else if (a.rfind("Declare=", 0) == 0) {
      std::vector<std::string> spelled{"-D", a.substr(8)};
      size_t at = 0;
      readOption(spelled, at, words);
    } else if (a.size() > 1 && a[0] == '-' && (std::isalpha(static_cast<unsigned char>(a[1])) || a[1] == '-')) {
      readOption(args, i, words);
    } else {
      words.positional.push_back(a);
    }
  }
  return words;
}

RenderOptions parseFlag(const std::string& flag, RenderOptions options) {
  Words words;
  words.options = std::move(options);
  size_t i = 0;
  readOption({flag}, i, words);
  return words.options;
}

std::string optionLabel(const Option& o) {
  std::string label = std::string(o.name) + (o.alias ? std::string(", ") + o.alias : "");
  switch (o.form) {
    case Form::Switch: return label;
    case Form::Joined: return label + "=" + o.argument;
    case Form::Either: return label + " " + o.argument;
    case Form::Optional: return label + "[=" + o.argument + "]";
  }
  return label;
}

std::string optionsHelp(Section section) {
  // The help starts in column 34; a longer label has a line of its own.
  constexpr size_t kColumn = 34;
  std::string text = section == Section::General ? "options:\n" : "image options (raycast, render):\n";
  for (const Option& o : kOptions) {
    if (o.section != section) continue;
    const std::string label = "  " + optionLabel(o);
    text += label.size() + 2 <= kColumn ? label + std::string(kColumn - label.size(), ' ')
                                        : label + "\n" + std::string(kColumn, ' ');
    for (const char* c = o.help; *c; ++c) text += *c == '\n' ? "\n" + std::string(kColumn, ' ') : std::string(1, *c);
    text += "\n";
  }
  return text;
}

const char* nearestName(const std::string& word, const std::vector<const char*>& names) {
  const char* best = nullptr;
  size_t bestDistance = 3;
  for (const char* candidate : names) {
    const std::string name(candidate);
    // Levenshtein distance, one row at a time.
    std::vector<size_t> row(name.size() + 1);
    for (size_t j = 0; j <= name.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= word.size(); ++i) {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= name.size(); ++j) {
        const size_t above = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (word[i - 1] == name[j - 1] ? 0 : 1)});
        diagonal = above;
      }
    }
    if (row[name.size()] < bestDistance) {
      bestDistance = row[name.size()];
      best = candidate;
    }
  }
  return best;
}

}  // namespace rt
