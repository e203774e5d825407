#include "raytrace/parse/povray/surface_reader.hpp"

#include <algorithm>
#include <numeric>

#include "raytrace/surface/density_file.hpp"
#include "raytrace/surface/patterns.hpp"

namespace rt::povray {

void ReadingContext::refuse(const Item& it, std::string_view otherwise) {
  refuse(it.loc, it.kind == Item::Kind::Keyword ? it.word : it.kind == Item::Kind::Node ? it.node->keyword : otherwise);
}

glm::dvec3 vec3(const Value& v) {
  if (v.type == Value::Type::Float) return glm::dvec3(v.v[0]);
  return {v.v[0], v.size > 1 ? v.v[1] : 0, v.size > 2 ? v.v[2] : 0};
}

Rgbft colourOf(const Value& v) {
  if (v.type == Value::Type::Float) return {Color(float(v.v[0])), 0, 0};
  double c[5] = {};
  for (int i = 0; i < v.size && i < 5; ++i) c[i] = v.v[size_t(i)];
  return {Color(float(c[0]), float(c[1]), float(c[2])), float(c[3]), float(c[4])};
}

namespace {

// A colour's component named after the colour, as in `Gold filter 0.92`.
bool isComponentWord(std::string_view w) {
  return w == "red" || w == "green" || w == "blue" || w == "filter" || w == "transmit";
}

}  // namespace

const Value* valueAfter(const Node& n, size_t& i) {
  if (i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Value) return &n.items[++i].value;
  return nullptr;
}

void readTransformBlock(const Node& n, std::vector<TransformStep>& steps, ReadingContext& context) {
  std::vector<TransformStep> own;
  bool inverse = false;
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    if (it.kind == Item::Kind::Keyword && it.word == "inverse") {
      inverse = !inverse;
    } else if (!readTransform(n, i, own, context)) {
      context.refuse(it, "transform");
    }
  }
  if (!inverse) {
    steps.insert(steps.end(), own.begin(), own.end());
    return;
  }
  // `inverse` anywhere in the block undoes the whole block (the manual's §3.3.1.12): one matrix step.
  const glm::dmat4 m = glm::inverse(composeTransforms<double>(own));
  auto rows = std::make_shared<std::array<double, 12>>();
  for (size_t r = 0; r < 4; ++r) {
    for (size_t c = 0; c < 3; ++c) (*rows)[r * 3 + c] = m[int(r)][int(c)];
  }
  steps.push_back({TransformStep::Kind::Matrix, glm::dvec3(0), std::move(rows)});
}

bool readTurbulence(const Node& n, size_t& i, Turbulence& t) {
  const Item& it = n.items[i];
  const std::string_view w = it.word;
  if (it.kind != Item::Kind::Keyword || (w != "turbulence" && w != "octaves" && w != "omega" && w != "lambda")) {
    return false;
  }
  const Value* v = valueAfter(n, i);
  const bool vector = w == "turbulence";
  if (!v || !v->numeric() || (!vector && v->type != Value::Type::Float)) {
    throw ParseError(it.loc, "'" + std::string(w) + (vector ? "' needs a float or a vector" : "' needs a float"));
  }
  const double x = v->v[0];
  if (w == "turbulence") {
    t.amount = vec3(*v);
  } else if (w == "octaves") {
    t.octaves = int(std::clamp(x, 1.0, 10.0));  // POV-Ray's limits
  } else if (w == "omega") {
    t.omega = float(x);
  } else {
    t.lambda = float(x);
  }
  return true;
}

