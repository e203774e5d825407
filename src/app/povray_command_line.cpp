#include "raytrace/app/povray_command_line.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "raytrace/app/arguments.hpp"
#include "raytrace/app/commands.hpp"
#include "raytrace/parse/scene_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"

namespace rt {

namespace {

constexpr int kMaxSide = 32768;       // as render's width and height
constexpr int kMaxFrame = 999999999;  // a frame number of 10 digits is certainly a typo
constexpr int kMaxIniDepth = 10;      // POV-Ray's limit on .ini files naming .ini files

bool sameLetters(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool endsWith(const std::string& s, const std::string& end) {
  return s.size() >= end.size() && sameLetters(s.substr(s.size() - end.size()), end);
}

// An .ini file, with a section or not: "res.ini", "res.ini[Low]".
bool isIni(const std::string& word) {
  const size_t bracket = word.find('[');
  return endsWith(word.substr(0, bracket), ".ini") && (bracket == std::string::npos || word.back() == ']');
}

// One option as given: `on` is false for a '-' switch or an INI "off"; `value` what follows the switch's letters
// or the INI '='; `name` the option as spelled ("+W", "Width"), `word` all of it ("+W0", "Width=0").
struct Given {
  bool on;
  std::string value, name, word;
};

// What the options said so far; a later one replaces an earlier one, as in POV-Ray, but for +L and Declare.
struct Settings {
  std::string input, output;
  std::string type;                // +F's letter: N (PNG, the default), E (OpenEXR) or H (Radiance HDR)
  int width = 320, height = 240;   // POV-Ray's own defaults, without an .ini file
  std::vector<std::string> words;  // -L and -D made from +L and Declare, in order
  std::string threads;
  bool display = false;
  // Anti-aliasing as POV-Ray defaults it: off, threshold 0.3, method 1, depth 3, jitter on with amount 1.
  bool antialias = false, jitter = true;
  double threshold = 0.3, jitterAmount = 1;
  int method = 1, depth = 3;
  std::optional<Given> startColumn, startRow, endColumn, endRow, subsetStart, subsetEnd, initialFrame, finalFrame;
  double initialClock = 0, finalClock = 1;
  bool cyclic = false;
  std::optional<double> clock;
  std::vector<std::string> animationOnly;  // the words that mean something only in an animation (+KI, +SF …)
  std::vector<std::string> own;            // raytrace's own options given among POV-Ray's
  int iniDepth = 0;
};

[[noreturn]] void unsupported(const Given& g) { throw Error(quote(g.word) + " is not supported yet"); }

bool isNumber(const std::string& s, double* value = nullptr) {
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v)) return false;
  if (value) *value = v;
  return true;
}

double number(const Given& g) {
  double v = 0;
  if (!isNumber(g.value, &v)) throw Error(g.name + " must be a number, found " + quote(g.value));
  return v;
}

// The manual's range: "the most two pixels can differ is 3.0".
double threshold(const Given& g) {
  const double v = number(g);
  if (v < 0 || v > 3) throw Error(g.name + " must be between 0 and 3, found " + quote(g.value));
  return v;
}

// Above 1.0 ("the maximum jitter which will insure that all super-samples remain inside the original pixel")
// samples would leave their pixel.
double jitterAmount(const Given& g) {
  const double v = number(g);
  if (v > 1) throw Error(g.name + " must be at most 1, found " + quote(g.value));
  return std::max(v, 0.0);
}

// "0.n", a fraction of the picture's side or of the frames, as POV-Ray reads +SR, +EC, +SF …; else a count.
std::optional<double> fraction(const std::string& value) {
  double v = 0;
  if (value.find('.') == std::string::npos || !isNumber(value, &v) || v < 0 || v > 1) return std::nullopt;
  return v;
}

void readIni(Settings& s, const std::string& spec);

enum class Kind {
  Bool,          // +D, -D; Display=on
  Number,        // +W640; Width=640
  Text,          // +Iscene.pov
  BoolOrNumber,  // +A, +A0.3, -A
};

struct PovOption {
  const char* key;      // the INI key, "Width"
  const char* letters;  // the switch's letters, "W"; nullptr for an INI key only
  Kind kind;
  void (*apply)(Settings& s, const Given& g);
};

void ignore(Settings&, const Given&) {}

const std::vector<PovOption> kPovOptions = {
    {"Input_File_Name", "I", Kind::Text,
     [](Settings& s, const Given& g) {
       if (g.value.empty()) throw Error(g.name + " needs a scene file");
       if (isIni(g.value)) return readIni(s, g.value);
       s.input = g.value;
     }},
    {"Output_File_Name", "O", Kind::Text,
     [](Settings& s, const Given& g) {
       if (g.value.empty()) throw Error(g.name + " needs a file name");
       s.output = g.value;
     }},
    {"Output_File_Type", "F", Kind::Text,
     [](Settings& s, const Given& g) {
       // N8 is PNG's default depth; -F (no file) and the other formats are POV-Ray's only.
       std::string t = g.value;
       for (char& c : t) c = char(std::toupper(static_cast<unsigned char>(c)));
       if (!g.on || !(t == "N" || t == "N8" || t == "E" || t == "H")) unsupported(g);
       s.type = t.substr(0, 1);
     }},
    {"Width", "W", Kind::Number,
     [](Settings& s, const Given& g) { s.width = parseInt(g.value, g.name.c_str(), 1, kMaxSide); }},
    {"Height", "H", Kind::Number,
     [](Settings& s, const Given& g) { s.height = parseInt(g.value, g.name.c_str(), 1, kMaxSide); }},
    {"Work_Threads", "WT", Kind::Number,
     [](Settings& s, const Given& g) {
       s.threads = std::to_string(parseInt(g.value, g.name.c_str(), 1, kMaxThreads));
     }},
    {"Library_Path", "L", Kind::Text,
     [](Settings& s, const Given& g) {
       if (g.value.empty()) throw Error(g.name + " needs a folder");
       s.words.insert(s.words.end(), {"-L", g.value});
     }},
    {"Declare", nullptr, Kind::Text,
     [](Settings& s, const Given& g) {
       if (g.value.find('=') == std::string::npos || g.value[0] == '=') {
         throw Error(g.name + " needs NAME=VALUE, found " + quote(g.value));
       }
       s.words.insert(s.words.end(), {"-D", g.value});
     }},
    {"Display", "D", Kind::Bool, [](Settings& s, const Given& g) { s.display = g.on; }},
    // What POV-Ray prints as it goes, and where: raytrace prints its own.
    {"Verbose", "V", Kind::Bool, ignore},
    {"All_Console", "GA", Kind::Bool, ignore},
    {"Debug_Console", "GD", Kind::Bool, ignore},
    {"Fatal_Console", "GF", Kind::Bool, ignore},
    {"Render_Console", "GR", Kind::Bool, ignore},
    {"Statistic_Console", "GS", Kind::Bool, ignore},
    {"Warning_Console", "GW", Kind::Bool, ignore},
    {"Pause_When_Done", "P", Kind::Bool,
     [](Settings&, const Given& g) {
       if (g.on) unsupported(g);
     }},
    // The manual's 3.2.2.x "Anti-Aliasing Options": +An.n turns it on with that threshold, -An.n off, keeping it.
    {"Antialias", "A", Kind::BoolOrNumber,
     [](Settings& s, const Given& g) {
       if (!g.value.empty()) s.threshold = threshold(g);
       s.antialias = g.on;
     }},
    {"Antialias_Threshold", nullptr, Kind::Number, [](Settings& s, const Given& g) { s.threshold = threshold(g); }},
    {"Sampling_Method", "AM", Kind::Number,
     [](Settings& s, const Given& g) { s.method = parseInt(g.value, g.name.c_str(), 1, 2); }},
    {"Antialias_Depth", "R", Kind::Number,
     [](Settings& s, const Given& g) { s.depth = parseInt(g.value, g.name.c_str(), 1, 9); }},
    // +J with no amount keeps the previous one; an amount of 0 or less turns jitter off; above 1 is refused.
    {"Jitter", "J", Kind::BoolOrNumber,
     [](Settings& s, const Given& g) {
       if (!g.value.empty()) s.jitterAmount = jitterAmount(g);
       s.jitter = g.on;
     }},
    {"Jitter_Amount", nullptr, Kind::Number, [](Settings& s, const Given& g) { s.jitterAmount = jitterAmount(g); }},
    {"Start_Column", "SC", Kind::Number, [](Settings& s, const Given& g) { s.startColumn = g; }},
    {"Start_Row", "SR", Kind::Number, [](Settings& s, const Given& g) { s.startRow = g; }},
    {"End_Column", "EC", Kind::Number, [](Settings& s, const Given& g) { s.endColumn = g; }},
    {"End_Row", "ER", Kind::Number, [](Settings& s, const Given& g) { s.endRow = g; }},
    {"Initial_Frame", "KFI", Kind::Number,
     [](Settings& s, const Given& g) {
       parseInt(g.value, g.name.c_str(), 0, kMaxFrame);
       s.initialFrame = g;
     }},
    {"Final_Frame", "KFF", Kind::Number,
     [](Settings& s, const Given& g) {
       parseInt(g.value, g.name.c_str(), 0, kMaxFrame);
       s.finalFrame = g;
     }},
    {"Initial_Clock", "KI", Kind::Number,
     [](Settings& s, const Given& g) {
       s.initialClock = number(g);
       s.animationOnly.push_back(g.word);
     }},
    {"Final_Clock", "KF", Kind::Number,
     [](Settings& s, const Given& g) {
       s.finalClock = number(g);
       s.animationOnly.push_back(g.word);
     }},
    {"Cyclic_Animation", "KC", Kind::Bool,
     [](Settings& s, const Given& g) {
       s.cyclic = g.on;
       if (g.on) s.animationOnly.push_back(g.word);
     }},
    {"Subset_Start_Frame", "SF", Kind::Number,
     [](Settings& s, const Given& g) {
       s.subsetStart = g;
       s.animationOnly.push_back(g.word);
     }},
    {"Subset_End_Frame", "EF", Kind::Number,
     [](Settings& s, const Given& g) {
       s.subsetEnd = g;
       s.animationOnly.push_back(g.word);
     }},
    {"Clock", "K", Kind::Number, [](Settings& s, const Given& g) { s.clock = number(g); }},
};

std::string trimmed(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t\r");
  return first == std::string::npos ? "" : s.substr(first, s.find_last_not_of(" \t\r") + 1 - first);
}

// A value in quotes, as POV-Ray allows for names with blanks: +I"my file.pov", Input_File_Name='a.pov'.
std::string unquoted(const std::string& v) {
  if (v.size() >= 2 && (v[0] == '"' || v[0] == '\'') && v.back() == v[0]) return v.substr(1, v.size() - 2);
  return v;
}

// A switch: '+' or '-', the letters of the longest option they start with, and its value.
void readSwitch(Settings& s, const std::string& word) {
  const PovOption* best = nullptr;
  for (const PovOption& o : kPovOptions) {
    const size_t n = o.letters ? std::strlen(o.letters) : 0;
    if (n > 0 && sameLetters(word.substr(1, n), o.letters) && (!best || n > std::strlen(best->letters))) best = &o;
  }
  const size_t n = best ? std::strlen(best->letters) : 0;
  const Given g{word[0] == '+', unquoted(word.substr(1 + n)), word.substr(0, 1 + n), word};
  // Another switch of POV-Ray's that starts with the same letters (+D0, +WL2, +AM2) is not this one.
  const bool numeric = best && (best->kind == Kind::Number || best->kind == Kind::BoolOrNumber);
  if (!best || (best->kind == Kind::Bool && !g.value.empty()) ||
      (numeric && !g.value.empty() && std::isalpha(static_cast<unsigned char>(g.value[0])))) {
    unsupported(g);
  }
  best->apply(s, g);
}

// An INI line's key=value, as POV-Ray reads it: the key in any case, blanks around either ignored.
void readSetting(Settings& s, const std::string& spelledKey, const std::string& value, const std::string& word) {
  const std::string key = trimmed(spelledKey);
  std::vector<const char*> keys;
  for (const PovOption& o : kPovOptions) {
    keys.push_back(o.key);
    if (!sameLetters(key, o.key)) continue;
    Given g{true, unquoted(trimmed(value)), key, word};
    if (o.kind == Kind::Bool || o.kind == Kind::BoolOrNumber) {
      const auto is = [&](std::initializer_list<const char*> names) {
        return std::any_of(names.begin(), names.end(), [&](const char* n) { return sameLetters(g.value, n); });
      };
      if (!is({"on", "off", "true", "false", "yes", "no", "1", "0"})) {
        throw Error(key + " must be on or off, found " + quote(g.value));
      }
      g.on = is({"on", "true", "yes", "1"});
      g.value.clear();
    }
    return o.apply(s, g);
  }
  if (const char* near = nearestName(key, keys)) {
    throw Error("unknown option " + quote(key) + ": did you mean " + quote(near) + "?");
  }
  throw Error(quote(word) + " is not supported yet");
}

// raytrace's own options among POV-Ray's: --anything, or a -word of its table (-o, -ss=3, -fresnel); -D and
// -L are POV-Ray's display switch and library path.
const Option* ownOption(const std::string& word) {
  const std::string name = word.substr(0, word.find('='));
  if (name == "-D" || name == "-L") return nullptr;
  for (const Option& o : optionTable()) {
    if (name == o.name || (o.alias && name == o.alias)) return &o;
  }
  return nullptr;
}

// One word of the command line or of an INI line, moving i past the value of a raytrace option that takes the
// next word.
void readWord(Settings& s, const std::vector<std::string>& words, size_t& i) {
  const std::string& word = words[i];
  if (word.rfind("--", 0) == 0 || ownOption(word)) {
    const Option* o = ownOption(word);
    if (!o) readWords({word});  // throws its "unknown option" message, with the nearest name
    s.own.push_back(word);
    if (o && o->form == Form::Either && word.find('=') == std::string::npos && i + 1 < words.size()) {
      s.own.push_back(words[++i]);
    }
  } else if (word.size() > 1 && (word[0] == '+' || word[0] == '-')) {
    readSwitch(s, word);
  } else if (const size_t equals = word.find('='); equals != std::string::npos) {
    readSetting(s, word.substr(0, equals), word.substr(equals + 1), word);
  } else if (endsWith(word, ".pov")) {
    s.input = word;  // POV-Ray 3.7 takes a bare scene file as +I
  } else {
    readIni(s, word);
  }
}

// An .ini file, "res.ini" or "res.ini[Low]": with a section, only its lines; without, only the lines before
// the first section. A line holds key=value, switches, or another .ini file's name; ';' starts a comment.
void readIni(Settings& s, const std::string& spec) {
  const size_t bracket = spec.back() == ']' ? spec.find('[') : std::string::npos;
  std::string path = spec.substr(0, bracket);
  const std::string section = bracket == std::string::npos ? "" : spec.substr(bracket + 1, spec.size() - bracket - 2);
  // As in POV-Ray, a name without an extension is an .ini file's.
  if (path.find('.', path.rfind('/') + 1) == std::string::npos) path += ".ini";
  if (s.iniDepth == kMaxIniDepth) {
    throw Error(quote(path) + " is more than " + std::to_string(kMaxIniDepth) + " .ini files deep");
  }
  ++s.iniDepth;
  const FileText file = readFile(path);
  const std::string_view text = file.view();
  std::string current;  // the section of the line
  bool found = section.empty();
  size_t start = 0;
  for (int line = 1; start < text.size(); ++line) {
    const size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view raw = text.substr(start, end - start);
    const std::string content = trimmed(std::string(raw.substr(0, raw.find(';'))));
    start = end + 1;
    if (!content.empty() && content[0] == '[' && content.back() == ']') {
      current = trimmed(content.substr(1, content.size() - 2));
      found = found || sameLetters(current, section);
      continue;
    }
    if (content.empty() || !sameLetters(current, section)) continue;
    try {
      // Switches, several to a line; or one key=value or file name.
      std::vector<std::string> words{content};
      if (content[0] == '+' || content[0] == '-') {
        words.clear();
        for (size_t at = 0; (at = content.find_first_not_of(" \t", at)) != std::string::npos;) {
          const size_t blank = std::min(content.find_first_of(" \t", at), content.size());
          words.push_back(content.substr(at, blank - at));
          at = blank;
        }
      }
      for (size_t i = 0; i < words.size(); ++i) readWord(s, words, i);
    } catch (const Error& e) {
      throw Error(printable(path, kMaxQuotedPath) + ":" + std::to_string(line) + ": " + e.what());
    }
  }
  if (!found) throw Error(quote(path) + " has no section " + quote("[" + section + "]"));
  --s.iniDepth;
}

// +SC, +SR: the first pixel counted from 1, or a fraction of the side; as an index from 0.
int regionStart(const std::optional<Given>& g, int side) {
  if (!g) return 0;
  if (const auto f = fraction(g->value)) return std::min(int(*f * side), side - 1);
  return parseInt(g->value, g->name.c_str(), 1, side) - 1;
}

// +EC, +ER: the last pixel counted from 1, or a fraction of the side; as the index after it.
int regionEnd(const std::optional<Given>& g, int side, int start) {
  if (!g) return side;
  const auto f = fraction(g->value);
  const int end = f ? int(*f * side) : parseInt(g->value, g->name.c_str(), 1, side);
  if (end <= start) throw Error(quote(g->word) + " ends the part to render before it starts");
  return end;
}

// +SF, +EF: a frame number, or a fraction f of the frames, as POV-Ray computes it: frame f x the number of
// frames, rounded down and kept within them.
int subsetFrame(const std::optional<Given>& g, int fallback, int first, int last) {
  if (!g) return fallback;
  if (const auto f = fraction(g->value)) return std::clamp(int(*f * (last - first + 1)), first, last);
  return parseInt(g->value, g->name.c_str(), first, last);
}

// The frames and their clocks as POV-Ray computes them: clock runs from +KI at +KFI to +KF at +KFF, or with
// +KC to one step short of +KF; each file is numbered, zero-padded to the digits of the final frame.
std::vector<PovRayFrame> frames(const Settings& s, const std::string& stem, const std::string& extension) {
  if (!s.initialFrame && !s.finalFrame) {
    if (!s.animationOnly.empty()) {
      throw Error(quote(s.animationOnly.front()) + " is for an animation: give +KFI and +KFF too");
    }
    povray::Clock still;
    still.clock = s.clock.value_or(0);
    still.on = s.clock.has_value();  // as POV-Ray sets clock_on for +K
    return {{stem + extension, still}};
  }
  if (s.clock) throw Error("+K sets the clock of one picture, but +KFI and +KFF ask for an animation");
  const int first = s.initialFrame ? std::atoi(s.initialFrame->value.c_str()) : 1;
  const int last = s.finalFrame ? std::atoi(s.finalFrame->value.c_str()) : 1;
  if (last < first) {
    throw Error("the final frame (" + (s.finalFrame ? s.finalFrame->word : "1 by default") +
                ") is before the initial frame (" + (s.initialFrame ? s.initialFrame->word : "1 by default") + ")");
  }
  const int from = subsetFrame(s.subsetStart, first, first, last);
  const int to = subsetFrame(s.subsetEnd, last, first, last);
  if (to < from) {
    throw Error("the last frame to render (" + s.subsetEnd->word + ") is before the first (" + s.subsetStart->word +
                ")");
  }
  // A cyclic animation's last frame is the one before it comes round to the first again.
  const int steps = last - first + (s.cyclic ? 1 : 0);
  povray::Clock c;
  c.on = true;
  c.initialFrame = first;
  c.finalFrame = first + steps;
  c.initialClock = s.initialClock;
  c.finalClock = s.finalClock;
  // One frame has no step: POV-Ray's clock is then NaN, ours the initial clock.
  c.delta = steps ? (s.finalClock - s.initialClock) / steps : 0;
  const size_t digits = std::to_string(c.finalFrame).size();
  std::vector<PovRayFrame> list;
  for (int f = from; f <= to; ++f) {
    c.frame = f;
    c.clock = steps ? s.initialClock + (s.finalClock - s.initialClock) * (f - first) / steps : s.initialClock;
    const std::string number = std::to_string(f);
    list.push_back({stem + std::string(digits - number.size(), '0') + number + extension, c});
  }
  return list;
}

}  // namespace

