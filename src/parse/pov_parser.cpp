#include "raytrace/parse/pov_parser.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "raytrace/util/limits.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/parse/pov_parts.hpp"
#include "raytrace/parse/tokenizer.hpp"

namespace rt {

namespace {

// The shortest an object can be written: `plane{<0,1,0>,0}`.
constexpr size_t kMinObjectBytes = 16;

class PovParser {
 public:
  // `text` is a whole file, or whole lines of one from line `firstLine` on, one of `parts` read at once.
  // `room` objects are reserved (objectRoom(), where memory allows).
  PovParser(std::string_view text, const std::string& file, size_t room, int firstLine = 1,
            std::uint64_t parts = 1)
      : tokens_(text, file, firstLine), current_(tokens_.next()), parts_(parts) {
    scene_.file = file;
    scene_.objects.reserve(room);
  }

  SceneDesc parse() {
    statements();
    if (cameras_ == 0) throw ParseError(peek().loc, "the scene has no camera");
    return std::move(scene_);  // parse() is the parser's last act
  }

  PovPart part() {
    statements();
    return {std::move(scene_), cameras_};
  }

 private:
  void statements() {
    while (peek().kind != Token::Kind::End) {
      const Token& t = next();
      if (t.kind != Token::Kind::Word) {
        throw ParseError(t.loc, "expected 'camera', 'light_source' or an object, found " + t.quoted());
      }
      if (t.text == "camera") {
        parseCamera(t);
        ++cameras_;
      } else if (t.text == "light_source") {
        parseLight(t);
      } else if (isShapeKeyword(t.text)) {
        parseObject(t);
      } else {
        throw ParseError(t.loc, "unknown keyword " + t.quoted());
      }
    }
  }

  const Token& peek() const { return current_; }
  // By value: the token after it replaces the lookahead, and a caller's `const Token&` keeps the value alive.
  Token next() {
    Token t = std::move(current_);
    current_ = t.kind == Token::Kind::End ? t : tokens_.next();
    return t;
  }
  bool isPunct(const Token& t, char c) const { return t.kind == Token::Kind::Punct && t.text[0] == c; }

  // The context is a C string so that the message costs nothing until it is needed.
  void expect(char c, const char* context) {
    const Token& t = next();
    if (!isPunct(t, c)) {
      throw ParseError(t.loc, std::string("expected '") + c + "' " + context + ", found " + t.quoted());
    }
  }
  void expect(char c, const std::string& context) { expect(c, context.c_str()); }

  // `what` completes "expected a number for …", e.g. "the sphere radius". The messages here are put together
  // only for an error: these run for every object, and the names are C strings so that they cost nothing.
  double numberFor(const char* what) {
    const Token& t = next();
    if (t.kind != Token::Kind::Number) {
      throw ParseError(t.loc, std::string("expected a number for ") + what + ", found " + t.quoted());
    }
    return t.number;
  }
  // The number after a keyword, e.g. `ambient 0.2`.
  double numberAfter(const Token& keyword) {
    const Token& t = next();
    if (t.kind != Token::Kind::Number) {
      throw ParseError(t.loc, "expected a number after " + keyword.quoted() + ", found " + t.quoted());
    }
    return t.number;
  }

  // `<a, b, …>` with between minN and maxN components.
  // The components of a vector: at most four are ever wanted, and `size` counts all that were written.
  struct Components {
    std::array<double, 4> v{};
    size_t size = 0;
    double operator[](size_t i) const { return v[i]; }
  };

  // `<a, b, …>` with between minN and maxN (at most 4) components.
  Components vector(int minN, int maxN, const char* what) {
    const Token& open = next();
    if (!isPunct(open, '<')) {
      throw ParseError(open.loc, std::string("expected '<' to start ") + what + ", found " + open.quoted());
    }
    Components v;
    for (;;) {
      const Token& t = next();
      if (t.kind != Token::Kind::Number) {
        throw ParseError(t.loc, std::string("expected a number in ") + what + ", found " + t.quoted());
      }
      if (v.size < v.v.size()) v.v[v.size] = t.number;
      ++v.size;
      if (!isPunct(peek(), ',')) break;
      next();
    }
    const Token& close = next();
    if (!isPunct(close, '>')) {
      throw ParseError(close.loc, std::string("expected ',' or '>' in ") + what + ", found " + close.quoted());
    }
    if (int(v.size) < minN || int(v.size) > maxN) {
      const std::string want = minN == maxN ? std::to_string(minN) : std::to_string(minN) + " or " + std::to_string(maxN);
      throw ParseError(close.loc, std::string(what) + " needs " + want + " components, found " + std::to_string(v.size));
    }
    return v;
  }

