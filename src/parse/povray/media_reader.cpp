// `media { absorption C  emission C  intervals N  samples MIN[, MAX]  method 3 }` in an interior (POV-Ray 3.7
// manual, "Media"): a homogeneous medium without scattering; density, scattering and the other sampling
// methods are refused.
#include "raytrace/parse/povray/surface_reader.hpp"

namespace rt::povray {

std::optional<Media> readMedia(const Node& n, Refusals& refusals) {
  Media media;
  bool refused = false;
  const auto refuse = [&](const SourceLoc& loc, std::string_view what) {
    refusals.refuse(loc, what);
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
      const std::optional<Media> declared = readMedia(*it.node, refusals);
      if (declared) media = *declared;
      refused = refused || !declared;
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
      if (number(i, it, "a number of intervals") < 1) throw ParseError(it.loc, "'intervals' needs at least 1");
    } else if (w == "method") {
      if (number(i, it, "1, 2 or 3") != 3) refuse(it.loc, "media method other than 3");
    } else {
      refuse(it.loc, w);
    }
  }
  if (refused) return std::nullopt;
  refusals.media = true;
  return media;
}

}  // namespace rt::povray