bool isPovRayCommandLine(const std::vector<std::string>& args) {
  if (args.empty()) return false;
  const std::string& a = args[0];
  const bool isSwitch =
      a.size() > 1 && (a[0] == '+' || a[0] == '-') && std::isalpha(static_cast<unsigned char>(a[1]));
  return isSwitch || isIni(a) || sameLetters(a.substr(0, 16), "Input_File_Name=");
}

PovRayJob readPovRayCommandLine(const std::vector<std::string>& args) {
  Settings s;
  for (size_t i = 0; i < args.size(); ++i) readWord(s, args, i);
  if (s.input.empty()) throw Error("no scene to render: give +Iscene.pov or Input_File_Name=scene.pov");
  const Words own = readWords(s.own);  // checked before anything is rendered
  if (!own.output.empty() && !s.output.empty()) throw Error("-o and +O both name the image: give one");
  if (!own.output.empty() && !s.type.empty()) throw Error("-o's extension and +F both pick the format: give one");
  const bool region = s.startColumn || s.startRow || s.endColumn || s.endRow;
  if (region && (!own.region.empty() || !own.tile.empty())) {
    throw Error("+SR, +ER, +SC or +EC and " + std::string(own.tile.empty() ? "--region" : "--tile") +
                " both name the part to render: give one");
  }
  // The image is named as POV-Ray names it: +O's name or the scene's, in the current folder, with the
  // format's extension added unless it is there already (in lower case); -o names it exactly.
  const std::string extension = s.type == "E" ? ".exr" : s.type == "H" ? ".hdr" : ".png";
  std::string stem = s.output;
  if (stem.empty() || stem.back() == '/') {
    const std::string name = s.input.substr(s.input.rfind('/') + 1);
    stem += name.substr(0, name.rfind('.'));
  } else if (stem.size() > extension.size() &&
             stem.compare(stem.size() - extension.size(), extension.size(), extension) == 0) {
    stem.resize(stem.size() - extension.size());
  }
  PovRayJob job;
  job.frames = frames(s, stem, extension);
  job.animation = s.initialFrame || s.finalFrame;
  if (!own.manifest.empty() && job.frames.size() > 1) {
    throw Error("--manifest lists the files of one picture, but this animation renders " +
                std::to_string(job.frames.size()) + " frames: give one with +SF and +EF");
  }
  if (!own.output.empty()) {
    // One frame of an animation (+SF and +EF the same) is one image: -o names it (a tile of it, say).
    if (job.frames.size() > 1) {
      throw Error("-o names one image, but an animation's are numbered: name them with +O");
    }
    job.frames[0].output = own.output;
  }
  job.words = {"render", s.input, std::to_string(s.width), std::to_string(s.height)};
  job.words.insert(job.words.end(), s.words.begin(), s.words.end());
  if (!s.threads.empty()) job.words.insert(job.words.end(), {"--threads", s.threads});
  if (s.display) job.words.push_back("--display");
  if (s.antialias) {
    char threshold[32];
    std::snprintf(threshold, sizeof threshold, "%.9g", s.threshold);
    job.words.insert(job.words.end(), {"--aa=" + std::to_string(s.method), std::string("--aa-threshold=") + threshold,
                                       "--aa-depth=" + std::to_string(s.depth)});
    if (s.jitter && s.jitterAmount > 0) {
      std::snprintf(threshold, sizeof threshold, "%.9g", s.jitterAmount);
      job.words.push_back(std::string("--jitter=") + threshold);
    }
  }
  if (region) {
    // raytrace renders a part as an OpenEXR tile for merge, where POV-Ray writes the whole picture.
    if (!endsWith(job.frames[0].output, ".exr")) {
      throw Error("+SR, +ER, +SC and +EC render a part of the picture, written as an OpenEXR tile: give +FE");
    }
    const int x0 = regionStart(s.startColumn, s.width), y0 = regionStart(s.startRow, s.height);
    const int x1 = regionEnd(s.endColumn, s.width, x0), y1 = regionEnd(s.endRow, s.height, y0);
    job.words.insert(job.words.end(), {"--region", std::to_string(x0) + "," + std::to_string(y0) + "," +
                                                       std::to_string(x1) + "," + std::to_string(y1)});
  }
  job.words.insert(job.words.end(), s.own.begin(), s.own.end());
  return job;
}

int runPovRayCommandLine(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const PovRayJob job = readPovRayCommandLine(args);
  int status = 0;
  for (const PovRayFrame& frame : job.frames) {
    Words words = readWords(job.words, 1);
    words.output = frame.output;
    words.load.clock = frame.clock;
    try {
      status = std::max(status, renderWords(words, out, err));
    } catch (const Error& e) {
      if (!job.animation) throw;
      throw Error("frame " + std::to_string(frame.clock.frame) + " failed, the frames before it are written: " +
                  e.what());
    }
  }
  return status;
}

}  // namespace rt