bool readTransform(const Node& n, size_t& i, std::vector<TransformStep>& steps, ReadingContext& context) {
  const Item& it = n.items[i];
  if (it.kind == Item::Kind::Node && it.node->keyword == "transform") {
    readTransformBlock(*it.node, steps, context);
    return true;
  }
  if (it.kind != Item::Kind::Keyword) return false;
  const std::string_view w = it.word;
  if (w == "transform") {
    if (i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Node) readTransformBlock(*n.items[++i].node, steps, context);
    return true;
  }
  if (w != "translate" && w != "rotate" && w != "scale" && w != "matrix") return false;
  const Value* v = valueAfter(n, i);
  if (!v) {
    context.refuse(it.loc, w);
    return true;
  }
  if (w == "matrix") {
    const auto* list = dynamic_cast<const CoefficientList*>(v->ref.get());
    if (!list || list->values.size() != 12) {
      throw ParseError(n.items[i].loc, "'matrix' needs 12 numbers, found " +
                                           std::to_string(list ? list->values.size() : size_t(v->size)));
    }
    auto m = std::make_shared<std::array<double, 12>>();
    std::copy(list->values.begin(), list->values.end(), m->begin());
    steps.push_back({TransformStep::Kind::Matrix, glm::dvec3(0), std::move(m)});
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

std::shared_ptr<const Pigment> nestedPigment(const Node& n, ReadingContext& context);

namespace {

std::shared_ptr<const Pigment> solidPigment(const Rgbft& c) {
  auto p = std::make_shared<Pigment>();
  p->solid = c;
  return p;
}

std::vector<WarpMark> readPigment(const Node& n, Pigment& p, std::vector<TransformStep>& steps, ReadingContext& context);

// frequency, phase and the wave types of a pigment or a normal; false for any other item.
template <class Waved> bool readWave(const Node& n, size_t& i, Waved& p) {
  const Item& it = n.items[i];
  if (it.kind != Item::Kind::Keyword) return false;
  const std::string_view w = it.word;
  constexpr std::pair<std::string_view, Wave> kWaves[] = {{"ramp_wave", Wave::Ramp},       {"triangle_wave", Wave::Triangle},
                                                          {"sine_wave", Wave::Sine},       {"scallop_wave", Wave::Scallop},
                                                          {"cubic_wave", Wave::Cubic},     {"poly_wave", Wave::Poly}};
  for (const auto& [name, wave] : kWaves) {
    if (w != name) continue;
    p.wave = wave;
    if (wave == Wave::Poly && i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Value) {
      p.exponent = valueAfter(n, i)->v[0];
    }
    return true;
  }
  if (w != "frequency" && w != "phase") return false;
  const Value* v = valueAfter(n, i);
  if (!v || v->type != Value::Type::Float) throw ParseError(it.loc, "'" + std::string(w) + "' needs a float");
  (w == "frequency" ? p.frequency : p.phase) = v->v[0];
  return true;
}

bool isFunction(const Item& it) { return it.kind == Item::Kind::Value && it.value.type == Value::Type::Function; }

// What follows a fractal pattern's keyword (POV-Ray 3.7 manual, "Fractal Pattern"): `mandel ITERATIONS`,
// `julia COMPLEX, ITERATIONS`, `magnet 1|2 mandel …` or `magnet 1|2 julia …`.
void readFractalHead(const Node& n, size_t& i, FractalArgs& f) {
  using Set = FractalArgs::Set;
  const Item& it = n.items[i];
  std::string_view form = it.word;
  int magnet = 0;
  if (form == "magnet") {
    const Value* type = valueAfter(n, i);
    if (!type || type->type != Value::Type::Float || (type->v[0] != 1 && type->v[0] != 2)) {
      throw ParseError(it.loc, "'magnet' needs its type, 1 or 2");
    }
    magnet = int(type->v[0]);
    const bool next = i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Keyword;
    form = next ? n.items[i + 1].word : "";
    if (form != "mandel" && form != "julia") throw ParseError(it.loc, "'magnet' needs 'mandel' or 'julia' after its type");
    ++i;
  }
  const bool julia = form == "julia";
  if (julia) {
    const Value* c = valueAfter(n, i);
    if (!c || !c->numeric()) throw ParseError(it.loc, "'julia' needs its complex constant");
    f.constant = glm::dvec2(vec3(*c));
  }
  const Value* iterations = valueAfter(n, i);
  if (!iterations || iterations->type != Value::Type::Float) {
    throw ParseError(it.loc, "'" + std::string(form) + "' needs its number of iterations");
  }
  f.iterations = int(std::max(0.0, iterations->v[0]));
  f.set = magnet == 0 ? (julia ? Set::Julia : Set::Mandel)
          : magnet == 1 ? (julia ? Set::Magnet1Julia : Set::Magnet1Mandel)
                        : (julia ? Set::Magnet2Julia : Set::Magnet2Mandel);
}

// What follows density_file: `df3 "file"`, the file found as an image map's is and read at once.
void readDensityFileHead(const Node& n, size_t& i, PatternArgs& args, ReadingContext& context) {
  const Item& it = n.items[i];
  const bool df3 = i + 2 < n.items.size() && n.items[i + 1].kind == Item::Kind::Keyword && n.items[i + 1].word == "df3" &&
                   n.items[i + 2].kind == Item::Kind::Value && n.items[i + 2].value.type == Value::Type::String;
  if (!df3) throw ParseError(it.loc, "'density_file' needs 'df3' and a file name");
  i += 2;
  const Item& name = n.items[i];
  const std::string path = context.findFile ? context.findFile(name.value.str()) : name.value.str();
  if (path.empty()) throw ParseError(name.loc, "cannot find the density file \"" + name.value.str() + "\"");
  args.densityFile = std::make_shared<const DensityGrid>(readDensityFile(path, name.loc));
}

// A pattern written as a block of its own: `pigment_pattern { … }` or `slope { … }`.
bool patternBlock(const Item& it) {
  return it.kind == Item::Kind::Node && (it.node->keyword == "pigment_pattern" || it.node->keyword == "slope");
}

// `slope { <direction> [, lo, hi] [altitude <altitude> [, lo, hi]] }` (POV-Ray 3.7 manual, "Slope Pattern");
// false when refused (the point_at form).
bool readSlope(const Node& n, SlopeArgs& a, ReadingContext& context) {
  size_t i = 0;
  const auto range = [&](double& lo, double& hi, const char* what) {
    if (i >= n.items.size() || n.items[i].kind != Item::Kind::Value || n.items[i].value.type != Value::Type::Float) return;
    const Item& at = n.items[i];
    const Value* l = &at.value;
    const Value* h = valueAfter(n, i);
    if (!h || h->type != Value::Type::Float) throw ParseError(at.loc, std::string("slope's ") + what + " range needs two floats");
    if (l->v[0] == h->v[0]) throw ParseError(at.loc, std::string("slope's ") + what + " range is empty");
    lo = l->v[0];
    hi = h->v[0];
    ++i;
  };
  if (!n.items.empty() && n.items[0].kind == Item::Kind::Keyword && n.items[0].word == "point_at") {
    context.refuse(n.items[0].loc, "slope point_at");
    return false;
  }
  if (n.items.empty() || n.items[0].kind != Item::Kind::Value || !n.items[0].value.numeric() ||
      glm::length(vec3(n.items[0].value)) == 0) {
    throw ParseError(n.loc, "slope needs a direction other than <0, 0, 0>");
  }
  a.direction = vec3(n.items[0].value);
  i = 1;
  range(a.lo, a.hi, "slope");
  if (i < n.items.size() && n.items[i].kind == Item::Kind::Keyword && n.items[i].word == "altitude") {
    const Value* v = valueAfter(n, i);
    if (!v || !v->numeric()) throw ParseError(n.items[i].loc, "'altitude' needs a vector");
    a.altitude = vec3(*v);
    ++i;
    range(a.altitudeLo, a.altitudeHi, "altitude");
  }
  if (i < n.items.size()) throw ParseError(n.items[i].loc, "slope takes a direction, a range and an altitude only");
  return true;
}

// A pattern being read: its kind and what the pigment's modifiers set, made again with them once the block
// is read, since the modifiers may follow the colour map.
struct PatternDraft {
  const PatternKind* kind = nullptr;
  PatternArgs args;
  bool modified = false;
  std::vector<WarpMark> warps;

  // The pattern of keyword n.items[i] (i moves past its vector), or of a `function { … }` value; nothing if the
  // item names no pattern, or is a function that did not compile (refused). `kinds` finds a keyword's kind.
  std::unique_ptr<Pattern> start(const Node& n, size_t& i, ReadingContext& context,
                                 const PatternKind* (*kinds)(std::string_view) = patternKind) {
    const Item& it = n.items[i];
    const bool function = isFunction(it);
    const bool block = patternBlock(it), pigment = block && it.node->keyword == "pigment_pattern";
    const PatternKind* k = function                         ? patternKind("function")
                           : block                          ? patternKind(it.node->keyword)
                           : it.kind == Item::Kind::Keyword ? kinds(it.word)
                                                            : nullptr;
    if (!k || (!block && (k->make == makePigmentPattern || k->make == makeSlope))) return nullptr;  // they need their block
    if (function && !static_cast<const FunctionValue&>(*it.value.ref).compiled) {
      const auto& f = static_cast<const FunctionValue&>(*it.value.ref);
      context.refuse(f.whyAt, f.why);
      return nullptr;
    }
    kind = k;
    args = PatternArgs{};
    args.noise.scene = context.sceneNoise;
    if (function) args.function = static_cast<const FunctionValue&>(*it.value.ref).compiled;
    if (pigment) args.pigment = nestedPigment(*it.node, context);
    if (block && !pigment && !readSlope(*it.node, args.slope, context)) return nullptr;
    if (k->needsVector) {
      const Value* v = valueAfter(n, i);
      if (!v || !v->numeric()) throw ParseError(it.loc, "'" + std::string(it.word) + "' needs a number or a vector");
      args.vector = vec3(*v);
      args.hasVector = true;
    }
    if (k->make == makeTiling) {
      // POV-Ray truncates the number and takes 1 … 27 (its parser's message).
      const int number = int(args.vector.x);
      if (number < 1 || number > 27) throw ParseError(it.loc, "tiling number must be between 1 and 27");
      if (!tilingDrawn(number)) {
        context.refuse(it.loc, "tiling " + std::to_string(number));
        return nullptr;
      }
    }
    if (k->make == makeFractal) readFractalHead(n, i, args.fractal);
    if (k->make == makeDensityFile) readDensityFileHead(n, i, args, context);
    return makePattern(*k, args);
  }

  // turbulence, octaves, omega, lambda, noise_generator, agate_turb, crackle's form, metric, offset and solid,
  // quilted's control0 and control1, brick's brick_size and mortar, and the fractals' exponent, interior and
  // exterior; false for any other item.
  bool modifier(const Node& n, size_t& i, ReadingContext& context) {
    const Item& it = n.items[i];
    if (it.kind != Item::Kind::Keyword) return false;
    const std::string_view w = it.word;
    if (w == "solid") {
      args.crackle.solid = true;
      modified = true;
      return true;
    }
    if (w == "interior" || w == "exterior") {
      fractalColouring(n, i);
      return true;
    }
    if (readTurbulence(n, i, args.turbulence)) {
      modified = true;
      return true;
    }
    if (w == "interpolate" && kind && kind->make == makeDensityFile) {
      const Value* v = valueAfter(n, i);
      if (!v || v->type != Value::Type::Float || (v->v[0] != 0 && v->v[0] != 1 && v->v[0] != 2)) {
        throw ParseError(it.loc, "the density_file's interpolate must be 0, 1 or 2");
      }
      args.densityInterpolation = int(v->v[0]);
      modified = true;
      return true;
    }
    const bool vector = w == "form" || w == "brick_size";
    if (!vector && w != "noise_generator" && w != "agate_turb" &&
        w != "metric" && w != "offset" && w != "control0" && w != "control1" && w != "mortar" && w != "exponent") {
      return false;
    }
    const Value* v = valueAfter(n, i);
    if (!v || !v->numeric() || (!vector && v->type != Value::Type::Float)) {
      throw ParseError(it.loc, "'" + std::string(w) + (vector ? "' needs a float or a vector" : "' needs a float"));
    }
    const double x = v->v[0];
    if (w == "form") {
      args.crackle.form = vec3(*v);
    } else if (w == "metric") {
      if (!(x > 0)) throw ParseError(it.loc, "the crackle metric must be greater than 0");
      args.crackle.metric = x;
    } else if (w == "offset") {
      args.crackle.offset = x;
    } else if (w == "agate_turb") {
      args.agateTurbulence = x;
    } else if (w == "control0" || w == "control1") {
      (w == "control0" ? args.control0 : args.control1) = x;
    } else if (w == "brick_size" || w == "mortar") {
      if (!kind || kind->make != makeBrick) throw ParseError(it.loc, "'" + std::string(w) + "' belongs to a brick pattern");
      if (w == "mortar") {
        args.mortar = x;
      } else {
        args.brickSize = vec3(*v);
      }
    } else if (w == "exponent") {
      const bool mandelOrJulia = args.fractal.set == FractalArgs::Set::Mandel || args.fractal.set == FractalArgs::Set::Julia;
      if (!kind || kind->make != makeFractal || !mandelOrJulia) {
        throw ParseError(it.loc, "'exponent' belongs to a mandel or julia pattern");
      }
      args.fractal.exponent = x >= 2 && x < 34 ? int(x) : 2;  // POV-Ray warns and takes 2 outside 2 to 33
    } else {
      args.noise.own = noiseGeneratorOf(x);
    }
    modified = true;
    return true;
  }

  // `interior TYPE, FACTOR` or `exterior TYPE, FACTOR`: what a fractal's value is inside or outside its set.
  void fractalColouring(const Node& n, size_t& i) {
    const Item& it = n.items[i];
    if (!kind || kind->make != makeFractal) {
      throw ParseError(it.loc, "'" + std::string(it.word) + "' belongs to a mandel, julia or magnet pattern");
    }
    const Value* type = valueAfter(n, i);
    const Value* factor = type ? valueAfter(n, i) : nullptr;
    if (!factor || type->type != Value::Type::Float || factor->type != Value::Type::Float) {
      throw ParseError(it.loc, "'" + std::string(it.word) + "' needs a type and a factor");
    }
    if (!(type->v[0] >= 0 && type->v[0] < 7)) {
      throw ParseError(it.loc, "the fractal " + std::string(it.word) + " type must be 0 to 6");
    }
    (it.word == "interior" ? args.fractal.interiorType : args.fractal.exteriorType) = int(type->v[0]);
    (it.word == "interior" ? args.fractal.interiorFactor : args.fractal.exteriorFactor) = factor->v[0];
    modified = true;
  }

  // The pattern made again with the modifiers read after it.
  void finish(std::shared_ptr<const Pattern>& pattern, const SourceLoc& at, ReadingContext& context) const {
    if (!modified || !pattern) return;
    if (!kind) {
      context.refuse(at, "turbulence on a pattern of an earlier block");
      return;
    }
    if (args.turbulence.on() && !kind->turbulenceDrawn) {
      context.refuse(at, "turbulence on " + std::string(kind->name));
      return;
    }
    pattern = makePattern(*kind, args);
  }
};

}  // namespace

namespace {

// color_map or pigment_map entries: `[value colour]`, `[value pigment { … }]`, or the old `[v0 v1 colour0 colour1]`.
// An average's entries may leave out their weight, which is then 1.
void readMap(const Node& n, std::vector<MapEntry>& map, ReadingContext& context, bool weightsOptional = false) {
  for (const Item& it : n.items) {
    if (it.kind == Item::Kind::Node && (it.node->keyword == "color_map" || it.node->keyword == "colour_map" ||
                                        it.node->keyword == "pigment_map")) {
      readMap(*it.node, map, context, weightsOptional);  // a map identifier
      continue;
    }
    if (it.kind != Item::Kind::Node || it.node->keyword != "[") {
      context.refuse(it, "a map entry");
      continue;
    }
    const std::vector<Item>& items = it.node->items;
    std::vector<double> values;
    size_t k = 0;
    for (; k < items.size() && values.size() < 2; ++k) {
      const Item& e = items[k];
      if (e.kind != Item::Kind::Value || e.value.type != Value::Type::Float) break;
      values.push_back(e.value.v[0]);
    }
    // Colours, pigments, or one pigment's items written bare (`[0.5 P_Cloud scale 2]`).
    std::vector<std::shared_ptr<const Pigment>> pigments;
    const bool listed = std::all_of(items.begin() + long(k), items.end(), [](const Item& e) {
      return (e.kind == Item::Kind::Value && e.value.numeric()) || (e.kind == Item::Kind::Node && e.node->keyword == "pigment");
    });
    if (listed) {
      for (size_t j = k; j < items.size(); ++j) {
        const Item& e = items[j];
        pigments.push_back(e.kind == Item::Kind::Value ? solidPigment(colourOf(e.value)) : nestedPigment(*e.node, context));
      }
    } else {
      Node body;
      body.keyword = "pigment";
      body.loc = items[k].loc;
      body.items.assign(items.begin() + long(k), items.end());
      pigments.push_back(nestedPigment(body, context));
    }
    // `[0.5 1]` is a value and a grey.
    if (pigments.empty() && values.size() == 2) pigments.push_back(solidPigment({Color(float(values[1])), 0, 0}));
    if (values.empty() && weightsOptional) values.push_back(1);
    if (values.empty() || pigments.empty()) continue;
    if (values.size() == 2 && pigments.size() == 2) {
      map.push_back({values[0], pigments[0]});
      map.push_back({values[1], pigments[1]});
    } else {
      map.push_back({values[0], pigments[0]});
    }
  }
  // POV-Ray reads the entries in order and expects them sorted; a stable sort keeps equal values' order.
  std::stable_sort(map.begin(), map.end(), [](const MapEntry& a, const MapEntry& b) { return a.value < b.value; });
}

void readPigmentItems(const Node& n, Pigment& p, PatternDraft& draft, std::vector<TransformStep>& steps,
                      ReadingContext& context) {
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    const bool blocks = p.pattern && p.pattern->blocks() > 0;
    if (it.kind == Item::Kind::Value && it.value.numeric()) {
      if (blocks && p.list.size() < size_t(p.pattern->blocks())) {
        p.list.push_back(solidPigment(colourOf(it.value)));
      } else {
        p = Pigment{};
        p.solid = colourOf(it.value);
      }
      continue;
    }
    if (readTransform(n, i, steps, context)) continue;
    const bool patternNode = patternBlock(it);
    if (it.kind == Item::Kind::Node && !patternNode) {
      const std::string_view k = it.node->keyword;
      if (k == "pigment" && blocks && p.list.size() < size_t(p.pattern->blocks())) {
        p.list.push_back(nestedPigment(*it.node, context));
      } else if (k == "pigment") {
        readPigmentItems(*it.node, p, draft, steps, context);  // an identifier, modified by what follows
      } else if (k == "warp") {
        if (std::shared_ptr<const Warp> warp = readWarp(*it.node, context)) draft.warps.push_back({steps.size(), warp});
      } else if (k == "color_map" || k == "colour_map" || k == "pigment_map") {
        p.map.clear();
        readMap(*it.node, p.map, context, p.average);
      } else if (k == "image_map") {
        p = Pigment{};
        p.image = readImageMap(*it.node, context);
        draft = PatternDraft{};
      } else {
        context.refuse(it, "pigment");
      }
      continue;
    }
    if (it.kind != Item::Kind::Keyword && !isFunction(it) && !patternNode) {
      context.refuse(it, "a value here");
      continue;
    }
    const std::string_view w = it.word;
    if (std::unique_ptr<Pattern> pattern = draft.start(n, i, context)) {
      const Rgbft keep = p.solid;
      p = Pigment{};
      p.solid = keep;
      p.pattern = std::move(pattern);
      p.wave = draft.kind->wave;
      continue;
    }
    if (isFunction(it)) {
      continue;  // refused by draft.start
    } else if (isComponentWord(w) && !p.pattern &&
               !p.average && !p.image) {
      // A colour identifier's component changed after it: `pigment { Gold filter 0.92 }`.
      const Value* v = valueAfter(n, i);
      if (!v || v->type != Value::Type::Float) throw ParseError(it.loc, "'" + std::string(w) + "' needs a float");
      const float x = float(v->v[0]);
      if (w == "filter") {
        p.solid.filter = x;
      } else if (w == "transmit") {
        p.solid.transmit = x;
      } else {
        p.solid.rgb[w == "red" ? 0 : w == "green" ? 1 : 2] = x;
      }
    } else if (w == "average") {
      const Rgbft keep = p.solid;
      p = Pigment{};
      p.solid = keep;
      p.average = true;
      draft = PatternDraft{};
    } else if (w == "quick_color" || w == "quick_colour") {
      // The colour of POV-Ray's quick preview, which draws no textures: read and dropped, also when spelled
      // by components (`quick_colour red 0.7 green 0.7 blue 1`).
      if (!valueAfter(n, i)) {
        while (i + 2 < n.items.size() && n.items[i + 1].kind == Item::Kind::Keyword &&
               isComponentWord(n.items[i + 1].word) && n.items[i + 2].kind == Item::Kind::Value) {
          i += 2;
        }
      }
    } else if (!readWave(n, i, p) && !draft.modifier(n, i, context)) {
      context.refuse(it.loc, w);
    }
  }
}

std::vector<WarpMark> readPigment(const Node& n, Pigment& p, std::vector<TransformStep>& steps, ReadingContext& context) {
  PatternDraft draft;
  if (const auto earlier = p.pattern ? context.patternRecipes->find(p.pattern) : context.patternRecipes->end();
      earlier != context.patternRecipes->end()) {  // a pattern of an earlier block, which this one may modify
    draft.kind = earlier->second.kind;
    draft.args = earlier->second.args;
  }
  readPigmentItems(n, p, draft, steps, context);
  draft.finish(p.pattern, n.loc, context);
  if (p.pattern && draft.kind) context.patternRecipes->insert_or_assign(p.pattern, ReadingContext::PatternRecipe{draft.kind, draft.args});
  // Without a map a continuous pattern is drawn with its kind's own map, else as a grey ramp, black at 0 and
  // white at 1 (measured with pigment functions).
  if (p.average && p.map.empty()) throw ParseError(n.loc, "'average' needs a pigment_map");
  if (p.pattern && p.pattern->blocks() == 0 && p.map.empty()) {
    if (const DefaultMap* own = draft.kind ? draft.kind->defaultMap : nullptr) {
      for (size_t k = 0; k < own->count; ++k) p.map.push_back({own->stops[k].value, solidPigment({own->stops[k].colour, 0, 0})});
    } else {
      p.map = {{0, solidPigment({})}, {1, solidPigment({Color(1), 0, 0})}};
    }
  }
  while (p.pattern && p.list.size() < size_t(p.pattern->blocks())) {
    p.list.push_back(solidPigment({p.pattern->defaultBlock(int(p.list.size())), 0, 0}));
  }
  return std::move(draft.warps);
}

float largest(const Color& c) { return std::max({c.r, c.g, c.b}); }

// A colour reflection as its largest channel and the tint that makes the colour of it.
Color reflectionTint(const Color& c) { return largest(c) > 0 ? c / largest(c) : Color(1); }

void setReflection(PovFinish& f, const Color& c) {
  f.reflection = largest(c);
  f.reflectionTint = reflectionTint(c);
}

// `reflection { [min,] max [fresnel on] [falloff F] }` (POV-Ray 3.7 manual, "Specular Reflection"): one value
// reflects the same at every angle, two vary from the first facing the viewer to the second at grazing angles.
void readReflection(const Node& n, PovFinish& f, ReadingContext& context) {
  std::vector<Color> values;
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& r = n.items[i];
    if (r.kind == Item::Kind::Value && r.value.numeric()) {
      values.push_back(colourOf(r.value).rgb);
      continue;
    }
    const Value* v = r.kind == Item::Kind::Keyword ? valueAfter(n, i) : nullptr;
    if (r.kind == Item::Kind::Keyword && r.word == "fresnel") {
      f.reflectionFresnel = !v || v->v[0] != 0;
    } else if (r.kind == Item::Kind::Keyword && r.word == "falloff" && v && v->numeric()) {
      f.reflectionFalloff = v->v[0];
    } else if (r.kind == Item::Kind::Keyword && r.word == "metallic") {
      f.reflectionMetallic = v && v->numeric() ? v->v[0] : 1;  // the value is optional
    } else if (r.kind == Item::Kind::Keyword && r.word == "exponent" && v && v->numeric() && v->v[0] == 1) {
      continue;  // POV-Ray's default: reflected light as it is
    } else {
      context.refuse(r, "reflection");
    }
  }
  if (values.empty()) return;
  setReflection(f, values.back());
  f.reflectionMin = values.size() > 1 ? std::optional<double>(largest(values.front())) : std::nullopt;
  f.reflectionMinTint = reflectionTint(values.front());
}

// `irid { amount [thickness T] [turbulence U] }` (POV-Ray 3.7 manual, "Iridescence"); amount 0 is no film.
void readIrid(const Node& n, PovFinish& f, ReadingContext& context) {
  Iridescence irid;
  irid.wavelengths = context.iridWavelength;
  irid.noise = context.sceneNoise;
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& r = n.items[i];
    if (r.kind == Item::Kind::Value && r.value.type == Value::Type::Float) {
      irid.amount = r.value.v[0];
      continue;
    }
    const Value* v = r.kind == Item::Kind::Keyword ? valueAfter(n, i) : nullptr;
    if (v && v->type == Value::Type::Float && r.word == "thickness") {
      irid.thickness = v->v[0];
    } else if (v && v->type == Value::Type::Float && r.word == "turbulence") {
      irid.turbulence = v->v[0];
    } else {
      context.refuse(r, "irid");
    }
  }
  f.irid = irid.amount != 0 ? std::make_shared<const Iridescence>(irid) : nullptr;
}

