#include "raytrace/surface/texture.hpp"

#include <algorithm>

namespace rt {

Material layerMaterial(const FinishTerms& f, const Rgbft& c) {
  Material m;
  m.pigment = c.rgb;
  m.filter = c.filter;
  m.ambient = f.ambient * c.rgb;
  m.diffuse = f.diffuse * c.rgb;
  // POV-Ray's metallic highlight takes the pigment's colour; its empirical change toward white at grazing
  // angles is not modelled (docs/povray-language.md, "Finish").
  m.specular = f.specular * (Color(1) + f.metallic * (c.rgb - Color(1)));
  m.exponent = f.exponent;
  m.roughness = f.roughness;
  m.reflection = f.reflection;
  m.ior = f.ior;
  m.brilliance = f.brilliance;
  m.lobe = f.lobe;
  return m;
}

namespace {

Color largest(const Color& a, const Color& b) { return glm::max(a, b); }

}  // namespace

Texture bounded(Texture t) {
  Material& b = t.bound;
  b = Material{};
  b.exponent = 0;
  for (const TextureLayer& layer : t.layers) {
    anyColour(*layer.pigment, [&](const Rgbft& c) {
      const Material m = layerMaterial(layer.finish, c);
      b.pigment = largest(b.pigment, m.pigment);
      b.filter = std::max(b.filter, m.filter);
      b.ambient = largest(b.ambient, m.ambient);
      b.diffuse = largest(b.diffuse, m.diffuse);
      b.specular = largest(b.specular, m.specular);
      b.reflection = std::max(b.reflection, m.reflection);
      b.roughness = m.roughness;
      b.exponent = m.exponent;
      b.ior = m.ior;
      b.brilliance = m.brilliance;
      return false;
    });
  }
  return t;
}

// Each layer covers the ones below it except where its filter and transmit let them through: filtered light
// takes the layer's colour, transmitted light does not (POV-Ray 3.7 manual, "Layered Textures").
Material Texture::at(const glm::dvec3& point) const {
  const glm::dvec3 p = glm::dvec3(fromWorld * glm::dvec4(point, 1));
  Material m;
  for (size_t i = 0; i < layers.size(); ++i) {
    const Rgbft c = layers[i].pigment->at(p);
    const Material top = layerMaterial(layers[i].finish, c);
    if (i == 0) {
      m = top;
      continue;
    }
    const Color through = c.filter * c.rgb + Color(c.transmit);
    const float cover = 1 - c.filter - c.transmit;
    m.ambient = top.ambient * cover + m.ambient * through;
    m.diffuse = top.diffuse * cover + m.diffuse * through;
    m.specular = top.specular * cover + m.specular * through;
    m.pigment = top.pigment * cover + m.pigment * through;
    m.filter *= c.filter + c.transmit;
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

}  // namespace rt
