#include "raytrace/parse/povray/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "raytrace/parse/povray/interpreter.hpp"
#include "raytrace/parse/povray/light_reader.hpp"
#include "raytrace/parse/povray/radiosity_reader.hpp"
#include "raytrace/parse/povray/surface_reader.hpp"
#include "raytrace/shapes/make_object.hpp"
#include "raytrace/util/format.hpp"
#include "raytrace/util/limits.hpp"

namespace rt::povray {

namespace {

template <class K, class = void> struct HasSturm : std::false_type {};
template <class K> struct HasSturm<K, std::void_t<decltype(std::declval<K&>().sturm)>> : std::true_type {};
template <class K, class = void> struct HasOpen : std::false_type {};
template <class K> struct HasOpen<K, std::void_t<decltype(std::declval<K&>().open)>> : std::true_type {};

// The scene's object list grows fourfold from this many objects on (Builder::add).
constexpr size_t kFourfoldFrom = 4096;

class Builder {
 public:
  Builder(SceneDesc& scene, Interpreter& interpreter) : scene_(scene), interpreter_(interpreter) {
    context_.findFile = [this](const std::string& name) { return interpreter_.findFile(name); };
    context_.imageGamma = [this]() -> std::optional<double> {
      if (interpreter_.version() < 3.7) return std::nullopt;
      return assumedGamma_.value_or(1.0);
    };
  }

  void statement(const std::shared_ptr<const Node>& n) {
    statementNode_ = n;
    statement(*n);
    statementNode_.reset();  // the interpreter reuses the tree's nodes that no one else holds
  }

  void statement(const Node& n) {
    const std::string_view k = n.keyword;
    if (k == "camera") {
      camera(n);
    } else if (k == "light_source") {
      light(n);
    } else if (k == "global_settings") {
      globalSettings(n);
    } else if (k == "default") {
      defaults(n);  // the `default { … }` of POV-Ray before 3.0, which 3.7 still reads
    } else if (k == "sky_sphere") {
      skySphere(n);
    } else if (k == "fog") {
      fog(n);
    } else if (k == "media") {
      if (std::optional<Media> media = readMedia(n, context_)) scene_.media.push_back(std::move(*media));
    } else if (k == "background") {
      for (const Item& i : n.items) {
        if (i.kind == Item::Kind::Value && i.value.numeric()) scene_.background = colourOf(i.value).rgb;
      }
    } else {
      ObjectDesc o;
      if (object(n, o)) add(std::move(o), n.loc);
      for (ObjectDesc& look : looksInside_) {
        const SourceLoc at = look.loc;
        add(std::move(look), at);
      }
      looksInside_.clear();
    }
  }

  // An object's surface: the #default one until an item changes it, copied then. A lone colour, `pigment {
  // rgb … }`, over a #default surface whose pigment has no pattern is kept aside (`solid`) without a copy: a
  // loop's million spheres copy no surface.
  struct ObjectSurface {
    const Surface& base;
    std::optional<Surface> own;
    std::optional<Rgbft> solid;  // what readSurfaceItem makes of such a pigment, written into `own` when made
    Surface& get() {
      if (!own) {
        own = base;
        if (solid) {
          Pigment& p = own->layers.back().pigment;
          p = Pigment{};
          p.solid = *solid;
        }
      }
      return *own;
    }
  };

  // The world bounding box of an object, as min_extent and max_extent give it.
  std::optional<std::array<double, 6>> extent(const std::shared_ptr<const Node>& n) {
    const std::optional<Aabb<double>> box = runtimeObject(n).bounds();
    if (!box) return std::nullopt;
    return std::array<double, 6>{box->min.x, box->min.y, box->min.z, box->max.x, box->max.y, box->max.z};
  }

  // trace(): the first point where a ray meets an object, and the outward normal there.
  std::optional<std::array<InterpreterOptions::Vec, 2>> trace(const std::shared_ptr<const Node>& n,
                                                             const InterpreterOptions::Vec& start,
                                                             const InterpreterOptions::Vec& dir) {
    const Ray<double> ray{{start[0], start[1], start[2]}, {dir[0], dir[1], dir[2]}};
    if (ray.dir == glm::dvec3(0)) return std::nullopt;
    const std::optional<Hit<double>> hit =
        runtimeObject(n).intersect(ray, {0, std::numeric_limits<double>::infinity()});
    if (!hit) return std::nullopt;
    const glm::dvec3 p = hit->point, normal = hit->normal;
    return std::array<InterpreterOptions::Vec, 2>{{{p.x, p.y, p.z}, {normal.x, normal.y, normal.z}}};
  }

  // The pigment a function reads, with the scene's settings; null, with why in `into`, if it is refused.
  template <class Read>
  std::shared_ptr<const Pigment> functionPigment(const Node& n, FunctionValue& into, Read read) {
    ReadingContext own = context_;
    own.firstRefusal.reset();
    const std::shared_ptr<const Pigment> p = read(n, own);
    if (!own.firstRefusal) return p;
    into.why = own.firstRefusal->what;
    into.whyAt = own.firstRefusal->loc;
    return nullptr;
  }

  // A function has no surface, and so no normal for a slope pattern to read: refused.
  static bool refusedSlope(const Pigment& p, const Node& n, FunctionValue& into) {
    if (!readsNormal(p)) return false;
    into.why = "slope in a function";
    into.whyAt = n.loc;
    return true;
  }

  // A pattern function's compiled form: the pattern's value at (x, y, z), read with the scene's noise generator.
  void patternFunction(const Node& pattern, FunctionValue& into) {
    const std::shared_ptr<const Pigment> p = functionPigment(pattern, into, patternPigment);
    if (!p || refusedSlope(*p, pattern, into)) return;
    using Op = Function::Op;
    into.compiled = std::make_shared<Function>(
        std::vector<Function::Instr>{{Op::Param, 0}, {Op::Param, 1}, {Op::Param, 2}, {Op::Pattern, 0, 0, nullptr, p}}, 3, 3);
  }

  // A pigment function's pigment, read with the scene's noise generator.
  void pigmentFunction(const Node& pigment, FunctionValue& into) {
    const std::shared_ptr<const Pigment> p = functionPigment(pigment, into, nestedPigment);
    if (!p || refusedSlope(*p, pigment, into)) return;
    into.pigment = p;
  }