void readFinish(const Node& n, PovFinish& f, ReadingContext& context) {
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    if (it.kind == Item::Kind::Node && it.node->keyword == "finish") {
      readFinish(*it.node, f, context);
      continue;
    }
    if (it.kind == Item::Kind::Node && it.node->keyword == "reflection") {
      readReflection(*it.node, f, context);
      continue;
    }
    if (it.kind == Item::Kind::Node && it.node->keyword == "irid") {
      readIrid(*it.node, f, context);
      continue;
    }
    if (it.kind != Item::Kind::Keyword) {
      context.refuse(it, "finish");
      continue;
    }
    const std::string_view w = it.word;
    if (w == "conserve_energy") {
      const Value* on = valueAfter(n, i);
      f.conserveEnergy = !on || on->v[0] != 0;
      continue;
    }
    const Value* v = valueAfter(n, i);
    if (w == "metallic") {
      f.metallic = v && v->numeric() ? v->v[0] : 1;  // the value is optional
      continue;
    }
    if (!v || !v->numeric()) {
      context.refuse(it.loc, w);
      continue;
    }
    const double x = v->v[0];
    if (w == "ambient") {
      f.ambient = colourOf(*v).rgb;
    } else if (w == "crand") {
      f.crand = x;
    } else if (w == "emission") {
      f.emission = colourOf(*v).rgb;
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
      setReflection(f, colourOf(*v).rgb);
      f.reflectionMin.reset();
      f.reflectionMinTint = Color(1);
    } else if (w == "brilliance") {
      f.brilliance = x;
    } else {
      context.refuse(it.loc, w);
    }
  }
}