  // [color|colour] rgb <r,g,b> | rgbf <r,g,b[,f]>; a missing filter is 0, as POV-Ray reads a 3-vector.
  // POV-Ray 3.7 also reads `rgb <r,g,b,f>`, with the fourth value as the filter and a "suspicious
  // expression" warning (marble2.pov relies on it); so do we.
  void color(Color& rgb, float& filter, const std::string& owner) {
    Token t = next();
    if (t.kind == Token::Kind::Word && (t.text == "color" || t.text == "colour")) t = next();
    if (t.kind != Token::Kind::Word || (t.text != "rgb" && t.text != "rgbf")) {
      throw ParseError(t.loc, "expected 'rgb' or 'rgbf' in the " + owner + " colour, found " + t.quoted());
    }
    const SourceLoc at = peek().loc;
    const auto v = vector(3, 4, t.text == "rgb" ? "an 'rgb' colour" : "an 'rgbf' colour");
    if (t.text == "rgb" && v.size == 4) {
      scene_.warnings.push_back(at.str() + ": warning: 'rgb' with 4 values; the fourth is read as the filter");
    }
    rgb = Color(float(v[0]), float(v[1]), float(v[2]));
    filter = v.size == 4 ? float(v[3]) : 0.0f;
    if (filter < 0 || filter > 1) throw ParseError(at, "filter must be between 0 and 1, found " + shortest(filter));
  }

  void parseCamera(const Token& keyword) {
    expect('{', "after 'camera'");
    CameraDesc& cam = scene_.camera;
    cam.loc = keyword.loc;
    for (;;) {
      const Token& t = next();
      if (isPunct(t, '}')) break;
      if (t.kind == Token::Kind::End) throw ParseError(t.loc, unclosed("camera", keyword));
      if (t.text == "location") {
        cam.location = vec3("the camera location");
      } else if (t.text == "up") {
        cam.up = vec3("the camera up vector");
      } else if (t.text == "right") {
        cam.right = vec3("the camera right vector");
      } else if (t.text == "look_at") {
        cam.lookAt = vec3("the camera look_at point");
      } else {
        throw ParseError(t.loc, "unknown camera property " + t.quoted());
      }
    }
    if (cam.lookAt == cam.location) throw ParseError(keyword.loc, "the camera's look_at equals its location");
    if (cam.up == glm::dvec3(0)) throw ParseError(keyword.loc, "the camera's up vector is zero");
    if (cam.right == glm::dvec3(0)) throw ParseError(keyword.loc, "the camera's right vector is zero");
    if (glm::length(glm::cross(cam.up, cam.right)) == 0) {
      throw ParseError(keyword.loc, "the camera's up and right vectors are parallel");
    }
  }

  void parseLight(const Token& keyword) {
    expect('{', "after 'light_source'");
    LightDesc light;
    light.position = vec3("the light position");
    float filter = 0;
    color(light.color, filter, "light");
    const Token& t = next();
    if (t.kind == Token::Kind::End) throw ParseError(t.loc, unclosed("light_source", keyword));
    if (!isPunct(t, '}')) throw ParseError(t.loc, "unknown light_source property " + t.quoted());
    scene_.lights.push_back(light);
  }

  void parseObject(const Token& keyword) {
    ObjectDesc obj = readObject(keyword);
    // A file of tiny objects can outgrow memory (limits.hpp). A part stands for its share of the file.
    const std::uint64_t n = scene_.objects.size();
    const std::string shortage = objectMemoryShortage(n * parts_, (n + 1) * parts_, "a scene");
    if (!shortage.empty()) throw ParseError(keyword.loc, shortage);
    scene_.objects.push_back(std::move(obj));
  }