  // A transform function's matrix, in `matrix`'s 12 numbers.
  void transformFunction(const Node& transform, FunctionValue& into) {
    ReadingContext own = context_;
    own.firstRefusal.reset();
    std::vector<TransformStep> steps;
    readTransformBlock(transform, steps, own);
    if (own.firstRefusal) {
      into.why = own.firstRefusal->what;
      into.whyAt = own.firstRefusal->loc;
      return;
    }
    const glm::dmat4 m = composeTransforms<double>(steps);
    auto rows = std::make_shared<std::array<double, 12>>();
    for (size_t i = 0; i < 4; ++i) {
      for (size_t j = 0; j < 3; ++j) (*rows)[i * 3 + j] = m[int(i)][int(j)];
    }
    into.transform = std::move(rows);
  }

  // The runtime object of a declared object, made once: scenes call trace() in loops. Its light sources are
  // not part of the scene, and a refused part is reported once the file is read.
  const Object<double>& runtimeObject(const std::shared_ptr<const Node>& n) {
    auto& made = asked_[n.get()];
    if (!made.object) {
      made.node = n;
      const auto statement = std::exchange(statementNode_, n);
      const size_t lights = scene_.lights.size();
      ObjectDesc o;
      // What follows would build on a wrong answer: a refusal is reported now.
      if (!object(*n, o) || context_.firstRefusal) finish();
      scene_.lights.resize(lights);
      statementNode_ = statement;
      made.object = makeObject<double>(o, SphereMethod::Robust, 0, false);
    }
    return *made.object;
  }

  void defaults(const Node& n) {
    defaultTerms_.reset();
    for (const Item& i : n.items) {
      if (i.kind != Item::Kind::Node) continue;
      readSurfaceItem(*i.node, default_, default_, context_);
    }
  }

  void finish() {
    if (const auto& refused = context_.firstRefusal) throw ParseError(refused->loc, "'" + refused->what + "' is not supported yet");
  }

 private:
  // A union's children go into the scene one by one, under the union's transforms: the same surfaces, and the
  // hierarchy bounds each of them (POV-Ray's split_union). An inverted or clipped union stays whole.
  void add(ObjectDesc&& o, const SourceLoc& at) {
    if (auto* csg = std::get_if<CsgDesc>(&o.shape); csg && csg->op == CsgOp::Union && !o.inverse && o.clip.empty()) {
      for (ObjectDesc& child : csg->children) {
        child.transforms.insert(child.transforms.end(), o.transforms.begin(), o.transforms.end());
        child.noShadow = child.noShadow || o.noShadow;
        child.noImage = child.noImage || o.noImage;
        child.noReflection = child.noReflection || o.noReflection;
        child.noRadiosity = child.noRadiosity || o.noRadiosity;
        if (!child.hollow) child.hollow = o.hollow;
        add(std::move(child), at);
      }
      return;
    }
    markInterior(o, false, 0);
    static const std::string kWhat = "the scene";  // made once, not for every object
    const std::string shortage = objectMemoryShortage(scene_.objects.size(), scene_.objects.size() + 1, kWhat);
    if (!shortage.empty()) throw ParseError(at, shortage);
    // A long list grows four times over rather than twice: each growth moves every object into fresh pages,
    // while the room not yet filled is never touched. A million objects are then moved a third of a time
    // each, not once, and their pages met 1.3 times rather than twice.
    std::vector<ObjectDesc>& list = scene_.objects;
    if (list.size() == list.capacity() && list.size() >= kFourfoldFrom) list.reserve(list.size() * 4);
    list.push_back(std::move(o));
    const ObjectDesc& added = list.back();
    plainOnly_ = plainOnly_ && !added.texture && !std::holds_alternative<CsgDesc>(added.shape) &&
                 !std::holds_alternative<MeshDesc>(added.shape);
  }

  // The material's `hollow` (SurfaceExtras), on a CSG's parts too unless they say otherwise, as POV-Ray's
  // manual has it ("Empty and Solid Objects"), and the interior a CSG's parts share (`group`, numbered here).
  // The extras made are shared (marked_).
  void markInterior(ObjectDesc& o, bool outer, size_t group) {
    const bool hollow = o.hollow.value_or(outer);
    if (group == 0 && std::holds_alternative<CsgDesc>(o.shape)) group = ++groups_;
    if (hollow != o.material.extras->hollow || group != o.material.extras->interior) {
      const SurfaceExtras*& made = marked_[{o.material.extras, hollow, group}];
      if (!made) {
        SurfaceExtras extras = *o.material.extras;
        extras.hollow = hollow;
        extras.interior = group;
        made = keptExtras(extras);
      }
      o.material.extras = made;
    }
    if (auto* csg = std::get_if<CsgDesc>(&o.shape)) {
      for (ObjectDesc& child : csg->children) markInterior(child, hollow, group);
    }
  }