// slope_map entries `[value, <height, slope>]`, or a slope_map identifier.
void readSlopeMap(const Node& n, std::vector<SlopeEntry>& slopes) {
  for (const Item& it : n.items) {
    if (it.kind == Item::Kind::Node && it.node->keyword == "slope_map") {
      readSlopeMap(*it.node, slopes);
      continue;
    }
    const std::vector<Item>* e = it.kind == Item::Kind::Node && it.node->keyword == "[" ? &it.node->items : nullptr;
    if (!e || e->size() != 2 || (*e)[0].kind != Item::Kind::Value || (*e)[0].value.type != Value::Type::Float ||
        (*e)[1].kind != Item::Kind::Value || !(*e)[1].value.numeric()) {
      throw ParseError(it.loc, "a slope_map entry is [value, <height, slope>]");
    }
    const glm::dvec3 hs = vec3((*e)[1].value);
    slopes.push_back({(*e)[0].value.v[0], hs.x, hs.y});
  }
  std::stable_sort(slopes.begin(), slopes.end(), [](const SlopeEntry& a, const SlopeEntry& b) { return a.value < b.value; });
}

std::vector<WarpMark> readNormal(const Node& n, Normal& normal, std::vector<TransformStep>& steps,
                                 ReadingContext& context);

// A map's or a list's normal, which starts as the #default texture's, as every normal block does.
std::shared_ptr<const Normal> nestedNormal(const Node& n, const Normal& base, ReadingContext& context) {
  auto normal = std::make_shared<Normal>(base);
  std::vector<TransformStep> steps;
  const std::vector<WarpMark> warps = readNormal(n, *normal, steps, context);
  placeTransforms(*normal, steps, warps);
  return normal;
}