 public:
  // The calls a shape kind's read() makes (shapes/kind.hpp).
  glm::dvec3 vec3(const char* what) {
    const auto v = vector(3, 3, what);
    return {v[0], v[1], v[2]};
  }
  double number(const char* what) { return numberFor(what); }
  std::vector<double> coefficients(size_t n, const char* what) {
    expect('<', std::string("to start ") + what);
    std::vector<double> c;
    for (;;) {
      c.push_back(numberFor(what));
      if (!isPunct(peek(), ',')) break;
      next();
    }
    const Token& close = next();
    if (!isPunct(close, '>')) {
      throw ParseError(close.loc, std::string("expected ',' or '>' in ") + what + ", found " + close.quoted());
    }
    if (c.size() != n) {
      throw ParseError(close.loc,
                       std::string(what) + " need " + std::to_string(n) + " numbers, found " + std::to_string(c.size()));
    }
    return c;
  }
  void comma(const char* after) { expect(',', after); }
  bool moreNumbers() const { return isPunct(peek(), ','); }
  SourceLoc here() const { return peek().loc; }
  bool objectNext() const { return peek().kind == Token::Kind::Word && isShapeKeyword(peek().text); }
  bool valueNext() const { return peek().kind == Token::Kind::Number || isPunct(peek(), '<'); }
  ObjectDesc object() { return readObject(next()); }
  // The course language has no strings, keywords or blocks in a shape, and so no text, prism, lathe, sor or
  // blob or isosurface: the first of these their read() calls stops it.
  bool keyword(std::string_view) const { throw povRayOnly(); }
  std::string string(const char*) const { throw povRayOnly(); }
  std::string findFont(const std::string&) const { throw povRayOnly(); }
  std::string findFile(const std::string&) const { throw povRayOnly(); }
  bool functionNext() const { throw povRayOnly(); }
  template <class S> bool texture(S&, const void*&) const { throw povRayOnly(); }
  template <class F> bool block(std::string_view, F&&) const { throw povRayOnly(); }
  bool function(std::shared_ptr<const Function>&) const { throw povRayOnly(); }
  bool imageFunction(std::shared_ptr<const Function>&, double&, double&) const { throw povRayOnly(); }
  std::vector<TransformStep> transforms() const { throw povRayOnly(); }
  ParseError povRayOnly() const {
    return ParseError(here(), "'" + std::string(kind_) + "' is read only in POV-Ray 3.7 scenes");
  }
  double positive(const char* what) {
    const SourceLoc at = peek().loc;
    const double v = numberFor(what);
    if (!(v > 0)) throw ParseError(at, std::string(what) + " must be greater than 0, found " + shortest(v));
    return v;
  }
  double nonNegative(const char* what) {
    const SourceLoc at = peek().loc;
    const double v = numberFor(what);
    if (v < 0) throw ParseError(at, std::string(what) + " must not be negative, found " + shortest(v));
    return v;
  }

 private:
  // An object, from the '{' after its keyword to its closing brace.
  ObjectDesc readObject(const Token& keyword) {
    expect('{', "after " + keyword.quoted());
    ObjectDesc obj;
    obj.loc = keyword.loc;
    kind_ = keyword.text;
    obj.shape = *readShape(keyword.text, *this);
    parseModifiers(obj, keyword);
    passTextureDown(obj);
    return obj;
  }

  // pigment, finish and transforms, in any order and repeated, up to the object's closing brace.
  void parseModifiers(ObjectDesc& obj, const Token& keyword) {
    Finish finish = *obj.finish;
    bool finishRead = false;
    for (;;) {
      const Token& t = next();
      if (isPunct(t, '}')) break;
      if (t.kind == Token::Kind::End) throw ParseError(t.loc, unclosed(keyword.text, keyword));
      if (t.text == "pigment") {
        expect('{', "after 'pigment'");
        color(obj.material.pigment, obj.material.filter, "pigment");
        expect('}', "to close the pigment");
        obj.textured = true;
      } else if (t.text == "finish") {
        parseFinish(finish, t);
        finishRead = true;
        obj.textured = true;
      } else if (t.text == "translate") {
        obj.transforms.push_back({TransformStep::Kind::Translate, vec3("the translation")});
      } else if (t.text == "scale") {
        obj.transforms.push_back({TransformStep::Kind::Scale, scaleFactors()});
      } else if (t.text == "rotate") {
        obj.transforms.push_back({TransformStep::Kind::Rotate, vec3("the rotation")});
      } else {
        throw ParseError(t.loc, "unknown " + std::string(keyword.text) + " property " + t.quoted());
      }
    }
    if (finishRead) obj.finish = finish;
    Material& m = obj.material;
    m.ambient = float(finish.ambient) * m.pigment;
    m.diffuse = float(finish.diffuse) * m.pigment;
    m.specular = float(finish.specular) * m.pigment;
    m.roughness = float(finish.roughness);
    m.exponent = float(2.0 / (finish.roughness * finish.roughness) - 2.0);  // §c.1
    m.reflection = float(finish.reflection);
    m.ior = float(finish.ior);
  }

