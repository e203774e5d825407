#include "raytrace/parse/povray/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>

#include "raytrace/parse/povray/interpreter.hpp"
#include "raytrace/parse/povray/surface_reader.hpp"
#include "raytrace/util/format.hpp"
#include "raytrace/util/limits.hpp"

namespace rt::povray {

namespace {

class Builder {
 public:
  Builder(SceneDesc& scene, const Interpreter& interpreter) : scene_(scene), interpreter_(interpreter) {}

  void statement(const Node& n) {
    const std::string_view k = n.keyword;
    if (k == "camera") {
      camera(n);
    } else if (k == "light_source") {
      light(n);
    } else if (k == "global_settings") {
      globalSettings(n);
    } else if (k == "background") {
      for (const Item& i : n.items) {
        if (i.kind == Item::Kind::Value && i.value.numeric()) scene_.conventions.background = colourOf(i.value).rgb;
      }
    } else {
      ObjectDesc o;
      if (object(n, o)) add(std::move(o), n.loc);
    }
  }

  void defaults(const Node& n) {
    for (const Item& i : n.items) {
      if (i.kind != Item::Kind::Node) continue;
      readSurfaceItem(*i.node, default_, refusals_);
    }
  }

  void finish() {
    if (refusals_.first) throw ParseError(refusals_.first->loc, "'" + refusals_.first->what + "' is not supported yet");
  }

 private:
  // A union's children go into the scene one by one, under the union's transforms: the same surfaces, and the
  // hierarchy bounds each of them (POV-Ray's split_union).
  void add(ObjectDesc o, const SourceLoc& at) {
    if (auto* csg = std::get_if<CsgDesc>(&o.shape); csg && csg->op == CsgOp::Union) {
      for (ObjectDesc& child : csg->children) {
        child.transforms.insert(child.transforms.end(), o.transforms.begin(), o.transforms.end());
        add(std::move(child), at);
      }
      return;
    }
    const std::string shortage = objectMemoryShortage(scene_.objects.size(), scene_.objects.size() + 1, "the scene");
    if (!shortage.empty()) throw ParseError(at, shortage);
    scene_.objects.push_back(std::move(o));
  }

  void refuse(const SourceLoc& loc, std::string_view what) { refusals_.refuse(loc, what); }
  bool transformItem(const Node& n, size_t& i, std::vector<TransformStep>& steps) {
    return readTransform(n, i, steps, refusals_);
  }

  // A shape's values for its kind's read() (shapes/kind.hpp), taken from the items of its node in order.
  class ItemReader {
   public:
    ItemReader(Builder& b, const Node& n, size_t& i) : b_(b), n_(n), i_(i) {}
    glm::dvec3 vec3(const char* what) {
      const Item& it = take(what);
      if (!it.value.numeric()) throw ParseError(it.loc, std::string("expected a vector for ") + what + ", found a " + typeName(it.value));
      return povray::vec3(it.value);
    }
    double number(const char* what) {
      const Item& it = take(what);
      if (it.value.type != Value::Type::Float) throw ParseError(it.loc, std::string("expected a float for ") + what + ", found a " + typeName(it.value));
      return it.value.v[0];
    }
    double positive(const char* what) {
      const SourceLoc at = here();
      const double v = number(what);
      if (!(v > 0)) throw ParseError(at, std::string(what) + " must be greater than 0, found " + shortest(v));
      return v;
    }
    double nonNegative(const char* what) {
      const SourceLoc at = here();
      const double v = number(what);
      if (v < 0) throw ParseError(at, std::string(what) + " must not be negative, found " + shortest(v));
      return v;
    }
    void comma(const char*) {}  // the interpreter has dropped them
    bool keyword(std::string_view word) {
      if (i_ >= n_.items.size() || n_.items[i_].kind != Item::Kind::Keyword || n_.items[i_].word != word) return false;
      ++i_;
      return true;
    }
    std::string string(const char* what) {
      const Item& it = take(what);
      if (it.value.type != Value::Type::String) throw ParseError(it.loc, std::string("expected a string for ") + what + ", found a " + typeName(it.value));
      // POV-Ray's default charset, ascii, turns every byte past 127 into a blank; utf8 and sys keep them.
      std::string s = it.value.s;
      if (b_.asciiStrings_) std::replace_if(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) > 127; }, ' ');
      return s;
    }
    std::string findFont(const std::string& name) const { return b_.interpreter_.findFont(name); }
    SourceLoc here() const { return i_ < n_.items.size() ? n_.items[i_].loc : n_.loc; }
    bool objectNext() {
      while (i_ < n_.items.size() && b_.lightHere(n_.items[i_])) ++i_;
      return i_ < n_.items.size() && isObject(n_.items[i_]);
    }
    ObjectDesc object() {
      ObjectDesc child;
      b_.object(*n_.items[i_++].node, child);
      return child;
    }

