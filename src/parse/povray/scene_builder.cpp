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
    } else if (k == "sky_sphere") {
      skySphere(n);
    } else if (k == "fog") {
      fog(n);
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
      readSurfaceItem(*i.node, default_, default_, refusals_);
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
        child.noShadow = child.noShadow || o.noShadow;
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
    std::vector<double> coefficients(size_t n, const char* what) {
      const Item& it = take(what);
      if (it.value.type != Value::Type::Vector) {
        throw ParseError(it.loc, std::string("expected a list of ") + what + ", found a " + typeName(it.value));
      }
      const auto* list = dynamic_cast<const CoefficientList*>(it.value.ref.get());
      const std::vector<double> c = list ? list->values : std::vector<double>(it.value.v.begin(), it.value.v.begin() + it.value.size);
      if (c.size() != n) {
        throw ParseError(it.loc, std::string(what) + " need " + std::to_string(n) + " numbers, found " + std::to_string(c.size()));
      }
      return c;
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
        "bicubic_patch", "blob", "disc", "height_field", "isosurface", "julia_fractal", "lathe", "mesh", "mesh2",
        "object", "ovus", "parametric", "polygon", "polynomial", "prism", "smooth_triangle", "sor", "sphere_sweep",
        "superellipsoid"};
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
          readSurfaceItem(*it.node, s, default_, refusals_);
          if (!textureFrom) textureFrom = o.transforms.size();
        } else {
          refuse(it.loc, m);
        }
      } else if (it.kind == Item::Kind::Keyword) {
        if (it.word == "hollow") {
          valueAfter(n, i);
        } else if (it.word == "no_shadow") {
          o.noShadow = true;
        } else if (it.word == "sturm") {
          const Value* v = valueAfter(n, i);
          sturm(o.shape, !v || v->v[0] != 0);
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
    for (size_t l = firstLight; l < scene_.lights.size(); ++l) moveLight(scene_.lights[l], m);
    return true;
  }

  // POV-Ray's `sturm [on]`: the Sturm-sequence root finder for a torus or a polynomial shape; other shapes
  // take it and have no use for it.
  static void sturm(ShapeDesc& shape, bool on) {
    if (auto* torus = std::get_if<TorusDesc>(&shape)) torus->sturm = on;
    if (auto* poly = std::get_if<PolyDesc>(&shape)) poly->sturm = on;
  }

  // The object's material, and its texture when its colour varies over it, moved by the transforms `after`.
  void surface(ObjectDesc& o, const Surface& s, const std::vector<TransformStep>& after) {
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

  // A camera statement's items as written (an identifier's first), before POV-Ray's rules combine them.
  struct PovCamera {
    glm::dvec3 location{0}, direction{0, 0, 1}, up{0, 1, 0}, right{1.33, 0, 0}, sky{0, 1, 0};
    std::optional<glm::dvec3> lookAt;
    std::optional<double> angle;
    bool orthographic = false, angleGiven = false, sizeGiven = false;
    std::vector<TransformStep> steps;
  };

  // POV-Ray's camera: defaults, then angle sets the direction's length, look_at turns direction, right and up
  // about the sky keeping their lengths and the handedness of right, then the transforms. An orthographic
  // camera's right and up are the picture's size: as written, or with `angle` or without either of them the
  // size a perspective camera shows at the look_at point.
  void camera(const Node& n) {
    PovCamera k;
    collectCamera(n, k);
    glm::dvec3 direction = k.direction, right = k.right, up = k.up;
    if (k.angle) {
      direction = glm::normalize(direction) * (0.5 * glm::length(right) / std::tan(glm::radians(*k.angle) / 2));
    }
    if (k.lookAt) {
      const double handedness = glm::dot(glm::cross(up, direction), right);
      direction = glm::normalize(*k.lookAt - k.location) * glm::length(direction);
      // Looking along the sky, right keeps its direction, and up follows from it.
      const glm::dvec3 side = glm::cross(k.sky, direction);
      right = glm::normalize(glm::length(side) > 1e-12 * glm::length(direction) ? side : right) * glm::length(right);
      up = glm::normalize(glm::cross(direction, right)) * glm::length(up);
      if (handedness < 0) right = -right;
    }
    // What right and up are divided by: the direction's length for a perspective camera, which makes them the
    // picture's size at unit distance; for an orthographic one, 1 or the look_at point's distance in units
    // of the direction's length.
    double size = 1;
    if (k.orthographic && (k.angleGiven || !k.sizeGiven)) {
      size = glm::length(direction) / (k.lookAt ? glm::length(*k.lookAt - k.location) : glm::length(direction));
    }
    const glm::dmat4 m = composeTransforms<double>(k.steps);
    const glm::dvec3 location = glm::dvec3(m * glm::dvec4(k.location, 1));
    direction = glm::dvec3(m * glm::dvec4(direction, 0));
    if (!k.orthographic) size = glm::length(direction);
    CameraDesc& c = scene_.camera;
    c.location = location;
    c.lookAt = location + glm::normalize(direction);
    c.right = glm::dvec3(m * glm::dvec4(right, 0)) / size;
    c.up = glm::dvec3(m * glm::dvec4(up, 0)) / size;
    c.orthographic = k.orthographic;
    c.loc = n.loc;
  }

  void collectCamera(const Node& n, PovCamera& k) {
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (it.kind == Item::Kind::Node && it.node->keyword == "camera") {
        collectCamera(*it.node, k);
        continue;
      }
      if (transformItem(n, i, k.steps)) continue;
      if (it.kind != Item::Kind::Keyword) {
        refusals_.refuse(it, "camera");
        continue;
      }
      const std::string_view w = it.word;
      if (w == "perspective" || w == "orthographic") {
        k.orthographic = w == "orthographic";
        continue;
      }
      const Value* v = valueAfter(n, i);
      if (w == "angle") k.angleGiven = true;
      if (!v && w == "angle" && k.orthographic) continue;  // the angle is optional there
      if (!v) {
        refuse(it.loc, w);
        continue;
      }
      if (!v->numeric()) throw ParseError(n.items[i].loc, "expected a vector after '" + std::string(w) + "', found a " + typeName(*v));
      if (w == "location") k.location = vec3(*v);
      else if (w == "direction") k.direction = vec3(*v);
      else if (w == "up") k.up = vec3(*v), k.sizeGiven = true;
      else if (w == "right") k.right = vec3(*v), k.sizeGiven = true;
      else if (w == "sky") k.sky = vec3(*v);
      else if (w == "look_at") k.lookAt = vec3(*v);
      else if (w == "angle") k.angle = v->v[0];
      else refuse(it.loc, w);
    }
  }

  void light(const Node& n) {
    LightDesc l;
    readLight(n, l);
    scene_.lights.push_back(l);
  }

  // A light's items into `l`, moved by its transforms: an identifier's first, then the ones that follow it.
  void readLight(const Node& n, LightDesc& l) {
    size_t i = 0;
    if (i < n.items.size() && n.items[i].kind == Item::Kind::Node && n.items[i].node->keyword == "light_source") {
      readLight(*n.items[i++].node, l);
    }
    if (i < n.items.size() && n.items[i].kind == Item::Kind::Value) l.position = vec3(n.items[i++].value);
    if (i < n.items.size() && n.items[i].kind == Item::Kind::Value) l.color = colourOf(n.items[i++].value).rgb;
    std::vector<TransformStep> steps;
    // The cone's values may come before `spotlight`, and mean nothing to a light that is not one.
    bool isSpot = l.spot.has_value();
    LightDesc::Spot spot = l.spot.value_or(LightDesc::Spot{});
    for (; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (transformItem(n, i, steps)) continue;
      if (it.kind != Item::Kind::Keyword) {
        refusals_.refuse(it, "light_source");
        continue;
      }
      const std::string_view w = it.word;
      if (w == "media_interaction" || w == "media_attenuation") {
        valueAfter(n, i);
      } else if (w == "shadowless") {
        l.shadowless = true;
      } else if (w == "spotlight") {
        isSpot = true;
      } else if (w == "point_at" || w == "radius" || w == "falloff" || w == "tightness" || w == "fade_distance" ||
                 w == "fade_power") {
        const Value* v = valueAfter(n, i);
        if (!v || !v->numeric()) throw ParseError(it.loc, "'" + std::string(w) + "' needs a value");
        if (w == "point_at") spot.pointAt = vec3(*v);
        else if (w == "radius") spot.radius = v->v[0];
        else if (w == "falloff") spot.falloff = v->v[0];
        else if (w == "tightness") spot.tightness = v->v[0];
        else if (w == "fade_distance") l.fadeDistance = v->v[0];
        else l.fadePower = v->v[0];
      } else {
        refuse(it.loc, w);
      }
    }
    if (isSpot) l.spot = spot;
    moveLight(l, composeTransforms<double>(steps));
  }

  static void moveLight(LightDesc& l, const glm::dmat4& m) {
    l.position = glm::dvec3(m * glm::dvec4(l.position, 1));
    if (l.spot) l.spot->pointAt = glm::dvec3(m * glm::dvec4(l.spot->pointAt, 1));
  }

  void skySphere(const Node& n) {
    auto sky = std::make_shared<SkySphere>(scene_.sky ? *scene_.sky : SkySphere{});
    std::vector<TransformStep> steps;
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (transformItem(n, i, steps)) continue;
      if (it.kind == Item::Kind::Node && it.node->keyword == "pigment") {
        sky->layers.push_back(nestedPigment(*it.node, refusals_));
      } else if (it.kind == Item::Kind::Node && it.node->keyword == "sky_sphere") {
        skySphere(*it.node);  // an identifier, modified by what follows
        sky = std::make_shared<SkySphere>(*scene_.sky);
      } else {
        refusals_.refuse(it, "sky_sphere");
      }
    }
    sky->fromWorld = sky->fromWorld * glm::inverse(composeTransforms<double>(steps));
    scene_.sky = sky;
  }

  void fog(const Node& n) {
    Fog f;
    std::vector<TransformStep> steps;
    readFog(n, f, steps);
    f.up = glm::normalize(glm::dvec3(composeTransforms<double>(steps) * glm::dvec4(f.up, 0)));
    scene_.fogs.push_back(f);
  }

  void readFog(const Node& n, Fog& f, std::vector<TransformStep>& steps) {
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (transformItem(n, i, steps)) continue;
      if (it.kind == Item::Kind::Node && it.node->keyword == "fog") {
        readFog(*it.node, f, steps);
        continue;
      }
      if (it.kind == Item::Kind::Value && it.value.numeric()) {
        f.colour = colourOf(it.value);
        continue;
      }
      const Value* v = it.kind == Item::Kind::Keyword ? valueAfter(n, i) : nullptr;
      if (!v || !v->numeric()) {
        refusals_.refuse(it, "fog");
      } else if (it.word == "fog_type" && (v->v[0] == 1 || v->v[0] == 2)) {
        f.type = Fog::Type(int(v->v[0]));
      } else if (it.word == "distance") {
        f.distance = v->v[0];
      } else if (it.word == "fog_offset") {
        f.offset = v->v[0];
      } else if (it.word == "fog_alt") {
        f.alt = v->v[0];
      } else if (it.word == "up") {
        f.up = vec3(*v);
      } else {
        refusals_.refuse(it, "fog");
      }
    }
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

// The texture with every layer's ambient term scaled, in the textures of its patterns too.
Texture ambientScaled(Texture t, const Color& light) {
  for (TextureLayer& layer : t.layers) {
    layer.finish.ambient *= light;
    if (!layer.pattern) continue;
    auto pattern = std::make_shared<TexturePattern>(*layer.pattern);
    for (auto& sub : pattern->textures) sub = std::make_shared<const Texture>(ambientScaled(*sub, light));
    layer.pattern = pattern;
  }
  return bounded(std::move(t));
}

// global_settings' ambient_light scales every ambient term, a CSG group's parts' too.
void scaleAmbient(ObjectDesc& o, const Color& light) {
  o.material.ambient *= light;
  if (o.texture) o.texture = std::make_shared<const Texture>(ambientScaled(*o.texture, light));
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
  scene.conventions.filteredShadows = true;
  InterpreterOptions io;
  io.libraryPaths = options.libraryPaths;
  io.imageWidth = options.imageWidth;
  io.imageHeight = options.imageHeight;
  io.debug = options.debugOutput ? &std::cerr : nullptr;
  io.maxTokens = options.maxTokens;
  io.writeFolder = options.writeFolder;
  io.writeAnywhere = options.writeAnywhere;
  io.clock = options.clock;
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
