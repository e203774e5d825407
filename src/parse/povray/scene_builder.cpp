#include "raytrace/parse/povray/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>

#include "raytrace/parse/povray/interpreter.hpp"
#include "raytrace/util/format.hpp"
#include "raytrace/util/limits.hpp"

namespace rt::povray {

namespace {

// A refusal of something POV-Ray has and raytrace cannot draw yet; parsing goes on, so that a real mistake
// later in the file is still reported as one.
struct Unsupported {
  SourceLoc loc;
  std::string what;
};

// A finish with POV-Ray 3.7's defaults.
struct PovFinish {
  Color ambient{0.1f};
  double diffuse = 0.6, phong = 0, phongSize = 40, specular = 0, roughness = 0.05, reflection = 0, ior = 1;
};

struct Surface {
  std::array<double, 5> colour{};  // POV-Ray's default pigment is black
  PovFinish finish;
};

glm::dvec3 vec3(const Value& v) {
  if (v.type == Value::Type::Float) return glm::dvec3(v.v[0]);
  return {v.v[0], v.size > 1 ? v.v[1] : 0, v.size > 2 ? v.v[2] : 0};
}

class Builder {
 public:
  explicit Builder(SceneDesc& scene) : scene_(scene) {}

  void statement(const Node& n) {
    const std::string_view k = n.keyword;
    if (k == "camera") {
      camera(n);
    } else if (k == "light_source") {
      light(n);
    } else if (k == "global_settings") {
      globalSettings(n);
    } else if (k == "background") {
      Surface s;
      for (const Item& i : n.items) {
        if (i.kind == Item::Kind::Value && i.value.numeric()) s.colour = colourOf(i.value);
      }
      scene_.conventions.background = Color(s.colour[0], s.colour[1], s.colour[2]);
    } else {
      ObjectDesc o;
      if (object(n, o)) add(std::move(o), n.loc);
    }
  }

  void defaults(const Node& n) {
    for (const Item& i : n.items) {
      if (i.kind != Item::Kind::Node) continue;
      surfaceItem(*i.node, default_);
    }
  }

  void finish() {
    if (unsupported_) throw ParseError(unsupported_->loc, "'" + unsupported_->what + "' is not supported yet");
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

  void refuse(const SourceLoc& loc, std::string_view what) {
    if (!unsupported_) unsupported_ = Unsupported{loc, std::string(what)};
  }

  static std::array<double, 5> colourOf(const Value& v) {
    std::array<double, 5> c{};
    if (v.type == Value::Type::Float) {
      c = {v.v[0], v.v[0], v.v[0], 0, 0};
    } else {
      for (int i = 0; i < v.size && i < 5; ++i) c[size_t(i)] = v.v[size_t(i)];
    }
    return c;
  }

  // Items after a keyword that take a value: the value, if the next item is one.
  static const Value* valueAfter(const Node& n, size_t& i) {
    if (i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Value) return &n.items[++i].value;
    return nullptr;
  }

  // The transforms of translate/rotate/scale/transform items, as steps; false for any other item.
  bool transformItem(const Node& n, size_t& i, std::vector<TransformStep>& steps) {
    const Item& it = n.items[i];
    if (it.kind == Item::Kind::Node && it.node->keyword == "transform") {
      transformBlock(*it.node, steps);
      return true;
    }
    if (it.kind != Item::Kind::Keyword) return false;
    const std::string_view w = it.word;
    if (w == "transform") {
      if (i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Node) transformBlock(*n.items[++i].node, steps);
      return true;
    }
    if (w != "translate" && w != "rotate" && w != "scale" && w != "matrix") return false;
    const Value* v = valueAfter(n, i);
    if (w == "matrix" || !v) {
      refuse(it.loc, w);
      return true;
    }
    glm::dvec3 a = vec3(*v);
    if (w == "translate") {
      steps.push_back({TransformStep::Kind::Translate, a});
    } else if (w == "scale") {
      for (int k = 0; k < 3; ++k) {
        if (a[k] == 0) a[k] = 1;  // as POV-Ray does, with a warning
      }
      steps.push_back({TransformStep::Kind::Scale, a});
    } else {
      // POV-Ray turns about x, then y, then z.
      if (a.x != 0) steps.push_back({TransformStep::Kind::Rotate, {a.x, 0, 0}});
      if (a.y != 0) steps.push_back({TransformStep::Kind::Rotate, {0, a.y, 0}});
      if (a.z != 0) steps.push_back({TransformStep::Kind::Rotate, {0, 0, a.z}});
    }
    return true;
  }

  void transformBlock(const Node& n, std::vector<TransformStep>& steps) {
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (it.kind == Item::Kind::Node && it.node->keyword == "transform") {
        transformBlock(*it.node, steps);
      } else if (!transformItem(n, i, steps)) {
        refuse(it.loc, it.kind == Item::Kind::Keyword ? it.word : std::string_view("transform"));
      }
    }
  }