   private:
    const Item& take(const char* what) {
      if (i_ >= n_.items.size() || n_.items[i_].kind != Item::Kind::Value) {
        throw ParseError(here(), "'" + std::string(n_.keyword) + "' needs " + what);
      }
      return n_.items[i_++];
    }
    Builder& b_;
    const Node& n_;
    size_t& i_;
  };

  // Whether an item is an object: a shape of ours, or one of POV-Ray's that is refused when read.
  static bool isObject(const Item& it) {
    static constexpr std::string_view kPovObjects[] = {
        "bicubic_patch", "blob", "cubic", "disc", "height_field", "isosurface", "julia_fractal", "lathe", "mesh",
        "mesh2", "object", "ovus", "parametric", "poly", "polygon", "polynomial", "prism", "quadric", "quartic",
        "smooth_triangle", "sor", "sphere_sweep", "superellipsoid", "torus"};
    if (it.kind != Item::Kind::Node) return false;
    const std::string_view k = it.node->keyword;
    return isShapeKeyword(k) || std::find(std::begin(kPovObjects), std::end(kPovObjects), k) != std::end(kPovObjects);
  }

  // A light source inside an object (POV-Ray moves it with the object): added to the scene here, and moved by
  // the object's transforms once they are known (object()).
  bool lightHere(const Item& it) {
    if (it.kind != Item::Kind::Node || it.node->keyword != "light_source") return false;
    light(*it.node);
    return true;
  }

  // One object into `o`, and its surface into `s`; false when it cannot be drawn (and is refused).
  bool object(const Node& n, ObjectDesc& o) {
    Surface s = default_;
    return object(n, o, s);
  }

