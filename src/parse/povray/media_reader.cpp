// `media { absorption C  emission C  scattering { … }  intervals N  samples MIN[, MAX]  method 3  aa_level N
// aa_threshold X  density { … } }` in an interior (POV-Ray 3.7 manual, "Media" and "Density"); the other
// sampling methods are refused.
#include <algorithm>

#include "raytrace/parse/povray/surface_reader.hpp"

namespace rt::povray {

namespace {

// A density block is written as a pigment is, with density_map and nested densities for pigment_map and
// pigments: the same node with those keywords renamed, read by the pigment reader.
std::shared_ptr<const Node> asPigment(const Node& n) {
  auto out = std::make_shared<Node>(n);
  if (n.keyword == "density") out->keyword = "pigment";
  if (n.keyword == "density_map") out->keyword = "pigment_map";
  for (Item& it : out->items) {
    if (it.kind == Item::Kind::Node) it.node = asPigment(*it.node);
  }
  return out;
}

// `density { … }`. Unlike a pigment's, a density's defaults are white and, for a pattern without a map, a
// ramp from black at 0 to white at 1 (POV-Ray 3.7 manual, "Density").
std::shared_ptr<const Pigment> readDensity(const Node& n, ReadingContext& context) {
  const std::shared_ptr<const Node> body = asPigment(n);
  auto p = std::make_shared<Pigment>(*nestedPigment(*body, context));
  const bool coloured = std::any_of(body->items.begin(), body->items.end(), [](const Item& it) {
    return (it.kind == Item::Kind::Value && it.value.numeric()) || (it.kind == Item::Kind::Node && it.node->keyword == "pigment");
  });
  if (!p->pattern && !p->average && !p->image && !coloured) p->solid.rgb = Color(1);
  if (p->pattern && p->pattern->blocks() == 0 && p->map.empty()) {
    auto grey = [](float v) {
      auto g = std::make_shared<Pigment>();
      g->solid.rgb = Color(v);
      return std::shared_ptr<const Pigment>(g);
    };
    p->map = {{0, grey(0)}, {1, grey(1)}};
  }
  return p;
}

// `scattering { type, colour [eccentricity e] [extinction x] }` (POV-Ray 3.7 manual, "Scattering").
Scattering readScattering(const Node& n) {
  Scattering out;
  size_t values = 0;
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    if (it.kind == Item::Kind::Value && values == 0) {
      if (it.value.type != Value::Type::Float || it.value.v[0] < 1 || it.value.v[0] >= 6) {
        throw ParseError(it.loc, "'scattering' needs a type from 1 to 5");
      }
      out.type = int(it.value.v[0]);
      ++values;
    } else if (it.kind == Item::Kind::Value && values == 1 && it.value.numeric()) {
      out.color = colourOf(it.value).rgb;
      ++values;
    } else if (it.kind == Item::Kind::Keyword && (it.word == "eccentricity" || it.word == "extinction")) {
      const Value* v = valueAfter(n, i);
      if (!v || v->type != Value::Type::Float) throw ParseError(it.loc, "'" + std::string(it.word) + "' needs a number");
      (it.word == "eccentricity" ? out.eccentricity : out.extinction) = v->v[0];
    } else {
      throw ParseError(it.loc, "'scattering' takes a type, a colour, eccentricity and extinction");
    }
  }
  if (values < 2) throw ParseError(n.loc, "'scattering' needs a type and a colour");
  return out;
}

}  // namespace

std::optional<Media> readMedia(const Node& n, ReadingContext& context) {
  Media media;
  bool refused = false;
  const auto refuse = [&](const SourceLoc& loc, std::string_view what) {
    context.refuse(loc, what);
    refused = true;
  };
  // The value after item i (i moves onto it), which follows the keyword `key`.
  const auto value = [&](size_t& i, const Item& key, const char* what) -> const Value& {
    const Value* v = valueAfter(n, i);
    if (!v || !v->numeric()) throw ParseError(key.loc, "'" + std::string(key.word) + "' needs " + what);
    return *v;
  };
  const auto number = [&](size_t& i, const Item& key, const char* what) {
    const Value& v = value(i, key, what);
    if (v.type != Value::Type::Float) throw ParseError(key.loc, "'" + std::string(key.word) + "' needs " + what);
    return v.v[0];
  };
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    if (it.kind == Item::Kind::Node && it.node->keyword == "media") {
      // A declared medium, which the rest of the block modifies.
      const std::optional<Media> declared = readMedia(*it.node, context);
      if (declared) media = *declared;
      refused = refused || !declared;
      continue;
    }
    if (it.kind == Item::Kind::Node && it.node->keyword == "density") {
      media.densities.push_back(readDensity(*it.node, context));
      continue;
    }
    if (it.kind == Item::Kind::Node && it.node->keyword == "scattering") {
      media.scattering = readScattering(*it.node);
      continue;
    }
    if (it.kind != Item::Kind::Keyword) {
      refuse(it.loc, it.kind == Item::Kind::Node ? std::string(it.node->keyword) : "a value in media");
      continue;
    }
    const std::string_view w = it.word;
    if (w == "absorption" || w == "emission") {
      (w == "absorption" ? media.absorption : media.emission) = colourOf(value(i, it, "a colour")).rgb;
    } else if (w == "samples") {
      const double least = number(i, it, "a number of samples");
      if (least < 1) throw ParseError(it.loc, "'samples' needs at least 1");
      media.samples = int(least);
      // The maximum: method 3 takes only the minimum.
      if (i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Value) ++i;
    } else if (w == "intervals") {
      const double intervals = number(i, it, "a number of intervals");
      if (intervals < 1) throw ParseError(it.loc, "'intervals' needs at least 1");
      media.intervals = int(intervals);
    } else if (w == "aa_level") {
      const double level = number(i, it, "a number of levels");
      if (level < 1) throw ParseError(it.loc, "'aa_level' needs at least 1");
      media.aaLevel = int(level);
    } else if (w == "aa_threshold") {
      media.aaThreshold = number(i, it, "a threshold");
    } else if (w == "method") {
      if (number(i, it, "1, 2 or 3") != 3) refuse(it.loc, "media method other than 3");
    } else {
      refuse(it.loc, w);
    }
  }
  if (refused) return std::nullopt;
  return media;
}

}  // namespace rt::povray
