#include "raytrace/parse/cs3451_parser.hpp"

#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "raytrace/util/limits.hpp"
#include "raytrace/util/message.hpp"
#include "raytrace/util/path.hpp"

namespace rt {

namespace {

// A whitespace-separated word of one line, where it starts.
struct Word {
  std::string text;
  SourceLoc loc;
};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Splits the text into lines of whitespace-separated words, one line at a time, so that a huge file never
// holds more than one line's words (a million spheres would otherwise take gigabytes). A word starting with
// '#' comments out the rest of its line, and a CR anywhere counts as a space, so CRLF files read like LF
// files. Control bytes are refused: a binary file should fail on its first line, not its hundredth.
class LineSplitter {
 public:
  // `text` must outlive the splitter, so a temporary string is refused at compile time.
  LineSplitter(std::string_view text, const std::string& file) : text_(text), file_(file) {}
  LineSplitter(std::string&& text, const std::string& file) = delete;

  // The words of the next line (none for a blank or comment line); false once every line has been given.
  bool next(std::vector<Word>& words) {
    if (done_) return false;
    words.clear();
    bool inWord = false, inComment = false;
    for (; i_ < text_.size(); ++i_, ++col_) {
      const char c = text_[i_];
      if (c == '\n') {
        ++i_, ++line_, col_ = 1;
        return true;
      }
      const auto byte = static_cast<unsigned char>(c);
      if ((byte < 0x20 && !isSpace(c)) || byte == 0x7F) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02X", byte);
        throw ParseError(here(), std::string("unexpected byte ") + hex + " (is this a text scene file?)");
      }
      if (inComment) continue;
      if (isSpace(c)) {
        inWord = false;
      } else if (!inWord && c == '#') {
        inComment = true;
      } else {
        if (!inWord) words.push_back(Word{"", here()});
        words.back().text += c;
        inWord = true;
      }
    }
    done_ = true;  // the last line, which no newline ends
    return true;
  }

  // The position reached: a word's or a bad byte's start, and after the last line the end of the text, for
  // errors about what the file lacks.
  SourceLoc here() const { return SourceLoc{file_, line_, col_}; }

 private:
  std::string_view text_;
  std::string file_;
  size_t i_ = 0;
  int line_ = 1, col_ = 1;
  bool done_ = false;
};

// A .cli number as the course's Python `float()` reads the files' values (`.5`, `-1`, `1e-3`), but nothing
// else strtod would take: no `nan`, `inf` or hexadecimal.
bool parseNumber(const std::string& s, double& value) {
  for (const char c : s) {
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E')) return false;
  }
  char* stop = nullptr;
  value = std::strtod(s.c_str(), &stop);
  return !s.empty() && *stop == '\0';
}

constexpr const char* kCommands[] = {"fov", "background", "light", "surface", "sphere", "cylinder", "write"};

class CliParser {
 public:
  CliParser(std::string_view text, const std::string& file) : lines_(text, file) {
    scene_.file = file;
    scene_.language = SceneLanguage::Cs3451;
    scene_.dialect = Dialect::cs3451();  // the rules that reproduce the course's reference images
  }

  SceneDesc parse() {
    std::vector<Word> words;
    while (lines_.next(words)) {
      if (!words.empty()) run(words);
    }
    if (!haveFov_) throw ParseError(lines_.here(), "the scene has no 'fov'");
    scene_.writes = std::move(writes_);
    return std::move(scene_);  // parse() is the parser's last act
  }

 private:
  void run(const std::vector<Word>& words) {
    const Word& command = words[0];
    const std::string& name = command.text;
    if (name == "fov") {
      const auto v = numbers(words, 1);
      if (!(v[0] > 0 && v[0] < 180)) {
        throw ParseError(words[1].loc, "'fov' must be between 0 and 180 degrees, found " + printable(words[1].text));
      }
      setFov(v[0], command.loc);
    } else if (name == "background") {
      scene_.background = color(numbers(words, 3), 0);
    } else if (name == "light") {
      const auto v = numbers(words, 6);
      LightDesc& light = scene_.lights.emplace_back();
      light.position = {v[3], v[4], v[5]};
      light.color = color(v, 0);  // colour first (§A.2)
    } else if (name == "surface") {
      surface(words);
    } else if (name == "sphere") {
      const auto v = numbers(words, 4);
      addObject(command, SphereDesc{{v[0], v[1], v[2]}, positive(words, 4, v, "radius")});
    } else if (name == "cylinder") {
      // `cylinder radius x z ymin ymax`: vertical and capped at both ends (§A.2).
      const auto v = numbers(words, 5);
      const double r = positive(words, 1, v, "radius");
      if (!(v[3] < v[4])) {
        throw ParseError(words[4].loc, "'cylinder' ymin must be less than ymax, found ymin " +
                                           printable(words[4].text) + " and ymax " + printable(words[5].text));
      }
      addObject(command, CylinderDesc{{v[1], v[3], v[2]}, {v[1], v[4], v[2]}, r});
    } else if (name == "write") {
      write(words);
    } else {
      std::string known;
      for (const char* c : kCommands) known += std::string(known.empty() ? "" : ", ") + c;
      throw ParseError(command.loc, "unknown command " + quote(name) + " (the commands are " + known + ")");
    }
  }

  // The command's arguments as exactly n numbers.
  std::vector<double> numbers(const std::vector<Word>& words, size_t n) {
    std::vector<double> v;
    for (size_t i = 1; i < words.size(); ++i) {
      double x = 0;
      if (!parseNumber(words[i].text, x)) {
        throw ParseError(words[i].loc, "'" + words[0].text + "' takes numbers, found " + quote(words[i].text));
      }
      if (!std::isfinite(x)) throw ParseError(words[i].loc, "number " + quote(words[i].text) + " is out of range");
      v.push_back(x);
    }
    if (v.size() != n) {
      throw ParseError(words[0].loc, "'" + words[0].text + "' needs " + std::to_string(n) +
                                         (n == 1 ? " number" : " numbers") + ", found " + std::to_string(v.size()));
    }
    return v;
  }