  void pigment(const Node& n, Surface& s) {
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      std::vector<TransformStep> ignored;  // a solid colour looks the same however it is moved
      if (it.kind == Item::Kind::Value && it.value.numeric()) {
        s.colour = colourOf(it.value);
      } else if (it.kind == Item::Kind::Node && it.node->keyword == "pigment") {
        pigment(*it.node, s);
      } else if (transformItem(n, i, ignored)) {
      } else if (it.kind == Item::Kind::Keyword && (it.word == "quick_color" || it.word == "quick_colour")) {
        valueAfter(n, i);
      } else {
        refuse(it.loc, it.kind == Item::Kind::Node ? it.node->keyword : it.word);
      }
    }
  }

  void finishBlock(const Node& n, PovFinish& f) {
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (it.kind == Item::Kind::Node && it.node->keyword == "finish") {
        finishBlock(*it.node, f);
        continue;
      }
      if (it.kind == Item::Kind::Node && it.node->keyword == "reflection") {
        for (const Item& r : it.node->items) {
          if (r.kind == Item::Kind::Value && r.value.numeric()) f.reflection = colourOf(r.value)[0];
          else refuse(r.loc, r.kind == Item::Kind::Keyword ? r.word : r.node ? r.node->keyword : "reflection");
        }
        continue;
      }
      if (it.kind != Item::Kind::Keyword) {
        refuse(it.loc, it.kind == Item::Kind::Node ? it.node->keyword : "finish");
        continue;
      }
      const std::string_view w = it.word;
      if (w == "conserve_energy") continue;
      const Value* v = valueAfter(n, i);
      if (!v || !v->numeric()) {
        refuse(it.loc, w);
        continue;
      }
      const double x = v->v[0];
      if (w == "ambient") {
        const auto c = colourOf(*v);
        f.ambient = Color(c[0], c[1], c[2]);
      } else if (w == "diffuse") {
        f.diffuse = x;
      } else if (w == "phong") {
        f.phong = x;
      } else if (w == "phong_size") {
        f.phongSize = x;
      } else if (w == "specular") {
        f.specular = x;
      } else if (w == "roughness") {
        f.roughness = x;
      } else if (w == "reflection") {
        f.reflection = x;
      } else if (w == "brilliance" && x == 1) {
      } else {
        refuse(it.loc, w);
      }
    }
  }