// normal_map entries `[value normal items…]`, or a normal_map identifier; an average's may leave out their
// weight, which is then 1.
void readNormalMap(const Node& n, std::vector<NormalEntry>& map, bool weightsOptional, const Normal& base,
                   ReadingContext& context) {
  for (const Item& it : n.items) {
    if (it.kind == Item::Kind::Node && it.node->keyword == "normal_map") {
      readNormalMap(*it.node, map, weightsOptional, base, context);
      continue;
    }
    const std::vector<Item>* e = it.kind == Item::Kind::Node && it.node->keyword == "[" ? &it.node->items : nullptr;
    const bool weighted = e && !e->empty() && (*e)[0].kind == Item::Kind::Value && (*e)[0].value.type == Value::Type::Float;
    if (!e || (!weighted && !weightsOptional) || e->size() < (weighted ? 2u : 1u)) {
      throw ParseError(it.loc, "a normal_map entry is [value normal]");
    }
    Node body;
    body.keyword = "normal";
    body.loc = it.loc;
    body.items.assign(e->begin() + (weighted ? 1 : 0), e->end());
    map.push_back({weighted ? (*e)[0].value.v[0] : 1.0, nestedNormal(body, base, context)});
  }
  // POV-Ray reads the entries in order and expects them sorted; a stable sort keeps equal values' order.
  if (!weightsOptional) {
    std::stable_sort(map.begin(), map.end(), [](const NormalEntry& a, const NormalEntry& b) { return a.value < b.value; });
  }
}

// `bump_map { … }` as the normal's pattern, its bump_size the normal's amount; only the planar map is drawn.
void readBumpMapNormal(const Node& n, Normal& normal, ReadingContext& context) {
  BumpMapSettings settings;
  const std::shared_ptr<const ImageMap> image = readBumpMap(n, context, settings);
  if (!image) return;
  if (image->mapping != ImageMap::Mapping::Planar) {
    context.refuse(n.loc, "bump_map map_type " + std::to_string(int(image->mapping)));
    return;
  }
  normal.pattern = makeBumpMap(*image);
  normal.map.clear();
  normal.average = false;
  if (settings.size) normal.amount = *settings.size;
}

