#include "raytrace/surface/texture.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>

namespace rt {

const SurfaceExtras* keptExtras(const SurfaceExtras& extras) {
  static std::mutex mutex;
  static std::deque<SurfaceExtras> kept;  // a deque never moves what it holds
  const std::lock_guard<std::mutex> lock(mutex);
  return &kept.emplace_back(extras);
}

Material layerMaterial(const FinishTerms& f, const Rgbft& c) {
  Material m;
  // The light let through is filter·C + transmit: the tracer's transmitted share is f + t, tinted by `pigment`.
  const float through = c.filter + c.transmit;
  m.pigment = through != 0 ? (c.filter * c.rgb + Color(c.transmit)) / through : c.rgb;
  m.filter = through;
  m.ambient = f.ambient * c.rgb;
  m.diffuse = f.diffuse * c.rgb;
  // POV-Ray's metallic highlight takes the pigment's colour; its empirical change toward white at grazing
  // angles is not modelled (docs/povray-language.md, "Textures").
  m.specular = f.specular * (Color(1) + f.metallic * (c.rgb - Color(1)));
  m.exponent = f.exponent;
  m.roughness = f.roughness;
  m.reflection = f.reflection;
  m.ior = f.ior;
  m.brilliance = f.brilliance;
  m.lobe = f.lobe;
  m.extras = f.extras;
  return m;
}

namespace {

// Whether a normal's pattern, or one of its map's normals, reads the surface's normal (slope).
bool readsNormal(const Normal& n) {
  if (n.pattern && n.pattern->readsNormal()) return true;
  return std::any_of(n.map.begin(), n.map.end(), [](const NormalEntry& e) { return readsNormal(*e.normal); });
}

}  // namespace

Texture bounded(Texture t) {
  Material& b = t.bound;
  b = Material{};
  b.exponent = 0;
  const auto take = [&b](const Material& m) {
    b.pigment = glm::max(b.pigment, m.pigment);
    b.filter = std::max(b.filter, std::abs(m.filter));  // POV-Ray draws a filter below 0 as written
    b.ambient = glm::max(b.ambient, m.ambient);
    b.diffuse = glm::max(b.diffuse, m.diffuse);
    b.specular = glm::max(b.specular, m.specular);
    b.reflection = std::max({b.reflection, m.reflection, m.extras->reflectionMin});  // a variable reflection reaches either
    b.roughness = m.roughness;
    b.exponent = m.exponent;
    b.ior = m.ior;
    b.brilliance = m.brilliance;
  };
  for (const TextureLayer& layer : t.layers) {
    t.bumpy = t.bumpy || layer.normal;
    t.readsNormal = t.readsNormal || (layer.normal && readsNormal(*layer.normal));
    if (layer.pattern) {
      t.readsNormal = t.readsNormal || readsNormal(layer.pattern->selector);
      for (const auto& sub : layer.pattern->textures) {
        take(sub->bound);
        t.bumpy = t.bumpy || sub->bumpy;
        t.readsNormal = t.readsNormal || sub->readsNormal;
      }
      continue;
    }
    t.readsNormal = t.readsNormal || readsNormal(*layer.pigment);
    anyColour(*layer.pigment, [&](const Rgbft& c) {
      take(layerMaterial(layer.finish, c));
      return false;
    });
  }
  if (t.interior) {
    take(t.interior->bound);
    t.bumpy = t.bumpy || t.interior->bumpy;
    t.readsNormal = t.readsNormal || t.interior->readsNormal;
  }
  return t;
}

namespace {

// a at t = 0, b at t = 1: the colour terms blended, the others taken from the nearer.
Material blend(const Material& a, const Material& b, float t) {
  Material m = t < 0.5f ? a : b;
  const auto lerp = [t](const Color& x, const Color& y) { return x + (y - x) * t; };
  m.pigment = lerp(a.pigment, b.pigment);
  m.ambient = lerp(a.ambient, b.ambient);
  m.diffuse = lerp(a.diffuse, b.diffuse);
  m.specular = lerp(a.specular, b.specular);
  m.filter = a.filter + (b.filter - a.filter) * t;
  m.reflection = a.reflection + (b.reflection - a.reflection) * t;
  return m;
}

// Which of a texture pattern's textures q (in the pattern's space) takes, and how far toward the next one.
std::pair<size_t, float> entryAt(const TexturePattern& tp, const glm::dvec3& q) {
  const double v = tp.selector.at(q).rgb.r;
  const size_t last = tp.textures.size() - 1;
  const size_t lo = std::min(size_t(std::max(0.0, std::floor(v))), last);
  return {lo, lo < last ? float(v - double(lo)) : 0.0f};
}

// An average's textures at q, their colour terms weighted; the terms that are not colours come from the heaviest
// entry, the highlight's shape from the heaviest that has a highlight.
Material averaged(const TexturePattern& tp, const glm::dvec3& q) {
  float sum = 0;
  for (float w : tp.weights) sum += w;
  Material m, shiniest;
  Color pigment(0), ambient(0), diffuse(0), specular(0);
  float filter = 0, reflection = 0, heaviest = -1, brightest = 0;
  for (size_t i = 0; i < tp.textures.size(); ++i) {
    const Material e = tp.textures[i]->at(q);
    const float w = tp.weights[i] / sum;
    if (tp.weights[i] > heaviest) m = e, heaviest = tp.weights[i];
    const float shine = w * (e.specular.r + e.specular.g + e.specular.b);
    if (shine > brightest) shiniest = e, brightest = shine;
    pigment += w * e.pigment, ambient += w * e.ambient, diffuse += w * e.diffuse, specular += w * e.specular;
    filter += w * e.filter, reflection += w * e.reflection;
  }
  m.pigment = pigment, m.ambient = ambient, m.diffuse = diffuse, m.specular = specular;
  m.filter = filter, m.reflection = reflection;
  if (brightest > 0) m.exponent = shiniest.exponent, m.roughness = shiniest.roughness, m.lobe = shiniest.lobe;
  return m;
}

// The texture a texture pattern gives at p.
Material patterned(const TexturePattern& tp, const glm::dvec3& p) {
  const glm::dvec3 q = glm::dvec3(tp.fromTexture * glm::dvec4(p, 1));
  if (!tp.weights.empty()) return averaged(tp, q);
  const auto [lo, t] = entryAt(tp, q);
  const Material a = tp.textures[lo]->at(q);
  return t > 0 ? blend(a, tp.textures[lo + 1]->at(q), t) : a;
}

// The normal a texture pattern gives at p: its textures' bent normals, blended as their colours are.
glm::dvec3 patternedNormal(const TexturePattern& tp, const glm::dvec3& p, const glm::dmat3& toTexture, const glm::dvec3& n) {
  const glm::dvec3 q = glm::dvec3(tp.fromTexture * glm::dvec4(p, 1));
  const glm::dmat3 toPattern = glm::dmat3(tp.fromTexture) * toTexture;
  const auto bentBy = [&](const Texture& sub) {
    return sub.bumpy ? sub.bentInSpace(glm::dvec3(sub.fromWorld * glm::dvec4(q, 1)), glm::dmat3(sub.fromWorld) * toPattern, n) : n;
  };
  if (!tp.weights.empty()) {
    float sum = 0;
    glm::dvec3 total(0);
    for (size_t i = 0; i < tp.textures.size(); ++i) {
      total += double(tp.weights[i]) * bentBy(*tp.textures[i]);
      sum += tp.weights[i];
    }
    return glm::normalize(total / double(sum));
  }
  const auto [lo, t] = entryAt(tp, q);
  const glm::dvec3 a = bentBy(*tp.textures[lo]);
  return t > 0 ? glm::normalize(a + (bentBy(*tp.textures[lo + 1]) - a) * double(t)) : a;
}

}  // namespace

// Each layer covers the ones below it except where its filter and transmit let them through: filtered light
// takes the layer's colour, transmitted light does not (POV-Ray 3.7 manual, "Layered Textures").
Material Texture::inSpace(const glm::dvec3& p) const {
  Material m;
  for (size_t i = 0; i < layers.size(); ++i) {
    const TextureLayer& layer = layers[i];
    Rgbft c;
    Material top;
    if (layer.pattern) {
      top = patterned(*layer.pattern, p);
      c = {top.pigment, top.filter, 0};
    } else {
      c = layer.pigment->at(p);
      top = layerMaterial(layer.finish, c);
    }
    if (i == 0) {
      m = top;
      continue;
    }
    const Color through = c.filter * c.rgb + Color(c.transmit);
    const float cover = 1 - c.filter - c.transmit;
    m.ambient = top.ambient * cover + m.ambient * through;
    m.diffuse = top.diffuse * cover + m.diffuse * through;
    m.specular = top.specular * cover + m.specular * through;
    // Light through the whole stack is let through by each layer: `pigment` is the tint of that light.
    const float open = c.filter + c.transmit;
    if (open > 0) m.pigment *= through / open;
    m.filter *= open;
    if (cover > 0.5f) {
      m.exponent = top.exponent;
      m.roughness = top.roughness;
      m.brilliance = top.brilliance;
      m.lobe = top.lobe;
    }
    m.reflection = top.reflection * cover + m.reflection * (c.filter + c.transmit);
  }
  return m;
}

// POV-Ray lights each layer with its own normal; one normal serves the whole stack here, the top layer's that
// has one (docs/povray-language.md, "Normals").
glm::dvec3 Texture::bentInSpace(const glm::dvec3& p, const glm::dmat3& toTexture, const glm::dvec3& n) const {
  for (auto layer = layers.rbegin(); layer != layers.rend(); ++layer) {
    if (layer->normal) return layer->normal->bent(n, p, toTexture);
    if (layer->pattern && std::any_of(layer->pattern->textures.begin(), layer->pattern->textures.end(),
                                      [](const auto& sub) { return sub->bumpy; })) {
      return patternedNormal(*layer->pattern, p, toTexture, n);
    }
  }
  return n;
}

}  // namespace rt