  // `scale <x,y,z>` or POV-Ray's uniform `scale s`; a zero factor would make the object unrenderable.
  glm::dvec3 scaleFactors() {
    const SourceLoc at = peek().loc;
    const glm::dvec3 s = peek().kind == Token::Kind::Number ? glm::dvec3(numberFor("the scale")) : vec3("the scale");
    if (s.x == 0 || s.y == 0 || s.z == 0) throw ParseError(at, "a scale factor is zero");
    return s;
  }

  void parseFinish(Finish& f, const Token& keyword) {
    expect('{', "after 'finish'");
    for (;;) {
      const Token& t = next();
      if (isPunct(t, '}')) break;
      if (t.kind == Token::Kind::End) throw ParseError(t.loc, unclosed("finish", keyword));
      const SourceLoc at = peek().loc;
      if (t.text == "ambient") {
        f.ambient = numberAfter(t);
      } else if (t.text == "diffuse") {
        f.diffuse = numberAfter(t);
      } else if (t.text == "specular") {
        f.specular = numberAfter(t);
      } else if (t.text == "roughness") {
        f.roughness = numberAfter(t);
        // 0 would make the exponent 2/roughness² − 2 infinite.
        if (!(f.roughness > 0)) throw ParseError(at, "roughness must be greater than 0, found " + shortest(f.roughness));
      } else if (t.text == "reflection") {
        f.reflection = numberAfter(t);
      } else if (t.text == "refraction") {
        f.refraction = numberAfter(t);
      } else if (t.text == "ior") {
        f.ior = numberAfter(t);
        if (!(f.ior > 0)) throw ParseError(at, "ior must be greater than 0, found " + shortest(f.ior));
      } else if (t.text == "metallic") {
        // A real POV-Ray finish keyword that this renderer does not model: read, said, and ignored.
        numberAfter(t);
        scene_.warnings.push_back(t.loc.str() + ": warning: 'metallic' is not modelled and is ignored");
      } else {
        throw ParseError(t.loc, "unknown finish property " + t.quoted());
      }
    }
  }

  static std::string unclosed(std::string_view what, const Token& opener) {
    return "end of file inside the " + std::string(what) + " started at line " + std::to_string(opener.loc.line) +
           "; expected '}'";
  }

  Tokenizer tokens_;
  Token current_;          // the one token of lookahead
  std::string_view kind_;  // the shape being read, for povRayOnly()
  std::uint64_t parts_;
  SceneDesc scene_;
  int cameras_ = 0;
};

}  // namespace

SceneDesc parsePov(std::string_view text, const std::string& file, int threads) {
  const size_t room = objectRoom(text.size());
  if (room == 0) return PovParser(text, file, 0).parse();  // a small text: nothing to reserve or to share out
  // In parts only with memory to spare for as many objects as the text could hold: where memory is short, the
  // one-piece read meets the memory checks exactly where it would on one thread, and the parts, which would
  // use memory of their own first, are not tried.
  const std::uint64_t available = availableMemory();
  const std::uint64_t mostObjects = text.size() / kMinObjectBytes;
  if (text.size() >= 2 * kMinPartBytes && threads > 1 &&
      memoryShortage("", mostObjects * kBytesPerObject, available).empty()) {
    // One part per thread: the fewer the parts, the fewer objects are copied into the first one's list. The
    // helper threads start while the cuts are found.
    const int count = int(std::min<size_t>(size_t(threads), text.size() / kMinPartBytes));
    startHelpers(count);
    const auto readPart = [&](std::string_view part, int firstLine, size_t partRoom, std::uint64_t parts) {
      return PovParser(part, file, partRoom, firstLine, parts).part();
    };
    if (auto scene = parseParts(text, partStarts(text, count), threads, readPart)) return std::move(*scene);
  }
  // Room only where memory allows, as parseObject()'s checks would.
  const bool roomFits = memoryShortage("", room * sizeof(ObjectDesc), available).empty();
  return PovParser(text, file, roomFits ? room : 0).parse();
}

}  // namespace rt