// `normal { [identifier] pattern [amount] modifiers… }` (POV-Ray 3.7 manual, "Normal").
void readNormalItems(const Node& n, Normal& normal, PatternDraft& draft, std::vector<TransformStep>& steps,
                     const Normal& base, ReadingContext& context) {
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    if (readTransform(n, i, steps, context)) continue;
    const bool patternNode = patternBlock(it);
    if (it.kind == Item::Kind::Node && !patternNode) {
      const std::string_view k = it.node->keyword;
      const bool blocks = normal.pattern && normal.pattern->blocks() > 0;
      if (k == "normal" && blocks && normal.map.size() < size_t(normal.pattern->blocks())) {
        normal.map.push_back({double(normal.map.size()), nestedNormal(*it.node, base, context)});
      } else if (k == "normal") {
        readNormalItems(*it.node, normal, draft, steps, base, context);  // an identifier, modified by what follows
      } else if (k == "slope_map") {
        normal.slopes.clear();
        readSlopeMap(*it.node, normal.slopes);
      } else if (k == "normal_map") {
        normal.map.clear();
        readNormalMap(*it.node, normal.map, normal.average, base, context);
      } else if (k == "bump_map") {
        readBumpMapNormal(*it.node, normal, context);
        draft = PatternDraft{};
      } else if (k == "warp") {
        if (std::shared_ptr<const Warp> warp = readWarp(*it.node, context)) draft.warps.push_back({steps.size(), warp});
      } else {
        context.refuse(it, "normal");
      }
      continue;
    }
    if (it.kind != Item::Kind::Keyword && !patternNode) {
      context.refuse(it, it.value.type == Value::Type::Function ? "function" : "a value here");
      continue;
    }
    const std::string_view w = it.word;
    // POV-Ray bends the normal by a formula of its own for facets, not by its value's slope.
    if (w == "facets") {
      context.refuse(it.loc, w);
      continue;
    }
    std::unique_ptr<Pattern> pattern = draft.start(n, i, context, normalPatternKind);
    if (!pattern) pattern = draft.start(n, i, context);
    if (pattern) {
      normal.pattern = std::move(pattern);
      normal.average = false;
      normal.wave = draft.kind->wave;
      // Without an amount the normal keeps the one it has: 0.5, or the #default normal's bump_size.
      if (const Value* amount = valueAfter(n, i)) normal.amount = amount->v[0];
      continue;
    }
    if (w == "bump_size" || w == "accuracy") {
      const Value* v = valueAfter(n, i);
      if (!v || v->type != Value::Type::Float) throw ParseError(it.loc, "'" + std::string(w) + "' needs a float");
      (w == "bump_size" ? normal.amount : normal.accuracy) = v->v[0];
    } else if (w == "average") {
      normal.pattern.reset();
      normal.map.clear();
      normal.average = true;
      draft = PatternDraft{};
    } else if (w == "no_bump_scale") {
      const Value* v = i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Value ? valueAfter(n, i) : nullptr;
      normal.bumpScale = v && v->v[0] == 0;
    } else if (!readWave(n, i, normal) && !draft.modifier(n, i, context)) {
      context.refuse(it.loc, w);
    }
  }
}

std::vector<WarpMark> readNormal(const Node& n, Normal& normal, std::vector<TransformStep>& steps,
                                 ReadingContext& context) {
  PatternDraft draft;
  Normal base = normal;
  base.pattern.reset();
  base.map.clear();
  base.average = false;
  readNormalItems(n, normal, draft, steps, base, context);
  // A normal's own formula reads its frequency and phase itself (ripples, waves).
  if (draft.kind && draft.kind == normalPatternKind(draft.kind->name)) {
    draft.args.frequency = normal.frequency;
    draft.args.phase = normal.phase;
    draft.modified = true;
  }
  draft.finish(normal.pattern, n.loc, context);
  if (normal.average && normal.map.empty()) throw ParseError(n.loc, "'average' needs a normal_map");
  if (!normal.average && !normal.map.empty() && !normal.pattern && !context.firstRefusal) {
    throw ParseError(n.loc, "a normal_map needs a pattern");
  }
  return std::move(draft.warps);
}

FinishTerms finishTerms(const PovFinish& f, const Surface& s) {
  FinishTerms t;
  t.ambient = f.ambient + f.emission;
  t.emission = f.emission;
  SurfaceExtras extras;
  extras.crand = float(f.crand);
  extras.reflectionMetallic = float(f.reflectionMetallic);
  extras.reflectionTint = f.reflectionTint;
  extras.reflectionMinTint = f.reflectionMinTint;
  extras.conserveEnergy = f.conserveEnergy;
  extras.irid = f.irid;
  // Fresnel with a single value varies from 0 (POV-Ray: `reflection { 1 fresnel }` is a dielectric's mirror).
  if (f.reflectionMin || f.reflectionFresnel) {
    extras.reflectionMin = float(f.reflectionMin.value_or(f.reflectionFresnel ? 0.0 : f.reflection));
    extras.reflectionFalloff = float(f.reflectionFalloff);
    extras.reflectionFresnel = f.reflectionFresnel;
  }
  extras.fadeDistance = s.fadePower > 0 ? float(s.fadeDistance) : 0;  // both 0 by default: no fade
  extras.fadePower = float(s.fadePower);
  extras.fadeColor = s.fadeColor;
  extras.caustics = float(s.caustics);
  extras.media = s.media;
  extras.doubleIlluminate = s.doubleIlluminate;
  if (extras.any()) t.extras = keptExtras(extras);
  t.diffuse = float(f.diffuse);
  // POV-Ray's highlights are white; `specular` has exponent 1/roughness, `phong` its phong_size.
  t.specular = Color(float(f.specular > 0 ? f.specular : f.phong));
  t.exponent = float(f.specular > 0 ? 1 / f.roughness : f.phongSize);
  t.roughness = float(f.roughness);
  t.reflection = float(f.reflection);
  t.ior = float(s.ior);
  t.brilliance = float(f.brilliance);
  t.metallic = float(f.metallic);
  t.lobe = f.specular > 0 ? Material::Lobe::HalfVector : Material::Lobe::Mirror;
  return t;
}

}  // namespace

namespace {

template <class T> void placeWarps(T& p, const std::vector<TransformStep>& steps, const std::vector<WarpMark>& warps) {
  p.fromTexture = glm::inverse(composeTransforms<double>(steps));
  p.warps.clear();
  // Undone from the last written: the transforms after the last warp, that warp, and so on back to the first.
  size_t end = steps.size();
  for (auto w = warps.rbegin(); w != warps.rend(); ++w) {
    const std::vector<TransformStep> between(steps.begin() + long(w->after), steps.begin() + long(end));
    p.warps.push_back({glm::inverse(composeTransforms<double>(between)), w->warp});
    end = w->after;
  }
  p.afterWarps = glm::inverse(composeTransforms<double>({steps.begin(), steps.begin() + long(end)}));
}

}  // namespace

void placeTransforms(Pigment& p, const std::vector<TransformStep>& steps, const std::vector<WarpMark>& warps) {
  placeWarps(p, steps, warps);
}