  bool object(const Node& n, ObjectDesc& o, Surface& s) {
    const std::string_view k = n.keyword;
    const size_t firstLight = scene_.lights.size();
    size_t i = 0;
    if (k == "object") {
      if (i >= n.items.size() || n.items[i].kind != Item::Kind::Node) throw ParseError(n.loc, "'object' needs an object identifier");
      if (!object(*n.items[i++].node, o, s)) return false;
    } else {
      ItemReader reader(*this, n, i);
      // A union of light sources alone, which POV-Ray allows to move them together.
      const bool lightsAlone = k == "union" && std::none_of(n.items.begin(), n.items.end(), isObject);
      std::optional<ShapeDesc> shape = lightsAlone ? ShapeDesc(CsgDesc{}) : readShape(k, reader);
      if (!shape) {
        refuse(n.loc, k);
        return false;
      }
      o.shape = std::move(*shape);
      o.loc = n.loc;
      if (auto* box = std::get_if<BoxDesc>(&o.shape)) *box = BoxDesc{glm::min(box->min, box->max), glm::max(box->min, box->max)};
    }
    auto* csg = std::get_if<CsgDesc>(&o.shape);
    const size_t ownTransforms = o.transforms.size();  // after those of an `object { Name` before them
    std::optional<size_t> textureFrom;  // the transforms from here on move this level's texture
    bool textureBlock = false;
    for (; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (transformItem(n, i, o.transforms)) continue;
      if (csg && k != "object" && isObject(it)) {
        ObjectDesc child;
        object(*it.node, child);
        csg->children.push_back(std::move(child));
        continue;
      }
      if (lightHere(it)) continue;
      if (it.kind == Item::Kind::Node) {
        const std::string_view m = it.node->keyword;
        if (m == "bounded_by" || m == "photons" || m == "radiosity") continue;
        if (m == "pigment" || m == "finish" || m == "texture" || m == "material" || m == "interior" ||
            m == "layered texture") {
          // A second texture block is a layer on top of the first.
          if (m == "texture" && textureBlock) s.layers.emplace_back();
          textureBlock = textureBlock || m == "texture";
          readSurfaceItem(*it.node, s, refusals_);
          if (!textureFrom) textureFrom = o.transforms.size();
        } else {
          refuse(it.loc, m);
        }
      } else if (it.kind == Item::Kind::Keyword) {
        if (it.word == "hollow" || it.word == "sturm") {
          valueAfter(n, i);
        } else {
          refuse(it.loc, it.word);
        }
      } else {
        refuse(it.loc, "a value here");
      }
    }
    const std::vector<TransformStep> own(o.transforms.begin() + long(ownTransforms), o.transforms.end());
    moveTextures(o, glm::inverse(composeTransforms<double>(own)));
    if (textureFrom || k != "object") surface(o, s, std::vector(o.transforms.begin() + long(textureFrom.value_or(o.transforms.size())), o.transforms.end()));
    if (textureFrom) o.textured = true;
    passTextureDown(o);
    const glm::dmat4 m = composeTransforms<double>(own);
    for (size_t l = firstLight; l < scene_.lights.size(); ++l) {
      scene_.lights[l].position = glm::dvec3(m * glm::dvec4(scene_.lights[l].position, 1));
    }
    return true;
  }

  // The object's material, and its texture when its colour varies over it, moved by the transforms `after`.
  void surface(ObjectDesc& o, const Surface& s, const std::vector<TransformStep>& after) {
    if (anyColour(s.layers.front().pigment, [](const Rgbft& c) { return c.transmit > 0; })) refuse(o.loc, "transmit");
    o.material = constantMaterial(s);
    o.finish = writtenFinish(s);
    o.texture = s.patterned() ? std::make_shared<const Texture>(bounded(makeTexture(s, after))) : nullptr;
  }

  // Textures made at a deeper level (a child's, or a declared object's) moved with this level's transforms:
  // `undo` takes this level's world back to the one they were made in.
  static void moveTextures(ObjectDesc& o, const glm::dmat4& undo) {
    if (o.texture) {
      auto t = std::make_shared<Texture>(*o.texture);
      t->fromWorld = t->fromWorld * undo;
      o.texture = t;
    }
    if (auto* csg = std::get_if<CsgDesc>(&o.shape)) {
      for (ObjectDesc& child : csg->children) moveTextures(child, undo);
    }
  }

  // POV-Ray's camera: defaults, then angle sets the direction's length, look_at turns direction, right and up
  // about the sky keeping their lengths and the handedness of right, then the transforms.
  void camera(const Node& n) {
    glm::dvec3 location(0), direction(0, 0, 1), up(0, 1, 0), right(1.33, 0, 0), sky(0, 1, 0);
    std::optional<glm::dvec3> lookAt;
    std::optional<double> angle;
    std::vector<TransformStep> steps;
    collectCamera(n, location, direction, up, right, sky, lookAt, angle, steps);
    if (angle) {
      direction = glm::normalize(direction) * (0.5 * glm::length(right) / std::tan(glm::radians(*angle) / 2));
    }
    if (lookAt) {
      const double handedness = glm::dot(glm::cross(up, direction), right);
      direction = glm::normalize(*lookAt - location) * glm::length(direction);
      right = glm::normalize(glm::cross(sky, direction)) * glm::length(right);
      up = glm::normalize(glm::cross(direction, right)) * glm::length(up);
      if (handedness < 0) right = -right;
    }
    const glm::dmat4 m = composeTransforms<double>(steps);
    location = glm::dvec3(m * glm::dvec4(location, 1));
    direction = glm::dvec3(m * glm::dvec4(direction, 0));
    up = glm::dvec3(m * glm::dvec4(up, 0));
    right = glm::dvec3(m * glm::dvec4(right, 0));
    const double length = glm::length(direction);
    CameraDesc& c = scene_.camera;
    c.location = location;
    c.lookAt = location + direction / length;
    c.right = right / length;
    c.up = up / length;
    c.loc = n.loc;
  }