  void refuse(const SourceLoc& loc, std::string_view what) { context_.refuse(loc, what); }
  // An item a block inside an object does not take, `where` it is ("'pigment in a blob's sphere' is not
  // supported yet").
  void refuseItem(const Item& it, const std::string& where) {
    const std::string in = " in " + where;
    if (it.kind == Item::Kind::Node) refuse(it.loc, std::string(it.node->keyword) + in);
    else if (it.kind == Item::Kind::Keyword) refuse(it.loc, std::string(it.word) + in);
    else refuse(it.loc, "a value" + in);
  }
  bool transformItem(const Node& n, size_t& i, std::vector<TransformStep>& steps) {
    return readTransform(n, i, steps, context_);
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
    bool moreNumbers() const {
      return i_ < n_.items.size() && n_.items[i_].kind == Item::Kind::Value && n_.items[i_].value.type == Value::Type::Float;
    }
    bool keyword(std::string_view word) {
      if (i_ >= n_.items.size() || n_.items[i_].kind != Item::Kind::Keyword || n_.items[i_].word != word) return false;
      ++i_;
      return true;
    }
    std::string string(const char* what) {
      const Item& it = take(what);
      if (it.value.type != Value::Type::String) throw ParseError(it.loc, std::string("expected a string for ") + what + ", found a " + typeName(it.value));
      // POV-Ray's default charset, ascii, turns every byte past 127 into a blank; utf8 and sys keep them.
      std::string s = it.value.str();
      if (b_.asciiStrings_) std::replace_if(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) > 127; }, ' ');
      return s;
    }
    std::string findFont(const std::string& name) const { return b_.interpreter_.findFont(name); }
    std::string findFile(const std::string& name) const { return b_.interpreter_.findFile(name); }
    bool functionNext() const {
      return i_ < n_.items.size() && n_.items[i_].kind == Item::Kind::Value && n_.items[i_].value.type == Value::Type::Function;
    }
    // A mesh triangle's texture, in the mesh's space (moveTextures() moves it with the mesh).
    bool texture(FaceSurface& out, const void*& source) {
      if (i_ >= n_.items.size() || n_.items[i_].kind != Item::Kind::Node || n_.items[i_].node->keyword != "texture") return false;
      const Node& t = *n_.items[i_++].node;
      // `texture { T }` holds T's own tree: two triangles naming T share one surface.
      source = t.items.size() == 1 && t.items[0].kind == Item::Kind::Node ? static_cast<const void*>(t.items[0].node.get()) : &t;
      Surface s = b_.default_;
      readSurfaceItem(t, s, b_.default_, b_.context_);
      out.material = constantMaterial(s);
      out.texture = s.patterned() ? std::make_shared<const Texture>(bounded(makeTexture(s, {}))) : nullptr;
      return true;
    }
    // `word { … }` next: read(reader) reads its items; what it leaves is refused.
    template <class F> bool block(std::string_view word, F&& read) {
      if (i_ >= n_.items.size() || n_.items[i_].kind != Item::Kind::Node || n_.items[i_].node->keyword != word) return false;
      const Node& inner = *n_.items[i_++].node;
      size_t j = 0;
      ItemReader sub(b_, inner, j);
      read(sub);
      for (; j < inner.items.size(); ++j) b_.refuseItem(inner.items[j], "a " + std::string(n_.keyword) + "'s " + std::string(word));
      return true;
    }
    // A `function { … }` next: true, with `into` its compiled form, or null (and refused) if it did not compile.
    bool function(std::shared_ptr<const Function>& into) {
      if (i_ >= n_.items.size() || n_.items[i_].kind != Item::Kind::Value || n_.items[i_].value.type != Value::Type::Function) {
        return false;
      }
      const auto& f = static_cast<const FunctionValue&>(*n_.items[i_++].value.ref);
      into = f.compiled;
      if (!into) b_.refuse(f.whyAt, f.why);
      return true;
    }
    // `function W, H { … }` next (a height field's): its size, and its value at (x, y, 0), a pigment function's
    // grey (manual, "Height Field"; POV-Ray's heights of a pigment function are its grey); null, and refused,
    // if it did not compile.
    bool imageFunction(std::shared_ptr<const Function>& into, double& width, double& height) {
      if (!functionNext()) return false;
      const auto& f = static_cast<const FunctionValue&>(*n_.items[i_++].value.ref);
      width = f.width;
      height = f.height;
      into = f.compiled;
      if (f.colour && f.pigment) {
        using Op = Function::Op;
        into = std::make_shared<Function>(std::vector<Function::Instr>{{Op::Param, 0}, {Op::Param, 1}, {Op::Param, 2},
                                                                        {Op::Colour, Function::Gray, 0, nullptr, f.pigment}},
                                          3, 3);
      }
      if (!into) b_.refuse(f.whyAt, f.why);
      return true;
    }
    std::vector<TransformStep> transforms() {
      std::vector<TransformStep> steps;
      while (i_ < n_.items.size() && b_.transformItem(n_, i_, steps)) ++i_;
      return steps;
    }
    SourceLoc here() const { return i_ < n_.items.size() ? n_.items[i_].loc : n_.loc; }
    bool valueNext() const { return i_ < n_.items.size() && n_.items[i_].kind == Item::Kind::Value; }
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
        "light_group", "object", "ovus", "parametric", "polynomial"};
    if (it.kind != Item::Kind::Node) return false;
    const std::string_view k = it.node->keyword;
    return isShapeKeyword(k) || std::find(std::begin(kPovObjects), std::end(kPovObjects), k) != std::end(kPovObjects);
  }

  // A light source inside an object (POV-Ray moves it with the object): added to the scene here, and moved by
  // the object's transforms once they are known (object()).
  bool lightHere(const Item& it) {
    if (it.kind != Item::Kind::Node || it.node->keyword != "light_source") return false;
    nestedLight_ = true;
    light(*it.node);
    nestedLight_ = false;
    return true;
  }

  // One object into `o`, and its surface into `s`; false when it cannot be drawn (and is refused).
  bool object(const Node& n, ObjectDesc& o) {
    ObjectSurface s{default_, std::nullopt, std::nullopt};
    return object(n, o, s);
  }

  // Whether `block` is a lone colour that `s` can keep aside (ObjectSurface), which it then does.
  static bool lonePigmentColour(const Node& block, ObjectSurface& s) {
    if (s.own || block.keyword != "pigment" || block.items.size() != 1 || s.base.layers.back().pigment.pattern) return false;
    const Item& it = block.items[0];
    if (it.kind != Item::Kind::Value || !it.value.numeric()) return false;
    s.solid = colourOf(it.value);
    return true;
  }

  bool object(const Node& n, ObjectDesc& o, ObjectSurface& s) {
    const std::string_view k = n.keyword;
    const size_t firstLight = scene_.lights.size(), firstLook = looksInside_.size();
    size_t i = 0;
    // `mesh { Name … }` is the declared mesh under what follows, as `object { Name … }` is.
    const bool namedMesh = (k == "mesh" || k == "mesh2") && !n.items.empty() && n.items[0].kind == Item::Kind::Node &&
                           (n.items[0].node->keyword == "mesh" || n.items[0].node->keyword == "mesh2");
    if (k == "object" || namedMesh) {
      if (i >= n.items.size() || n.items[i].kind != Item::Kind::Node) throw ParseError(n.loc, "'object' needs an object identifier");
      if (k == "object" && lightHere(n.items[i])) {
        // `object { ALight … }`: the light, moved by what follows as a union of lights alone moves its own.
        ++i;
        o.shape = CsgDesc{};
        o.loc = n.loc;
      } else if (!object(*n.items[i++].node, o, s)) {
        return false;
      }
    } else {
      ItemReader reader(*this, n, i);
      // A union of light sources alone, which POV-Ray allows to move them together.
      const bool lightsAlone = k == "union" && std::none_of(n.items.begin(), n.items.end(), isObject);
      std::optional<ShapeDesc> shape;
      // A mesh read before (`object { MyMesh }` again) is the same triangles, shared (shapes/triangle_mesh).
      if (const auto read = meshesRead_.empty() ? meshesRead_.end() : meshesRead_.find(&n); read != meshesRead_.end()) {
        shape = read->second.first;
        i = read->second.second;
      } else {
        shape = lightsAlone ? ShapeDesc(CsgDesc{}) : readShape(k, reader);
        if (shape && std::holds_alternative<MeshDesc>(*shape)) {
          meshesRead_.emplace(&n, std::make_pair(*shape, i));
          // The statement holds the node: its address names no other node while the map has it.
          if (heldNodes_.empty() || heldNodes_.back() != statementNode_) heldNodes_.push_back(statementNode_);
        }
      }
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
    std::vector<ClipDesc> bound;  // bounded_by's objects
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
        if (m == "clipped_by" || m == "bounded_by") {
          std::vector<ClipDesc>& into = m == "clipped_by" ? o.clip : bound;
          for (const Item& c : it.node->items) {
            if (c.kind == Item::Kind::Node && isObject(c)) {
              ObjectDesc clip;
              if (object(*c.node, clip)) into.push_back({std::move(clip), o.transforms.size()});
            } else if (c.kind == Item::Kind::Keyword && c.word == "bounded_by" && m == "clipped_by") {
              o.clip.insert(o.clip.end(), bound.begin(), bound.end());
            } else if (!(c.kind == Item::Kind::Keyword && c.word == "clipped_by" && m == "bounded_by")) {
              refuseItem(c, std::string(m));
            }
          }
          continue;
        }
        if (m == "photons" || m == "radiosity") continue;
        if (m == "pigment" || m == "finish" || m == "normal" || m == "texture" || m == "material" ||
            m == "interior" || m == "layered texture") {
          // A second texture block is a layer on top of the first, starting as the #default texture.
          if (m == "texture" && textureBlock) s.get().layers.push_back(default_.layers.back());
          textureBlock = textureBlock || m == "texture";
          if (!lonePigmentColour(*it.node, s)) readSurfaceItem(*it.node, s.get(), default_, context_);
          if (!textureFrom) textureFrom = o.transforms.size();
        } else if (m == "interior_texture") {
          // Read as a texture block of its own, starting as the #default texture.
          Node body = *it.node;
          body.keyword = "texture";
          Surface inside = default_;
          readSurfaceItem(body, inside, default_, context_);
          s.get().inside = std::make_shared<const Surface>(std::move(inside));
          if (!textureFrom) textureFrom = o.transforms.size();
        } else {
          refuse(it.loc, m);
        }
      } else if (it.kind == Item::Kind::Keyword) {
        if (it.word == "hollow") {
          const Value* v = valueAfter(n, i);
          o.hollow = !v || v->v[0] != 0;
        } else if (it.word == "hierarchy") {
          valueAfter(n, i);
        } else if (it.word == "inverse") {
          o.inverse = !o.inverse;
        } else if (it.word == "no_shadow") {
          o.noShadow = true;
        } else if (it.word == "uv_mapping") {
          s.get().uvMapped = true;
        } else if (it.word == "no_image") {
          o.noImage = true;
        } else if (it.word == "no_reflection") {
          o.noReflection = true;
        } else if (it.word == "no_radiosity") {
          o.noRadiosity = true;
        } else if (it.word == "double_illuminate") {
          const Value* v = valueAfter(n, i);
          s.get().doubleIlluminate = !v || v->v[0] != 0;
        } else if (it.word == "open" && open(o.shape)) {  // set on the kinds that have ends to leave off
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
    // POV-Ray's pictures of unbounded shapes with a bounded_by (the quartics of scenes/objects/quartic) show
    // only what lies inside the bound: there it clips, unless the object has a clip of its own.
    if (o.clip.empty() && std::visit([](const auto& kind) { return kind.boundingBall().radius == 0; }, o.shape)) {
      o.clip = std::move(bound);
    }
    const std::vector<TransformStep> own(o.transforms.begin() + long(ownTransforms), o.transforms.end());
    // Only a texture already there, or a CSG's or a mesh's, moves: most objects take theirs just below, and
    // a million spheres need no matrix inverse each.
    if (o.texture || std::holds_alternative<CsgDesc>(o.shape) || std::holds_alternative<MeshDesc>(o.shape)) {
      moveTextures(o, glm::inverse(composeTransforms<double>(own)));
    }
    if (textureFrom || (k != "object" && !namedMesh)) surface(o, s, std::vector(o.transforms.begin() + long(textureFrom.value_or(o.transforms.size())), o.transforms.end()));
    if (textureFrom) o.textured = true;
    passTextureDown(o);
    refuseUvMapping(o, n.loc);
    if (scene_.lights.size() > firstLight) {
      const glm::dmat4 m = composeTransforms<double>(own);
      for (size_t l = firstLight; l < scene_.lights.size(); ++l) moveLight(scene_.lights[l], m);
      // Their looks_like objects move with them, objects of their own as at the top level.
      for (size_t l = firstLook; l < looksInside_.size(); ++l) {
        ObjectDesc& look = looksInside_[l];
        look.transforms.insert(look.transforms.end(), own.begin(), own.end());
        moveTextures(look, glm::inverse(m));
      }
    }
    return true;
  }

  // uv_mapping is drawn on the shapes made of triangles (their uv vectors), without a normal: any other is
  // refused where the object is written.
  void refuseUvMapping(const ObjectDesc& o, const SourceLoc& at) {
    const auto refused = [](const std::shared_ptr<const Texture>& t) { return t && t->uvMapped && t->bumpy; };
    if (const auto* csg = std::get_if<CsgDesc>(&o.shape)) {
      for (const ObjectDesc& child : csg->children) refuseUvMapping(child, at);
    } else if (const auto* mesh = std::get_if<MeshDesc>(&o.shape)) {
      if (refused(o.texture) || std::any_of(mesh->surfaces.begin(), mesh->surfaces.end(),
                                            [&](const FaceSurface& f) { return refused(f.texture); })) {
        refuse(at, "uv_mapping of a normal");
      }
    } else if (o.texture && o.texture->uvMapped) {
      refuse(at, "uv_mapping on a " + std::string(std::visit([](const auto& kind) { return kind.name(); }, o.shape)));
    }
  }

  // POV-Ray's `sturm [on]`: the Sturm-sequence root finder, for the kinds that have one (a `sturm` member);
  // the other shapes take it and have no use for it.
  static void sturm(ShapeDesc& shape, bool on) {
    std::visit(
        [on](auto& kind) {
          if constexpr (HasSturm<std::decay_t<decltype(kind)>>::value) kind.sturm = on;
        },
        shape);
  }

  // POV-Ray's `open` among an object's modifiers, for the kinds that have ends to leave off (an `open` member);
  // false for the others, which refuse it.
  static bool open(ShapeDesc& shape) {
    return std::visit(
        [](auto& kind) {
          if constexpr (HasOpen<std::decay_t<decltype(kind)>>::value) return kind.open = true;
          return false;
        },
        shape);
  }

  // The object's material, and its texture when its colour varies over it, moved by the transforms `after`.
  void surface(ObjectDesc& o, ObjectSurface& s, const std::vector<TransformStep>& after) {
    if (!defaultTerms_) defaultTerms_ = DefaultTerms{topTerms(default_), writtenFinish(default_), default_.patterned()};
    if (!s.own && !defaultTerms_->patterned) {
      // The #default surface, or it with a lone colour: its finish terms are the same for every object.
      o.material = layerMaterial(defaultTerms_->terms, s.solid.value_or(default_.layers.back().pigment.solid));
      o.finish = defaultTerms_->finish;
      o.texture = nullptr;
    } else {
      const Surface& full = s.get();
      o.material = constantMaterial(full);
      o.finish = writtenFinish(full);
      o.texture = full.patterned() ? std::make_shared<const Texture>(bounded(makeTexture(full, after))) : nullptr;
    }
    // The inverse only for a medium with densities to move: a million spheres need none.
    if (hasDensities(o.material)) moveMedia(o.material, glm::inverse(composeTransforms<double>(after)));
  }

  static bool hasDensities(const Material& m) {
    const std::vector<Media>& media = m.extras->media;
    return std::any_of(media.begin(), media.end(), [](const Media& one) { return !one.densities.empty(); });
  }

  // A medium's densities move with the object as a texture does; `undo` as in moveTextures.
  static void moveMedia(Material& m, const glm::dmat4& undo) {
    if (!hasDensities(m)) return;
    SurfaceExtras moved = *m.extras;
    for (Media& media : moved.media) media.fromWorld = media.fromWorld * undo;
    m.extras = keptExtras(moved);
  }

  // Textures made at a deeper level (a child's, or a declared object's) moved with this level's transforms:
  // `undo` takes this level's world back to the one they were made in.
  static void moveTextures(ObjectDesc& o, const glm::dmat4& undo) {
    moveMedia(o.material, undo);
    if (o.texture) o.texture = moved(*o.texture, undo);
    if (auto* csg = std::get_if<CsgDesc>(&o.shape)) {
      for (ObjectDesc& child : csg->children) moveTextures(child, undo);
    }
    if (auto* mesh = std::get_if<MeshDesc>(&o.shape)) {
      for (FaceSurface& face : mesh->surfaces) {
        if (face.texture) face.texture = moved(*face.texture, undo);
      }
    }
  }

  // The texture, and its interior one, with `undo` before its own map from world space.
  static std::shared_ptr<const Texture> moved(const Texture& texture, const glm::dmat4& undo) {
    auto t = std::make_shared<Texture>(texture);
    t->fromWorld = t->fromWorld * undo;
    if (t->interior) t->interior = moved(*t->interior, undo);
    return t;
  }

  // A camera statement's items as written (an identifier's first), before POV-Ray's rules combine them.
  struct PovCamera {
    glm::dvec3 location{0}, direction{0, 0, 1}, up{0, 1, 0}, right{1.33, 0, 0}, sky{0, 1, 0};
    std::optional<glm::dvec3> lookAt;
    std::optional<double> angle, verticalAngle;
    const ProjectionKind* projection = &perspectiveProjection();
    bool angleGiven = false, sizeGiven = false;
    std::vector<TransformStep> steps;
    CameraDesc::FocalBlur blur;
    std::shared_ptr<MeshCamera> mesh;
    std::shared_ptr<const Normal> normal;
  };

  // POV-Ray's camera: defaults, then angle sets the direction's length, look_at turns direction, right and up
  // about the sky keeping their lengths and the handedness of right, then the transforms. An orthographic
  // camera's right and up are the picture's size: as written, or with `angle` or without either of them the
  // size a perspective camera shows at the look_at point.
  void camera(const Node& n) {
    PovCamera k;
    collectCamera(n, k);
    glm::dvec3 direction = k.direction, right = k.right, up = k.up;
    if (k.angle && k.projection->planar) {
      direction = glm::normalize(direction) * (0.5 * glm::length(right) / std::tan(glm::radians(*k.angle) / 2));
    }
    if (k.lookAt) {
      const double handedness = glm::dot(glm::cross(up, direction), right);
      direction = glm::normalize(*k.lookAt - k.location) * glm::length(direction);
      // Looking along the sky, right keeps its direction, and up follows from it.
      const glm::dvec3 side = glm::cross(k.sky, direction);
      right = glm::normalize(glm::length(side) > 1e-12 * glm::length(direction) ? side : right) * glm::length(right);
      up = glm::normalize(glm::cross(direction, right)) * glm::length(up);
      if (handedness <= 0) right = -right;  // POV-Ray flips it when up and direction are parallel too
    }
    // What right and up are divided by: the direction's length for a perspective camera, which makes them the
    // picture's size at unit distance; for an orthographic one, 1 or the look_at point's distance in units
    // of the direction's length.
    const ProjectionKind* orthographic = projectionNamed("orthographic");
    double size = 1;
    if (k.projection == orthographic && (k.angleGiven || !k.sizeGiven)) {
      size = glm::length(direction) / (k.lookAt ? glm::length(*k.lookAt - k.location) : glm::length(direction));
    }
    const glm::dmat4 m = composeTransforms<double>(k.steps);
    const glm::dvec3 location = glm::dvec3(m * glm::dvec4(k.location, 1));
    direction = glm::dvec3(m * glm::dvec4(direction, 0));
    if (k.projection == &perspectiveProjection()) size = glm::length(direction);
    CameraDesc& c = scene_.camera;
    c.location = location;
    c.lookAt = location + glm::normalize(direction);
    c.right = glm::dvec3(m * glm::dvec4(right, 0)) / size;
    c.up = glm::dvec3(m * glm::dvec4(up, 0)) / size;
    c.projection = k.projection;
    c.directionLength = glm::length(direction);
    // The kind's default angle; spherical's vertical angle is half the angle unless given, the others' (ultra
    // wide angle's) follows up's length against right's.
    const bool spherical = k.projection == projectionNamed("spherical");
    c.angle = glm::radians(k.angle.value_or(k.projection->defaultAngle));
    c.verticalAngle = spherical ? glm::radians(k.verticalAngle.value_or(glm::degrees(c.angle) / 2))
                                : c.angle * glm::length(up) / glm::length(right);
    c.normal = k.normal;
    c.focalBlur = k.blur;
    c.focalBlur.focalPoint = glm::dvec3(m * glm::dvec4(k.blur.focalPoint, 1));
    c.loc = n.loc;
    if (k.mesh && k.normal) refuse(n.loc, "a mesh_camera's normal");
    if (k.mesh) {
      // A mesh camera reads only the z of the location and of the direction (manual, "Mesh projection").
      k.mesh->offset = k.location.z;
      k.mesh->reversed = k.direction.z < -1e-6;
      c.mesh = k.mesh;
    }
  }

  // `mesh_camera { rays distribution [max_distance] mesh { … } … [smooth] }`: the meshes' faces in world space.
  void meshCamera(const Node& n, PovCamera& k) {
    auto cam = std::make_shared<MeshCamera>();
    std::vector<double> numbers;
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (it.kind == Item::Kind::Value && it.value.type == Value::Type::Float) {
        numbers.push_back(it.value.v[0]);
        if (numbers.size() == 3 && numbers[2] > 1e-6) refuse(it.loc, "mesh_camera's max distance");
        if (numbers.size() > 3) throw ParseError(it.loc, "'mesh_camera' takes at most three numbers before its meshes");
      } else if (it.kind == Item::Kind::Keyword && it.word == "smooth") {
        cam->smooth = true;
      } else if (it.kind == Item::Kind::Node && (it.node->keyword == "mesh" || it.node->keyword == "mesh2")) {
        ObjectDesc o;
        if (!object(*it.node, o)) continue;
        const auto* mesh = std::get_if<MeshDesc>(&o.shape);
        if (!mesh) throw ParseError(it.loc, "a mesh_camera's 'mesh' must be a mesh or mesh2");
        cam->meshes.push_back(meshCameraFaces(*mesh->data, o.worldFromObject()));
      } else {
        refuseItem(it, "mesh_camera");
      }
    }
    if (numbers.size() < 2) throw ParseError(n.loc, "'mesh_camera' needs the rays per pixel and the distribution type");
    cam->raysPerPixel = int(numbers[0]);
    cam->distribution = int(numbers[1]);
    if (cam->raysPerPixel < 1) throw ParseError(n.loc, "a mesh_camera needs at least 1 ray per pixel");
    if (cam->distribution < 0 || cam->distribution > 3 || cam->distribution != numbers[1]) {
      throw ParseError(n.loc, "a mesh_camera's distribution type must be 0, 1, 2 or 3");
    }
    if (cam->meshes.empty()) throw ParseError(n.loc, "a mesh_camera needs a mesh");
    if (cam->distribution == 0 && cam->meshes.size() < size_t(cam->raysPerPixel)) {
      throw ParseError(n.loc, "a mesh_camera of distribution 0 needs a mesh for each ray per pixel");
    }
    if (cam->distribution >= 2 && cam->raysPerPixel != 1) {
      throw ParseError(n.loc, "a mesh_camera of distribution " + std::to_string(cam->distribution) +
                                  " takes 1 ray per pixel");
    }
    k.projection = projectionNamed("mesh_camera");
    k.mesh = std::move(cam);
  }

  // A mesh's faces under the matrix m: corners, corner normals (by the inverse transpose) and uv vectors.
  static std::vector<MeshCamera::Face> meshCameraFaces(const MeshData& data, const glm::dmat4& m) {
    const glm::dmat3 normals = glm::transpose(glm::inverse(glm::dmat3(m)));
    std::vector<MeshCamera::Face> faces;
    faces.reserve(data.faces.size());
    for (const MeshData::Face& f : data.faces) {
      MeshCamera::Face face{};
      for (size_t c = 0; c < 3; ++c) {
        face.corners[c] = glm::dvec3(m * glm::dvec4(data.vertices[f.v[c]], 1));
        if (f.n[c] >= 0) face.normals[c] = normals * data.normals[size_t(f.n[c])];
        if (f.uv[c] >= 0) face.uv[c] = data.uvs[size_t(f.uv[c])];
      }
      faces.push_back(face);
    }
    return faces;
  }

  void collectCamera(const Node& n, PovCamera& k) {
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (it.kind == Item::Kind::Node && it.node->keyword == "camera") {
        collectCamera(*it.node, k);
        continue;
      }
      if (it.kind == Item::Kind::Node && it.node->keyword == "mesh_camera") {
        meshCamera(*it.node, k);
        continue;
      }
      if (it.kind == Item::Kind::Node && it.node->keyword == "normal") {
        k.normal = aloneNormal(*it.node, context_);
        continue;
      }
      if (it.kind == Item::Kind::Keyword && it.word == "smooth" && k.mesh) {
        k.mesh->smooth = true;
        continue;
      }
      if (transformItem(n, i, k.steps)) continue;
      if (it.kind != Item::Kind::Keyword) {
        context_.refuse(it, "camera");
        continue;
      }
      const std::string_view w = it.word;
      if (const ProjectionKind* named = projectionNamed(w)) {
        k.projection = named;
        continue;
      }
      const Value* v = valueAfter(n, i);
      if (w == "cylinder") {
        const int type = v && v->type == Value::Type::Float ? int(v->v[0]) : 0;
        k.projection = projectionNamed(w, type);
        if (!k.projection) throw ParseError(it.loc, "'cylinder' needs a type from 1 to 4");
        continue;
      }
      if (w == "angle") k.angleGiven = true;
      if (!v && w == "angle" && k.projection == projectionNamed("orthographic")) continue;  // optional there
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
      else if (w == "aperture") k.blur.aperture = v->v[0];
      else if (w == "focal_point") k.blur.focalPoint = vec3(*v);
      else if (w == "confidence") k.blur.confidence = v->v[0];
      else if (w == "variance") k.blur.variance = v->v[0];
      else if (w == "blur_samples") {
        // `blur_samples MIN, MAX` or `blur_samples MAX`.
        k.blur.maxSamples = int(v->v[0]);
        if (i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Value && n.items[i + 1].value.type == Value::Type::Float) {
          k.blur.minSamples = k.blur.maxSamples;
          k.blur.maxSamples = int(valueAfter(n, i)->v[0]);
        }
      }
      else if (w == "angle") {
        k.angle = v->v[0];
        // `angle H, V` of a spherical camera.
        if (i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Value && n.items[i + 1].value.type == Value::Type::Float) {
          k.verticalAngle = valueAfter(n, i)->v[0];
        }
      }
      else refuse(it.loc, w);
    }
  }

  void light(const Node& n) {
    LightDesc l;
    readLight(n, l, context_,
              [this](const Node& looksLike, const glm::dvec3& position, const std::vector<TransformStep>& steps) {
                lookLike(looksLike, position, steps);
              },
              [this](const Node& block) {
                const size_t index = scene_.lights.size();
                if (scene_.projectedThrough.size() <= index) scene_.projectedThrough.resize(index + 1);
                scene_.projectedThrough[index] = projectedThrough(block);
              });
    scene_.lights.push_back(l);
  }

  // A light's projected_through object, which is not drawn: its shape alone, with no texture or interior
  // (POV-Ray 3.7 manual, "Projected_Through"). A light inside an object would move it with that object: refused.
  std::shared_ptr<const ObjectDesc> projectedThrough(const Node& n) {
    if (nestedLight_) {
      refuse(n.loc, "projected_through in a light inside an object");
      return nullptr;
    }
    std::shared_ptr<const ObjectDesc> through;
    for (const Item& it : n.items) {
      if (!isObject(it) || through) {
        if (through) throw ParseError(it.loc, "projected_through takes one object");
        refuseItem(it, " in projected_through");
        continue;
      }
      ObjectDesc o;
      if (object(*it.node, o)) through = std::make_shared<const ObjectDesc>(std::move(o));
    }
    if (!through && !context_.firstRefusal) throw ParseError(n.loc, "projected_through needs an object");
    return through;
  }

  // A light's looks_like object: drawn about the light's position and moved with it, casting no shadow
  // (POV-Ray 3.7 manual, "Looks_like"). A light inside an object leaves it to that object to move (object()).
  void lookLike(const Node& n, const glm::dvec3& position, const std::vector<TransformStep>& steps) {
    for (const Item& it : n.items) {
      if (!isObject(it)) {
        refuseItem(it, " in looks_like");
        continue;
      }
      ObjectDesc o;
      if (!object(*it.node, o)) continue;
      std::vector<TransformStep> moves{{TransformStep::Kind::Translate, position}};
      moves.insert(moves.end(), steps.begin(), steps.end());
      o.transforms.insert(o.transforms.end(), moves.begin(), moves.end());
      moveTextures(o, glm::inverse(composeTransforms<double>(moves)));
      o.noShadow = true;
      if (nestedLight_) looksInside_.push_back(std::move(o));
      else add(std::move(o), it.node->loc);
    }
  }

  void skySphere(const Node& n) {
    auto sky = std::make_shared<SkySphere>(scene_.sky ? *scene_.sky : SkySphere{});
    std::vector<TransformStep> steps;
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      if (transformItem(n, i, steps)) continue;
      if (it.kind == Item::Kind::Node && it.node->keyword == "pigment") {
        sky->layers.push_back(nestedPigment(*it.node, context_));
      } else if (it.kind == Item::Kind::Node && it.node->keyword == "sky_sphere") {
        skySphere(*it.node);  // an identifier, modified by what follows
        sky = std::make_shared<SkySphere>(*scene_.sky);
      } else {
        context_.refuse(it, "sky_sphere");
      }
    }
    sky->fromWorld = sky->fromWorld * glm::inverse(composeTransforms<double>(steps));
    sky->filterTints = interpreter_.version() >= 3.7;  // measured: docs/povray-language.md, sky_sphere
    scene_.sky = sky;
  }

  void fog(const Node& n) {
    Fog f;
    f.noise.scene = context_.sceneNoise;
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
        context_.refuse(it, "fog");
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
      } else if (it.word == "turbulence") {
        f.turbulence.amount = vec3(*v);
      } else if (it.word == "turb_depth") {
        f.turbDepth = v->v[0];
      } else if (it.word == "octaves") {
        f.turbulence.octaves = int(std::clamp(v->v[0], 1.0, 10.0));  // POV-Ray's limits, as on patterns
      } else if (it.word == "omega") {
        f.turbulence.omega = float(v->v[0]);
      } else if (it.word == "lambda") {
        f.turbulence.lambda = float(v->v[0]);
      } else {
        context_.refuse(it, "fog");
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
          scene_.depthLimit = int(std::max(1.0, v->v[0]));
        } else if (w == "ambient_light" && v && v->numeric()) {
          ambientLight_ = colourOf(*v).rgb;
        } else if (w == "assumed_gamma" && v && v->type == Value::Type::Float) {
          assumedGamma_ = v->v[0];
        } else if (w == "noise_generator" && v && v->type == Value::Type::Float) {
          // POV-Ray drops the fraction and stops at anything but 1, 2 or 3.
          if (!(v->v[0] >= 1 && v->v[0] < 4)) {
            throw ParseError(it.loc, "noise_generator in global_settings must be 1, 2 or 3, found " + shortest(v->v[0]));
          }
          *context_.sceneNoise = noiseGeneratorOf(v->v[0]);
        } else if (w == "adc_bailout" && v && v->type == Value::Type::Float) {
          scene_.adcBailout = float(std::max(0.0, v->v[0]));
        } else if (w == "irid_wavelength" && v && v->numeric()) {
          *context_.iridWavelength = glm::dvec3(colourOf(*v).rgb);
        } else if (w == "number_of_waves" || w == "max_intersections" || w == "hf_gray_16") {
        } else {
          refuse(it.loc, w);
        }
      } else if (it.kind == Item::Kind::Node && it.node->keyword == "radiosity") {
        scene_.radiosity = readRadiosity(*it.node, context_);
      } else {
        refuse(it.loc, it.kind == Item::Kind::Node ? it.node->keyword : "global_settings");
      }
    }
  }

 public:
  Color ambientLight_{1};
  // No object added so far has a texture, a CSG's parts or a mesh's faces: an ambient_light of 1 then leaves
  // every ambient term as it is, and the million objects of a large scene need not be gone over again.
  bool plainOnly_ = true;
  bool nestedLight_ = false;  // reading a light inside an object
  std::vector<ObjectDesc> looksInside_;  // the looks_like objects of such lights, moved with them
  std::optional<double> assumedGamma_;

 private:
  SceneDesc& scene_;
  Interpreter& interpreter_;  // its findFile notes the files the scene reads
  bool asciiStrings_ = true;  // global_settings' charset
  Surface default_;
  // The #default surface's finish terms, its finish as written, and whether it is patterned: worked out once
  // for all the objects until a #default changes it.
  struct DefaultTerms {
    FinishTerms terms;
    SharedFinish finish;
    bool patterned;
  };
  std::optional<DefaultTerms> defaultTerms_;
  ReadingContext context_;
  // markInterior's: each extras made (not) hollow and in a CSG's interior, and the CSGs numbered so far.
  std::map<std::tuple<const SurfaceExtras*, bool, size_t>, const SurfaceExtras*> marked_;
  size_t groups_ = 0;
  struct Asked {
    std::shared_ptr<const Node> node;  // held, so that its address names no other node
    std::unique_ptr<Object<double>> object;
  };
  std::unordered_map<const Node*, Asked> asked_;
  // The meshes read, by their node, with the item after what their read took; the statements that hold
  // those nodes; the statement being read.
  std::unordered_map<const Node*, std::pair<ShapeDesc, size_t>> meshesRead_;
  std::vector<std::shared_ptr<const Node>> heldNodes_;
  std::shared_ptr<const Node> statementNode_;
};