  // pigment, finish, texture, material or interior, into a surface; other items are refused.
  void surfaceItem(const Node& n, Surface& s) {
    const std::string_view k = n.keyword;
    if (k == "pigment") {
      pigment(n, s);
    } else if (k == "finish") {
      finishBlock(n, s.finish);
    } else if (k == "texture" || k == "material") {
      std::vector<TransformStep> ignored;
      for (size_t i = 0; i < n.items.size(); ++i) {
        const Item& it = n.items[i];
        if (it.kind == Item::Kind::Node) {
          surfaceItem(*it.node, s);
        } else if (!transformItem(n, i, ignored)) {
          refuse(it.loc, it.kind == Item::Kind::Keyword ? it.word : k);
        }
      }
    } else if (k == "interior") {
      for (size_t i = 0; i < n.items.size(); ++i) {
        const Item& it = n.items[i];
        const Value* v = it.kind == Item::Kind::Keyword && it.word == "ior" ? valueAfter(n, i) : nullptr;
        if (v && v->type == Value::Type::Float) {
          s.finish.ior = v->v[0];
        } else if (it.kind == Item::Kind::Node && it.node->keyword == "interior") {
          surfaceItem(*it.node, s);
        } else {
          refuse(it.loc, it.kind == Item::Kind::Keyword ? it.word : it.node ? it.node->keyword : "interior");
        }
      }
    } else {
      refuse(n.loc, k);
    }
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
        "superellipsoid", "text"};
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
    bool textured = false;
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
        if (m == "texture" && textured) refuse(it.loc, "layered texture");
        textured = textured || m == "texture";
        if (m == "pigment" || m == "finish" || m == "texture" || m == "material" || m == "interior") {
          surfaceItem(*it.node, s);
          o.textured = true;
        } else {
          refuse(it.loc, m);
        }
      } else if (it.kind == Item::Kind::Keyword) {
        if (it.word == "hollow") {
          valueAfter(n, i);
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
    material(o, s);
    passTextureDown(o);
    const glm::dmat4 m = composeTransforms<double>(std::vector(o.transforms.begin() + long(ownTransforms), o.transforms.end()));
    for (size_t l = firstLight; l < scene_.lights.size(); ++l) {
      scene_.lights[l].position = glm::dvec3(m * glm::dvec4(scene_.lights[l].position, 1));
    }
    return true;
  }

  // POV-Ray's `sturm [on]`: the Sturm-sequence root finder for a torus or a polynomial shape; other shapes
  // take it and have no use for it.
  static void sturm(ShapeDesc& shape, bool on) {
    if (auto* torus = std::get_if<TorusDesc>(&shape)) torus->sturm = on;
    if (auto* poly = std::get_if<PolyDesc>(&shape)) poly->sturm = on;
  }

  void material(ObjectDesc& o, const Surface& s) {
    const PovFinish& f = s.finish;
    if (s.colour[4] > 0) refuse(o.loc, "transmit");
    o.finish.ambient = (f.ambient.r + f.ambient.g + f.ambient.b) / 3;
    o.finish.diffuse = f.diffuse;
    o.finish.specular = f.specular > 0 ? f.specular : f.phong;
    o.finish.roughness = f.roughness;
    o.finish.reflection = f.reflection;
    o.finish.ior = f.ior;
    Material& m = o.material;
    m.pigment = Color(s.colour[0], s.colour[1], s.colour[2]);
    m.filter = float(s.colour[3]);
    m.ambient = f.ambient * m.pigment;
    m.diffuse = float(f.diffuse) * m.pigment;
    // POV-Ray's highlights are white; `specular` has exponent 1/roughness, `phong` its phong_size.
    m.specular = Color(float(o.finish.specular));
    m.exponent = float(f.specular > 0 ? 1 / f.roughness : f.phongSize);
    m.roughness = float(f.roughness);
    m.reflection = float(f.reflection);
    m.ior = float(f.ior);
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
      const auto c = colourOf(n.items[i++].value);
      l.color = Color(c[0], c[1], c[2]);
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
          ++i;
          continue;
        }
        const Value* v = valueAfter(n, i);
        if (w == "max_trace_level" && v && v->type == Value::Type::Float) {
          scene_.conventions.maxDepth = int(std::max(1.0, v->v[0]));
        } else if (w == "ambient_light" && v && v->numeric()) {
          const auto c = colourOf(*v);
          ambientLight_ = Color(c[0], c[1], c[2]);
        } else if (w == "assumed_gamma" || w == "adc_bailout" || w == "number_of_waves" || w == "noise_generator" ||
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

 private:
  SceneDesc& scene_;
  Surface default_;
  std::optional<Unsupported> unsupported_;
};

// global_settings' ambient_light scales every ambient term, a CSG group's parts' too.
void scaleAmbient(ObjectDesc& o, const Color& light) {
  o.material.ambient *= light;
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
  Interpreter interpreter(io);
  for (const std::string& d : options.declares) {
    const size_t eq = d.find('=');
    interpreter.declare(d.substr(0, eq), eq == std::string::npos ? "1" : d.substr(eq + 1));
  }
  Builder builder(scene);
  interpreter.run(path, text, [&](const std::shared_ptr<const Node>& n) { builder.statement(*n); },
                  [&](const std::shared_ptr<const Node>& n) { builder.defaults(*n); });
  builder.finish();
  for (ObjectDesc& o : scene.objects) scaleAmbient(o, builder.ambientLight_);
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