void placeTransforms(Normal& n, const std::vector<TransformStep>& steps, const std::vector<WarpMark>& warps) {
  placeWarps(n, steps, warps);
}

std::shared_ptr<const Pigment> nestedPigment(const Node& n, ReadingContext& context) {
  auto p = std::make_shared<Pigment>();
  std::vector<TransformStep> steps;
  const std::vector<WarpMark> warps = readPigment(n, *p, steps, context);
  placeTransforms(*p, steps, warps);
  return p;
}

std::shared_ptr<const Normal> aloneNormal(const Node& n, ReadingContext& context) {
  return nestedNormal(n, Normal{}, context);
}

std::shared_ptr<const Pigment> patternPigment(const Node& n, ReadingContext& context) {
  auto p = std::make_shared<Pigment>();
  std::vector<TransformStep> steps;
  PatternDraft draft;
  readPigmentItems(n, *p, draft, steps, context);
  draft.finish(p->pattern, n.loc, context);
  if (!p->pattern) context.refuse(n.loc, "a pattern function without a pattern");
  p->fromTexture = glm::inverse(composeTransforms<double>(steps));
  return p;
}

// An emission needs a Texture too: ambient_light scales a constant material's whole ambient term, and a
// texture's ambient alone (scene_builder's scaleAmbient).
bool Surface::patterned() const {
  const SurfaceLayer& l = layers[0];
  return layers.size() > 1 || l.pigment.pattern || l.pigment.average || l.pigment.image || l.pattern || l.normal ||
         l.finish.emission != Color(0) || inside;
}

namespace {

// Whether a texture block is a pattern of textures: a pattern keyword or a texture_map in it.
bool texturePatternIn(const Node& n) {
  return std::any_of(n.items.begin(), n.items.end(), [](const Item& it) {
    return (it.kind == Item::Kind::Keyword && patternKind(it.word)) || isFunction(it) || patternBlock(it) ||
           (it.kind == Item::Kind::Node && (it.node->keyword == "texture_map" || it.node->keyword == "tiles" ||
                                             it.node->keyword == "material_map"));
  });
}

std::shared_ptr<const Texture> subTexture(const Node& n, const Surface& defaults, ReadingContext& context) {
  Surface sub = defaults;
  readSurfaceItem(n, sub, defaults, context);
  return std::make_shared<const Texture>(bounded(makeTexture(sub, {})));
}

// The old `tiles { texture { A } tile2 texture { B } }`: checker's two blocks, B first (as POV-Ray draws it,
// the same picture as `checker texture { B } texture { A }`); false when refused.
bool readTiles(const Node& n, TexturePattern& tp, const Surface& defaults, ReadingContext& context) {
  const auto texture = [](const Item& it) { return it.kind == Item::Kind::Node && it.node->keyword == "texture"; };
  const auto tile2 = [](const Item& it) { return it.kind == Item::Kind::Keyword && it.word == "tile2"; };
  const auto split = std::find_if(n.items.begin(), n.items.end(), tile2);
  const bool written = split != n.items.begin() && split != n.items.end() && split + 1 != n.items.end() &&
                       std::all_of(n.items.begin(), split, texture) && std::all_of(split + 1, n.items.end(), texture);
  if (!written) throw ParseError(n.loc, "tiles needs 'texture { … } tile2 texture { … }'");
  if (n.items.size() != 3) {
    context.refuse(n.loc, "tiles of layered textures");
    return false;
  }
  tp.textures = {subTexture(*n.items[2].node, defaults, context), subTexture(*n.items[0].node, defaults, context)};
  return true;
}

// `material_map { "file" … TEXTURE… TRANSFORMATIONS }`: its textures, and the image's indices as the selector's
// colours; its transforms move the textures with the image, as a pattern's do.
void readMaterialMap(const Node& n, TexturePattern& tp, std::vector<TransformStep>& steps, const Surface& defaults,
                     ReadingContext& context) {
  Node image;
  image.keyword = n.keyword;
  image.loc = n.loc;
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    if (it.kind == Item::Kind::Node && it.node->keyword == "texture") {
      tp.textures.push_back(subTexture(*it.node, defaults, context));
    } else if (!readTransform(n, i, steps, context)) {
      image.items.push_back(it);
    }
  }
  if (tp.textures.empty()) throw ParseError(n.loc, "material_map needs a texture");
  tp.selector.image = readMaterialMapImage(image, tp.textures.size(), context);
}

// `texture { checker texture { … } texture { … } }` or `texture { gradient x texture_map { [v texture { … }] … } }`,
// or `texture { material_map { … } }`.
std::shared_ptr<const TexturePattern> readTexturePattern(const Node& n, const Surface& defaults, ReadingContext& context) {
  auto tp = std::make_shared<TexturePattern>();
  Pigment& selector = tp->selector;
  PatternDraft draft;
  std::vector<TransformStep> steps;
  std::vector<float> weights;
  bool average = false;
  const Node* unweighted = nullptr;  // the first texture_map entry without its value
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    if (readTransform(n, i, steps, context)) continue;
    if (it.kind == Item::Kind::Node && it.node->keyword == "texture") {
      tp->textures.push_back(subTexture(*it.node, defaults, context));
    } else if (it.kind == Item::Kind::Keyword && it.word == "average") {
      average = true;
    } else if (it.kind == Item::Kind::Node && it.node->keyword == "texture_map") {
      for (const Item& e : it.node->items) {
        // `[value texture { … }]`, or `[value pigment { … } finish { … } …]`: a texture's items written bare.
        const bool bracket = e.kind == Item::Kind::Node && e.node->keyword == "[" && !e.node->items.empty();
        const bool valued = bracket && e.node->items[0].kind == Item::Kind::Value &&
                            e.node->items[0].value.type == Value::Type::Float;
        // An average's entries may leave out their weight, which is then 1 (the POV-Ray 3.7 manual, "Average").
        if (!(valued && e.node->items.size() >= 2) && !(bracket && !valued)) {
          context.refuse(e, "a texture_map entry");
          continue;
        }
        Node body;
        body.keyword = "texture";
        body.loc = e.loc;
        body.items.assign(e.node->items.begin() + (valued ? 1 : 0), e.node->items.end());
        const double value = valued ? e.node->items[0].value.v[0] : 1.0;
        selector.map.push_back({value, solidPigment({Color(float(tp->textures.size())), 0, 0})});
        weights.push_back(float(value));
        if (!valued && !unweighted) unweighted = e.node.get();
        tp->textures.push_back(subTexture(body, defaults, context));
      }
    } else if (it.kind == Item::Kind::Node && it.node->keyword == "tiles") {
      if (readTiles(*it.node, *tp, defaults, context)) selector.pattern = makePattern(*patternKind("checker"), {});
      draft = PatternDraft{};
    } else if (it.kind == Item::Kind::Node && it.node->keyword == "material_map") {
      readMaterialMap(*it.node, *tp, steps, defaults, context);
    } else if (std::unique_ptr<Pattern> pattern = draft.start(n, i, context)) {
      selector.pattern = std::move(pattern);
      selector.wave = draft.kind->wave;
    } else if (!readWave(n, i, selector) && !draft.modifier(n, i, context)) {
      context.refuse(it, "texture");
    }
  }
  draft.finish(selector.pattern, n.loc, context);
  if (average) {
    if (selector.pattern || selector.image) throw ParseError(n.loc, "'average' takes no pattern");
    if (tp->textures.empty() || weights.size() != tp->textures.size()) {
      throw ParseError(n.loc, "'average' needs a texture_map and no other texture");
    }
    if (std::accumulate(weights.begin(), weights.end(), 0.0f) <= 0) {
      throw ParseError(n.loc, "an average's weights must add up to more than 0");
    }
    tp->weights = std::move(weights);
    selector.map.clear();
    tp->fromTexture = glm::inverse(composeTransforms<double>(steps));
    return tp;
  }
  if (unweighted) throw ParseError(unweighted->loc, "a texture_map entry needs its value before its texture");
  const int blocks = selector.pattern ? selector.pattern->blocks() : 0;
  for (int b = 0; b < blocks; ++b) selector.list.push_back(solidPigment({Color(float(b)), 0, 0}));
  if (!selector.pattern && !selector.image) {
    context.refuse(n.loc, "texture");  // its pattern or material_map was refused above
    tp->textures.assign(1, std::make_shared<const Texture>());
  } else if (selector.pattern && (tp->textures.size() < size_t(std::max(blocks, 1)) || (blocks == 0 && selector.map.empty()))) {
    throw ParseError(n.loc, "this texture pattern needs " + std::to_string(std::max(blocks, 1)) +
                                (blocks ? " textures" : " texture_map"));
  }
  tp->fromTexture = glm::inverse(composeTransforms<double>(steps));
  return tp;
}

}  // namespace

