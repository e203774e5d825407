// `warp { … }` (POV-Ray 3.7 manual, "Warp"): one kind a row of kWarps, its own items after its keyword.
#include <cmath>

#include "raytrace/parse/povray/surface_reader.hpp"

namespace rt::povray {

namespace {

// Reads a warp's items: its keyword at n.items[0] and what follows.
class WarpItems {
 public:
  WarpItems(const Node& n, ReadingContext& context) : n_(n), context_(context) {}

  // The value after item i as a vector (a float promoted), or a float; i moves onto it.
  glm::dvec3 vector(size_t& i) { return vec3(value(i, "a float or a vector")); }
  double number(size_t& i) {
    const Value& v = value(i, "a float");
    if (v.type != Value::Type::Float) throw ParseError(n_.items[i].loc, "'" + key_ + "' needs a float");
    return v.v[0];
  }
  // Calls item(word, i) for each keyword after the warp's own; refuses what it does not take (item false).
  template <class F> void rest(size_t i, F item) {
    for (++i; i < n_.items.size(); ++i) {
      const Item& it = n_.items[i];
      if (it.kind != Item::Kind::Keyword || !item(it.word, i)) refuse(it);
    }
  }
  void refuse(const Item& it) {
    context_.refuse(it, "a value in a warp");
    refused_ = true;
  }
  bool refused() const { return refused_; }
  const Node& node() const { return n_; }

 private:
  const Value& value(size_t& i, const char* what) {
    key_ = std::string(n_.items[i].word);
    const SourceLoc& loc = n_.items[i].loc;
    const Value* v = valueAfter(n_, i);
    if (!v || !v->numeric()) throw ParseError(loc, "'" + key_ + "' needs " + what);
    return *v;
  }

  const Node& n_;
  ReadingContext& context_;
  std::string key_;
  bool refused_ = false;
};

std::shared_ptr<const Warp> turbulence(WarpItems& r) {
  Turbulence t;
  const Node& n = r.node();
  for (size_t i = 0; i < n.items.size(); ++i) {
    if (!readTurbulence(n, i, t)) r.refuse(n.items[i]);
  }
  return t.on() ? makeTurbulenceWarp(t) : nullptr;
}

// `repeat W [offset O] [flip F]`: W along one axis.
std::shared_ptr<const Warp> repeat(WarpItems& r) {
  size_t i = 0;
  const glm::dvec3 w = r.vector(i);
  const int axes = (w.x != 0) + (w.y != 0) + (w.z != 0);
  if (axes != 1) throw ParseError(r.node().items[0].loc, "a repeat warp's vector must lie along one axis");
  RepeatWarpArgs a;
  a.axis = w.x != 0 ? 0 : w.y != 0 ? 1 : 2;
  a.width = w[a.axis];
  r.rest(i, [&](std::string_view word, size_t& k) {
    if (word == "offset") a.offset = r.vector(k);
    if (word == "flip") a.flip = glm::notEqual(r.vector(k), glm::dvec3(0));
    return word == "offset" || word == "flip";
  });
  return makeRepeatWarp(a);
}

// `black_hole C, R [falloff F] [strength S] [inverse] [repeat V] [turbulence T]`.
std::shared_ptr<const Warp> blackHole(WarpItems& r) {
  size_t i = 0;
  BlackHoleArgs a;
  a.centre = r.vector(i);
  a.radius = r.number(i);
  if (!(a.radius > 0)) throw ParseError(r.node().items[0].loc, "a black hole's radius must be greater than 0");
  r.rest(i, [&](std::string_view word, size_t& k) {
    if (word == "falloff") a.falloff = r.number(k);
    if (word == "strength") a.strength = r.number(k);
    if (word == "repeat") a.repeat = r.vector(k);
    if (word == "inverse") a.inverse = true;
    if (word == "turbulence") a.turbulence = r.vector(k);
    return word == "falloff" || word == "strength" || word == "repeat" || word == "inverse" || word == "turbulence";
  });
  return makeBlackHoleWarp(a);
}

// `planar [N, D]`: by default the x-y plane.
std::shared_ptr<const Warp> planar(WarpItems& r) {
  size_t i = 0;
  glm::dvec3 normal(0, 0, 1);
  double distance = 0;
  if (i + 1 < r.node().items.size() && r.node().items[1].kind == Item::Kind::Value) {
    normal = r.vector(i);
    distance = r.number(i);
    if (!(glm::length(normal) > 0)) throw ParseError(r.node().items[0].loc, "a planar warp's normal is zero");
  }
  r.rest(i, [](std::string_view, size_t&) { return false; });
  return makePlanarWarp(glm::normalize(normal), distance);
}

// `cylindrical`, `spherical`, `toroidal`: `orientation O`, `dist_exp E`, and the toroidal's `major_radius R`.
MappingWarpArgs mappingArgs(WarpItems& r, bool toroidal) {
  MappingWarpArgs a;
  r.rest(0, [&](std::string_view word, size_t& k) {
    if (word == "orientation") {
      const SourceLoc& loc = r.node().items[k].loc;
      a.orientation = r.vector(k);
      if (!(glm::length(a.orientation) > 0)) throw ParseError(loc, "a warp's orientation is zero");
      a.orientation = glm::normalize(a.orientation);
    }
    if (word == "dist_exp") a.distExp = r.number(k);
    if (word == "major_radius") {
      if (!toroidal) throw ParseError(r.node().items[k].loc, "only a toroidal warp takes 'major_radius'");
      a.majorRadius = r.number(k);
    }
    return word == "orientation" || word == "dist_exp" || word == "major_radius";
  });
  return a;
}

std::shared_ptr<const Warp> cylindrical(WarpItems& r) { return makeCylindricalWarp(mappingArgs(r, false)); }
std::shared_ptr<const Warp> spherical(WarpItems& r) { return makeSphericalWarp(mappingArgs(r, false)); }
std::shared_ptr<const Warp> toroidal(WarpItems& r) { return makeToroidalWarp(mappingArgs(r, true)); }

std::shared_ptr<const Warp> cubic(WarpItems& r) {
  r.rest(0, [](std::string_view, size_t&) { return false; });
  return makeCubicWarp();
}

struct WarpKind {
  std::string_view name;
  std::shared_ptr<const Warp> (*read)(WarpItems&);
};

constexpr WarpKind kWarps[] = {
    {"turbulence", turbulence}, {"octaves", turbulence}, {"omega", turbulence}, {"lambda", turbulence},
    {"repeat", repeat},         {"black_hole", blackHole}, {"planar", planar},         {"cylindrical", cylindrical},
    {"spherical", spherical},   {"toroidal", toroidal},    {"cubic", cubic},
};

}  // namespace

std::shared_ptr<const Warp> readWarp(const Node& n, ReadingContext& context) {
  if (n.items.empty() || n.items[0].kind != Item::Kind::Keyword) {
    throw ParseError(n.loc, "a warp needs its kind: turbulence, repeat, black_hole, planar, …");
  }
  for (const WarpKind& kind : kWarps) {
    if (kind.name != n.items[0].word) continue;
    WarpItems items(n, context);
    std::shared_ptr<const Warp> warp = kind.read(items);
    return items.refused() ? nullptr : warp;
  }
  context.refuse(n.items[0], "warp");
  return nullptr;
}

}  // namespace rt::povray