  void collectCamera(const Node& n, glm::dvec3& location, glm::dvec3& direction, glm::dvec3& up, glm::dvec3& right,
                     glm::dvec3& sky, std::optional<glm::dvec3>& lookAt, std::optional<double>& angle,
                     std::vector<TransformStep>& steps) {
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (it.kind == Item::Kind::Node && it.node->keyword == "camera") {
        collectCamera(*it.node, location, direction, up, right, sky, lookAt, angle, steps);
        continue;
      }
      if (transformItem(n, i, steps)) continue;
      if (it.kind != Item::Kind::Keyword) {
        refuse(it.loc, it.kind == Item::Kind::Node ? it.node->keyword : "camera");
        continue;
      }
      const std::string_view w = it.word;
      if (w == "perspective") continue;
      const Value* v = valueAfter(n, i);
      if (!v) {
        refuse(it.loc, w);
        continue;
      }
      if (!v->numeric()) throw ParseError(n.items[i].loc, "expected a vector after '" + std::string(w) + "', found a " + typeName(*v));
      if (w == "location") location = vec3(*v);
      else if (w == "direction") direction = vec3(*v);
      else if (w == "up") up = vec3(*v);
      else if (w == "right") right = vec3(*v);
      else if (w == "sky") sky = vec3(*v);
      else if (w == "look_at") lookAt = vec3(*v);
      else if (w == "angle") angle = v->v[0];
      else refuse(it.loc, w);
    }
  }

  void light(const Node& n) {
    LightDesc l;
    size_t i = 0;
    if (i < n.items.size() && n.items[i].kind == Item::Kind::Value) l.position = vec3(n.items[i++].value);
    if (i < n.items.size() && n.items[i].kind == Item::Kind::Value) {
      l.color = colourOf(n.items[i++].value).rgb;
    }
    std::vector<TransformStep> steps;
    for (; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (transformItem(n, i, steps)) continue;
      if (it.kind == Item::Kind::Keyword && (it.word == "media_interaction" || it.word == "media_attenuation")) {
        valueAfter(n, i);
        continue;
      }
      refuse(it.loc, it.kind == Item::Kind::Node ? it.node->keyword : it.kind == Item::Kind::Keyword ? it.word : "light_source");
    }
    l.position = glm::dvec3(composeTransforms<double>(steps) * glm::dvec4(l.position, 1));
    scene_.lights.push_back(l);
  }

  void globalSettings(const Node& n) {
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (it.kind == Item::Kind::Keyword) {
        const std::string_view w = it.word;
        if (w == "charset") {
          asciiStrings_ = i + 1 < n.items.size() && n.items[i + 1].word == "ascii";
          ++i;
          continue;
        }
        const Value* v = valueAfter(n, i);
        if (w == "max_trace_level" && v && v->type == Value::Type::Float) {
          scene_.conventions.maxDepth = int(std::max(1.0, v->v[0]));
        } else if (w == "ambient_light" && v && v->numeric()) {
          ambientLight_ = colourOf(*v).rgb;
        } else if (w == "assumed_gamma" && v && v->type == Value::Type::Float) {
          assumedGamma_ = v->v[0];
        } else if (w == "adc_bailout" || w == "number_of_waves" || w == "noise_generator" ||
                   w == "irid_wavelength" || w == "max_intersections" || w == "hf_gray_16") {
        } else {
          refuse(it.loc, w);
        }
      } else {
        refuse(it.loc, it.kind == Item::Kind::Node ? it.node->keyword : "global_settings");
      }
    }
  }

 public:
  Color ambientLight_{1};
  std::optional<double> assumedGamma_;

 private:
  SceneDesc& scene_;
  const Interpreter& interpreter_;
  bool asciiStrings_ = true;  // global_settings' charset
  Surface default_;
  Refusals refusals_;
};

