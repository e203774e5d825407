// `light_source { … }` (POV-Ray 3.7 manual, "Light Sources"): a point light, or one of the emitter kinds of
// lightKinds() (scene/light_kind.hpp), with the parallel, area, fading, shadowless and projected_through
// modifiers; what else a light may say is refused.
#include "raytrace/parse/povray/light_reader.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "raytrace/util/error.hpp"

namespace rt::povray {

namespace {

// `area_light <axis1>, <axis2>, size1, size2` after the word at i.
AreaDesc areaLight(const Node& n, size_t& i, AreaDesc area) {
  const Item& word = n.items[i];
  const Value* v[4];
  for (const Value*& value : v) {
    value = valueAfter(n, i);
    if (!value || !value->numeric()) throw ParseError(word.loc, "'area_light' needs two axes and two sizes");
  }
  area.axis1 = vec3(*v[0]);
  area.axis2 = vec3(*v[1]);
  area.size1 = std::max(1, int(v[2]->v[0]));
  area.size2 = std::max(1, int(v[3]->v[0]));
  return area;
}

}  // namespace

void readLight(const Node& n, LightDesc& l, ReadingContext& context, const LooksLike& looksLikeAt,
               const ProjectedThrough& projectedThrough) {
  size_t i = 0;
  if (i < n.items.size() && n.items[i].kind == Item::Kind::Node && n.items[i].node->keyword == "light_source") {
    readLight(*n.items[i++].node, l, context, looksLikeAt, projectedThrough);
  }
  if (i < n.items.size() && n.items[i].kind == Item::Kind::Value) l.position = vec3(n.items[i++].value);
  if (i < n.items.size() && n.items[i].kind == Item::Kind::Value) l.color = colourOf(n.items[i++].value).rgb;
  std::vector<TransformStep> steps;
  // The cone's values may come before `spotlight`, and mean nothing to a light that is not one.
  bool isSpot = l.spot.has_value(), parallel = l.parallelTo != nullptr;
  SpotDesc spot = l.spot.value_or(SpotDesc{});
  if (l.parallelTo) spot.pointAt = *l.parallelTo;
  // The grid's modifiers may come before `area_light`, and mean nothing to a light without one.
  AreaDesc grid = l.area ? *l.area : AreaDesc{};
  bool isArea = l.area != nullptr;
  const Item* circular = nullptr;
  std::optional<double> radius, falloff;
  const Item* tightness = nullptr;
  const Node* looksLike = nullptr;
  const Node* through = nullptr;
  std::optional<bool> illumination;
  for (; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    if (readTransform(n, i, steps, context)) continue;
    if (it.kind == Item::Kind::Node && it.node->keyword == "looks_like") {
      looksLike = it.node.get();
      continue;
    }
    if (it.kind == Item::Kind::Node && it.node->keyword == "projected_through") {
      through = it.node.get();
      continue;
    }
    if (it.kind != Item::Kind::Keyword) {
      context.refuse(it, "light_source");
      continue;
    }
    const std::string_view w = it.word;
    if (w == "media_interaction" || w == "media_attenuation") {
      const Value* v = valueAfter(n, i);
      (w == "media_interaction" ? l.mediaInteraction : l.mediaAttenuation) = !v || v->v[0] != 0;
    } else if (w == "shadowless") {
      l.shadowless = true;
    } else if (const LightKind* kind = lightKindNamed(w)) {
      isSpot = true;
      spot.kind = kind;
    } else if (w == "parallel") {
      parallel = true;
    } else if (w == "area_light") {
      grid = areaLight(n, i, grid);
      isArea = true;
    } else if (w == "jitter" || w == "circular" || w == "orient") {
      (w == "jitter" ? grid.jitter : w == "circular" ? grid.circular : grid.orient) = true;
      if (w == "circular") circular = &it;
    } else if (w == "area_illumination") {
      // On (the word alone, or a value other than 0): each grid point lights from its own direction; a light
      // without a grid is one point, which lights the same either way.
      const Value* v = valueAfter(n, i);
      illumination = !v || v->v[0] != 0;
    } else if (w == "point_at" || w == "radius" || w == "falloff" || w == "tightness" || w == "fade_distance" ||
               w == "fade_power" || w == "adaptive") {
      const Value* v = valueAfter(n, i);
      if (!v || !v->numeric()) throw ParseError(it.loc, "'" + std::string(w) + "' needs a value");
      if (w == "point_at") spot.pointAt = vec3(*v);
      else if (w == "radius") radius = v->v[0];
      else if (w == "falloff") falloff = v->v[0];
      else if (w == "tightness") spot.tightness = v->v[0], tightness = &it;
      else if (w == "fade_distance") l.fadeDistance = v->v[0];
      else if (w == "adaptive") grid.adaptive = std::max(0, int(v->v[0]));
      else l.fadePower = v->v[0];
    } else {
      context.refuse(it.loc, w);
    }
  }
  // A new emitter's radius and falloff are its kind's unless given; a light_source copied keeps its own.
  spot.radius = radius.value_or(isSpot && !l.spot ? spot.kind->defaultRadius : spot.radius);
  spot.falloff = falloff.value_or(isSpot && !l.spot ? spot.kind->defaultFalloff : spot.falloff);
  if (!spot.kind->tightness && spot.tightness != 0 && tightness) {
    context.refuse(tightness->loc, "a " + std::string(spot.kind->keyword) + " light's tightness");
  }
  if (isSpot) l.spot = spot;
  if (parallel) l.parallelTo = std::make_shared<const glm::dvec3>(spot.pointAt);
  // As POV-Ray: a circular grid needs points to place on its circle.
  if (circular && (!isArea || grid.size1 < 2 || grid.size2 < 2)) {
    throw ParseError(circular->loc, "'circular' needs an area_light of more than one point along each axis");
  }
  if (isArea && illumination) grid.illumination = *illumination;
  if (isArea) l.area = std::make_shared<const AreaDesc>(grid);
  if (looksLike) looksLikeAt(*looksLike, l.position, steps);
  if (through && !steps.empty()) context.refuse(n.loc, "projected_through in a light with transforms");
  if (through) projectedThrough(*through);
  moveLight(l, composeTransforms<double>(steps));
}

void moveLight(LightDesc& l, const glm::dmat4& m) {
  l.position = glm::dvec3(m * glm::dvec4(l.position, 1));
  if (l.spot) l.spot->pointAt = glm::dvec3(m * glm::dvec4(l.spot->pointAt, 1));
  if (l.parallelTo) l.parallelTo = std::make_shared<const glm::dvec3>(m * glm::dvec4(*l.parallelTo, 1));
  if (l.area) {
    AreaDesc a = *l.area;
    a.axis1 = glm::dvec3(m * glm::dvec4(a.axis1, 0));
    a.axis2 = glm::dvec3(m * glm::dvec4(a.axis2, 0));
    l.area = std::make_shared<const AreaDesc>(a);
  }
}

}  // namespace rt::povray