  static Color color(const std::vector<double>& v, size_t first) {
    return Color(float(v[first]), float(v[first + 1]), float(v[first + 2]));
  }

  // Argument i (1-based, as words[i]), which must be greater than 0.
  static double positive(const std::vector<Word>& words, size_t i, const std::vector<double>& v,
                         const std::string& what) {
    if (!(v[i - 1] > 0)) {
      throw ParseError(words[i].loc,
                       "'" + words[0].text + "' " + what + " must be greater than 0, found " +
                           printable(words[i].text));
    }
    return v[i - 1];
  }

  // The eye at the origin looking down −z with y up; `fov` is the full angle and the image plane at z = −1
  // spans ±tan(fov/2) (§A.4.1). No half-pixel offset: pixel (i, j), row j from the top, looks through
  // x = (i − W/2)·2k/W, y = −(j − H/2)·2k/H. In the camera's pixel units (y up, pixel y = H−1−j) that is the
  // pixel's upper-left corner, offset (0, 1) from its lower-left one.
  void setFov(double degrees, const SourceLoc& loc) {
    const double k = std::tan(glm::radians(degrees) / 2);
    CameraDesc& cam = scene_.camera;
    cam.location = glm::dvec3(0);
    cam.lookAt = glm::dvec3(0, 0, -1);
    cam.up = glm::dvec3(0, 2 * k, 0);
    cam.right = glm::dvec3(2 * k, 0, 0);
    cam.rightFollowsImage = true;
    cam.pixelOffset = glm::dvec2(0, 1);
    cam.loc = loc;
    haveFov_ = true;
  }

  // `surface Car Cag Cab Cdr Cdg Cdb Csr Csg Csb P Krefl`: ambient first (§A.2). The terms are used as
  // written: C = Ca + Σ (Cd·Lc·N·L + Cs·Lc·(N·H)^P) + Krefl·C_refl (§A.4.5).
  void surface(const std::vector<Word>& words) {
    const auto v = numbers(words, 11);
    if (v[9] < 0) {
      throw ParseError(words[10].loc, "'surface' power P must not be negative, found " + printable(words[10].text));
    }
    Material m;
    m.ambient = color(v, 0);
    m.diffuse = color(v, 3);
    m.specular = color(v, 6);
    m.exponent = float(v[9]);
    m.reflection = float(v[10]);
    m.pigment = m.diffuse;  // what raycast and firsthit show; .cli shading never reads it (tintReflection off)
    material_ = m;
    haveSurface_ = true;
  }

  void addObject(const Word& command, const ShapeDesc& shape) {
    // The starter has no default surface; a forgotten one is a mistake better told than drawn black.
    if (!haveSurface_) {
      throw ParseError(command.loc, "'" + command.text + "' comes before any 'surface', so it has no material");
    }
    const size_t n = scene_.objects.size();  // a file of tiny objects can outgrow memory (limits.hpp)
    const std::string shortage = objectMemoryShortage(n, n + 1, "a scene");
    if (!shortage.empty()) throw ParseError(command.loc, shortage);
    ObjectDesc o;
    o.shape = shape;
    o.material = material_;
    o.loc = command.loc;
    scene_.objects.push_back(o);
  }

  // `write name.png`: the scene as it stands now goes to that file when the scene is rendered.
  void write(const std::vector<Word>& words) {
    const Word& command = words[0];
    if (words.size() == 1) throw ParseError(command.loc, "'write' needs a file name");
    if (words.size() > 2) {
      throw ParseError(words[2].loc, "'write' takes one file name, found another word " + quote(words[2].text));
    }
    const std::string& path = words[1].text;
    if (path.size() > PATH_MAX) {  // no system opens it, and its message would quote all of it
      throw ParseError(words[1].loc, "'write' file name is longer than " + std::to_string(PATH_MAX) +
                                         " bytes: " + quote(path));
    }
    if (extension(path) != "png") {
      throw ParseError(words[1].loc, "'write' makes PNG files: the name must end in .png, found " + quote(path));
    }
    if (!haveFov_) throw ParseError(command.loc, "'write' comes before any 'fov', so there is no camera");
    writes_.push_back(WriteDesc{path, command.loc, scene_.lights.size(), scene_.objects.size(), scene_.camera,
                                scene_.background});
  }

  LineSplitter lines_;
  SceneDesc scene_;
  std::vector<WriteDesc> writes_;
  Material material_;
  bool haveSurface_ = false;
  bool haveFov_ = false;
};

}  // namespace

SceneDesc parseCs3451(std::string_view text, const std::string& file) { return CliParser(text, file).parse(); }

bool looksLikeCs3451(std::string_view text) {
  size_t lineStart = 0;
  while (lineStart < text.size()) {
    const size_t newline = text.find('\n', lineStart);
    const size_t lineEnd = newline == std::string_view::npos ? text.size() : newline;
    const std::string_view line = text.substr(lineStart, lineEnd - lineStart);
    lineStart = lineEnd + 1;
    const size_t first = line.find_first_not_of(" \t\r\f\v");
    if (first == std::string_view::npos || line[first] == '#') continue;
    const std::string_view word = line.substr(first, line.find_first_of(" \t\r\f\v", first) - first);
    for (const char* command : kCommands) {
      if (word == command) return line.find('{') == std::string_view::npos;
    }
    return false;
  }
  return false;
}

}  // namespace rt