// The texture with every layer's ambient term scaled, in the textures of its patterns too.
Texture ambientScaled(Texture t, const Color& light) {
  for (TextureLayer& layer : t.layers) {
    layer.finish.ambient = (layer.finish.ambient - layer.finish.emission) * light + layer.finish.emission;
    if (!layer.pattern) continue;
    auto pattern = std::make_shared<TexturePattern>(*layer.pattern);
    for (auto& sub : pattern->textures) sub = std::make_shared<const Texture>(ambientScaled(*sub, light));
    layer.pattern = pattern;
  }
  if (t.interior) t.interior = std::make_shared<const Texture>(ambientScaled(*t.interior, light));
  return bounded(std::move(t));
}

// global_settings' ambient_light scales every ambient term, a CSG group's parts' too.
void scaleAmbient(ObjectDesc& o, const Color& light) {
  o.material.ambient *= light;
  if (o.texture) o.texture = std::make_shared<const Texture>(ambientScaled(*o.texture, light));
  if (auto* csg = std::get_if<CsgDesc>(&o.shape)) {
    for (ObjectDesc& child : csg->children) scaleAmbient(child, light);
  }
  if (auto* mesh = std::get_if<MeshDesc>(&o.shape)) {
    for (FaceSurface& face : mesh->surfaces) {
      face.material.ambient *= light;
      if (face.texture) face.texture = std::make_shared<const Texture>(ambientScaled(*face.texture, light));
    }
  }
}

}  // namespace