void readSurfaceItem(const Node& n, Surface& s, const Surface& defaults, ReadingContext& context) {
  const std::string_view k = n.keyword;
  // uv_mapping in a pigment, normal or texture maps the whole surface by its uv coordinates: the block is read
  // without it.
  const auto uv = [](const Item& it) { return it.kind == Item::Kind::Keyword && it.word == "uv_mapping"; };
  if ((k == "pigment" || k == "normal" || k == "texture") && std::any_of(n.items.begin(), n.items.end(), uv)) {
    Node without = n;
    without.items.erase(std::remove_if(without.items.begin(), without.items.end(), uv), without.items.end());
    s.uvMapped = true;
    readSurfaceItem(without, s, defaults, context);
    return;
  }
  SurfaceLayer& top = s.layers.back();
  if (k == "pigment") {
    const std::vector<WarpMark> warps = readPigment(n, top.pigment, top.steps, context);
    top.warps.insert(top.warps.end(), warps.begin(), warps.end());
  } else if (k == "finish") {
    readFinish(n, top.finish, context);
  } else if (k == "normal") {
    if (!top.normal) top.normal.emplace();
    const std::vector<WarpMark> warps = readNormal(n, *top.normal, top.normalSteps, context);
    top.normalWarps.insert(top.normalWarps.end(), warps.begin(), warps.end());
  } else if (k == "texture" && texturePatternIn(n)) {
    top.pattern = readTexturePattern(n, defaults, context);
  } else if (k == "texture" || k == "material") {
    // A transform moves every layer the block has read so far (a layered texture identifier's too), and the
    // normals they have by then.
    const size_t first = s.layers.size() - 1;
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      std::vector<TransformStep> steps;
      if (it.kind == Item::Kind::Node) {
        readSurfaceItem(*it.node, s, defaults, context);
      } else if (!readTransform(n, i, steps, context)) {
        context.refuse(it, k);
      }
      for (size_t l = first; l < s.layers.size(); ++l) {
        SurfaceLayer& layer = s.layers[l];
        layer.steps.insert(layer.steps.end(), steps.begin(), steps.end());
        if (layer.normal) layer.normalSteps.insert(layer.normalSteps.end(), steps.begin(), steps.end());
      }
    }
  } else if (k == "layered texture") {
    // Each layer starts as the #default texture, on top of the ones before.
    for (size_t i = 0; i < n.items.size(); ++i) {
      if (i > 0) s.layers.push_back(defaults.layers.back());
      readSurfaceItem(*n.items[i].node, s, defaults, context);
    }
  } else if (k == "interior") {
    for (size_t i = 0; i < n.items.size(); ++i) {
      const Item& it = n.items[i];
      const bool known = it.kind == Item::Kind::Keyword &&
                         (it.word == "ior" || it.word == "fade_distance" || it.word == "fade_power" ||
                          it.word == "fade_color" || it.word == "caustics");
      const Value* v = known ? valueAfter(n, i) : nullptr;
      if (v && v->numeric() && it.word == "fade_color") {
        s.fadeColor = colourOf(*v).rgb;
      } else if (v && v->type == Value::Type::Float) {
        (it.word == "ior"             ? s.ior
         : it.word == "fade_distance" ? s.fadeDistance
         : it.word == "caustics"      ? s.caustics
                                      : s.fadePower) = v->v[0];
      } else if (it.kind == Item::Kind::Node && it.node->keyword == "interior") {
        readSurfaceItem(*it.node, s, defaults, context);
      } else if (it.kind == Item::Kind::Node && it.node->keyword == "media") {
        if (std::optional<Media> media = readMedia(*it.node, context)) s.media.push_back(std::move(*media));
      } else {
        context.refuse(it, "interior");
      }
    }
  } else {
    context.refuse(n.loc, k);
  }
}

FinishTerms topTerms(const Surface& s) { return finishTerms(s.layers.back().finish, s); }

Material constantMaterial(const Surface& s) { return layerMaterial(topTerms(s), s.layers.back().pigment.solid); }

Finish writtenFinish(const Surface& s) {
  const PovFinish& f = s.layers.back().finish;
  Finish w;
  w.ambient = (f.ambient.r + f.ambient.g + f.ambient.b) / 3;
  w.diffuse = f.diffuse;
  w.specular = f.specular > 0 ? f.specular : f.phong;
  w.roughness = f.roughness;
  w.reflection = f.reflection;
  w.ior = s.ior;
  return w;
}

Texture makeTexture(const Surface& s, const std::vector<TransformStep>& after) {
  Texture t;
  for (const SurfaceLayer& layer : s.layers) {
    auto p = std::make_shared<Pigment>(layer.pigment);
    placeTransforms(*p, layer.steps, layer.warps);
    std::shared_ptr<Normal> normal;
    if (layer.normal && (layer.normal->pattern || layer.normal->average)) {
      normal = std::make_shared<Normal>(*layer.normal);
      placeTransforms(*normal, layer.normalSteps, layer.normalWarps);
    }
    t.layers.push_back({p, finishTerms(layer.finish, s), layer.pattern, std::move(normal)});
  }
  t.fromWorld = glm::inverse(composeTransforms<double>(after));
  t.uvMapped = s.uvMapped;
  if (s.inside) t.interior = std::make_shared<const Texture>(bounded(makeTexture(*s.inside, after)));
  return t;
}

}  // namespace rt::povray