// global_settings' ambient_light scales every ambient term, a CSG group's parts' too.
void scaleAmbient(ObjectDesc& o, const Color& light) {
  o.material.ambient *= light;
  if (o.texture) {
    Texture t = *o.texture;
    for (TextureLayer& layer : t.layers) layer.finish.ambient *= light;
    o.texture = std::make_shared<const Texture>(bounded(std::move(t)));
  }
  if (auto* csg = std::get_if<CsgDesc>(&o.shape)) {
    for (ObjectDesc& child : csg->children) scaleAmbient(child, light);
  }
}

}  // namespace

SceneDesc parsePovRay(std::string_view text, const std::string& path, const PovRayOptions& options) {
  SceneDesc scene;
  scene.file = path;
  scene.language = SceneLanguage::PovRay;
  scene.camera.right = {1.33, 0, 0};
  scene.camera.lookAt = {0, 0, 1};
  scene.conventions.reflectionMixes = false;  // POV-Ray adds reflected light to the surface's own
  scene.conventions.tintReflection = false;
  InterpreterOptions io;
  io.libraryPaths = options.libraryPaths;
  io.imageWidth = options.imageWidth;
  io.imageHeight = options.imageHeight;
  io.debug = options.debugOutput ? &std::cerr : nullptr;
  io.maxTokens = options.maxTokens;
  io.writeFolder = options.writeFolder;
  io.writeAnywhere = options.writeAnywhere;
  Interpreter interpreter(io);
  for (const std::string& d : options.declares) {
    const size_t eq = d.find('=');
    interpreter.declare(d.substr(0, eq), eq == std::string::npos ? "1" : d.substr(eq + 1));
  }
  Builder builder(scene, interpreter);
  interpreter.run(path, text, [&](const std::shared_ptr<const Node>& n) { builder.statement(*n); },
                  [&](const std::shared_ptr<const Node>& n) { builder.defaults(*n); });
  builder.finish();
  // POV-Ray 3.7 works in linear light and writes sRGB when assumed_gamma is 1, which is its default from
  // #version 3.7 on; an older scene, or another gamma (mostly 2.2), has its colours written as they are
  // (docs/povray-language.md, "Gamma").
  const double gamma = builder.assumedGamma_.value_or(interpreter.version() >= 3.7 ? 1.0 : 0.0);
  if (gamma == 1.0) scene.conventions.toByte = Conventions::ToByte::Srgb;
  for (ObjectDesc& o : scene.objects) scaleAmbient(o, builder.ambientLight_);
  scene.dataFiles = interpreter.takeDataFiles();
  return scene;
}

bool usesPovRayLanguage(std::string_view text) {
  // A '#' followed by a letter outside a comment or string, or the word global_settings.
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      const size_t end = text.find("*/", i + 2);
      if (end == std::string_view::npos) return false;
      i = end + 1;
    } else if (c == '"') {
      while (++i < text.size() && text[i] != '"' && text[i] != '\n') {
      }
    } else if (c == '#') {
      size_t j = i + 1;
      while (j < text.size() && (text[j] == ' ' || text[j] == '\t')) ++j;
      if (j < text.size() && std::isalpha(static_cast<unsigned char>(text[j]))) return true;
    } else if (c == 'g' && text.compare(i, 15, "global_settings") == 0 &&
               (i == 0 || !(std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_'))) {
      return true;
    }
  }
  return false;
}

}  // namespace rt::povray