SceneDesc parsePovRay(std::string_view text, const std::string& path, const PovRayOptions& options) {
  SceneDesc scene;
  scene.file = path;
  scene.language = SceneLanguage::PovRay;
  scene.camera.right = {1.33, 0, 0};
  scene.camera.lookAt = {0, 0, 1};
  InterpreterOptions io;
  io.libraryPaths = options.libraryPaths;
  io.imageWidth = options.imageWidth;
  io.imageHeight = options.imageHeight;
  io.debug = options.debugOutput ? &std::cerr : nullptr;
  io.maxTokens = options.maxTokens;
  io.writeFolder = options.writeFolder;
  io.writeAnywhere = options.writeAnywhere;
  io.clock = options.clock;
  Builder* builderOf = nullptr;  // made once the interpreter is, and asked only while it runs
  io.extent = [&builderOf](const std::shared_ptr<const Node>& n) { return builderOf->extent(n); };
  io.trace = [&builderOf](const std::shared_ptr<const Node>& n, const InterpreterOptions::Vec& start,
                          const InterpreterOptions::Vec& dir) { return builderOf->trace(n, start, dir); };
  io.inside = [&builderOf](const std::shared_ptr<const Node>& n, const InterpreterOptions::Vec& p) {
    return builderOf->runtimeObject(n).inside({p[0], p[1], p[2]});
  };
  io.patternFunction = [&builderOf](const Node& pattern, FunctionValue& into) { builderOf->patternFunction(pattern, into); };
  io.pigmentFunction = [&builderOf](const Node& pigment, FunctionValue& into) { builderOf->pigmentFunction(pigment, into); };
  io.transformFunction = [&builderOf](const Node& t, FunctionValue& into) { builderOf->transformFunction(t, into); };
  Interpreter interpreter(io);
  for (const std::string& d : options.declares) {
    const size_t eq = d.find('=');
    interpreter.declare(d.substr(0, eq), eq == std::string::npos ? "1" : d.substr(eq + 1));
  }
  Builder builder(scene, interpreter);
  builderOf = &builder;
  interpreter.run(path, text, [&](const std::shared_ptr<const Node>& n) { builder.statement(n); },
                  [&](const std::shared_ptr<const Node>& n) { builder.defaults(*n); });
  builder.finish();
  // assumed_gamma is 1 by default from #version 3.7 on; an older scene without it has its colours written as
  // they are (docs/povray-language.md, "Gamma").
  scene.dialect = Dialect::povray(builder.assumedGamma_.value_or(interpreter.version() >= 3.7 ? 1.0 : 0.0));
  if (!scene.adcBailout) scene.adcBailout = 1.0f / 255;  // POV-Ray's default (manual, "Adc_Bailout")
  // With radiosity a 3.7 scene's ambient term is 0 and its emission alone lights; an older scene's ambient (times
  // ambient_light) still does, as emission would (POV-Ray 3.7 manual, "How Radiosity Works"; measured, docs/gi.md).
  const bool noAmbient = scene.radiosity && interpreter.version() >= 3.7;
  const Color light = noAmbient ? Color(0) : builder.ambientLight_;
  if (light != Color(1) || !builder.plainOnly_) {
    for (ObjectDesc& o : scene.objects) scaleAmbient(o, light);
  }
  scene.dataFiles = interpreter.takeDataFiles();
  scene.inputFiles = interpreter.takeFilesFound();
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
