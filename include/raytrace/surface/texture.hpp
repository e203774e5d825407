// A texture as shading reads it at a hit: layers of pigment and finish, evaluated where the ray hits
// (docs/povray-language.md, "Textures"). An object without one keeps its constant Material.
#pragma once

#include <memory>
#include <vector>

#include "raytrace/surface/material.hpp"
#include "raytrace/surface/normal.hpp"
#include "raytrace/surface/pigment.hpp"

namespace rt {

// A finish's terms that scale the pigment's colour.
struct FinishTerms {
  Color ambient{0};  // POV-Ray's ambient times global_settings' ambient_light, plus its emission
  Color emission{0};  // POV-Ray 3.7's emission, which ambient_light does not scale (scene_builder's ambientScaled)
  float diffuse = 0;
  Color specular{0};
  float metallic = 0;  // the highlight's share that takes the pigment's colour
  Material::Lobe lobe = Material::Lobe::HalfVector;
  float exponent = 0, roughness = 1, reflection = 0, ior = 1, brilliance = 1;
  const SurfaceExtras* extras = &kNoExtras;
};

struct Texture;

// A pattern that picks whole textures (`checker texture { … } texture { … }`) or blends them (`texture_map`):
// the selector is a pigment whose red channel is the index of the texture at a point, fractional between two
// entries of a map.
struct TexturePattern {
  Pigment selector;
  std::vector<std::shared_ptr<const Texture>> textures;
  glm::dmat4 fromTexture{1};  // the pattern's transforms, which move its textures too
  // `average texture_map { [w T] … }`: every texture at once, each weighted by w over the weights' sum (the
  // POV-Ray 3.7 manual, "Average"); empty for a pattern, which reads the selector instead.
  std::vector<float> weights;
};

struct TextureLayer {
  std::shared_ptr<const Pigment> pigment;
  FinishTerms finish;
  std::shared_ptr<const TexturePattern> pattern;  // when set, it gives the layer instead of pigment and finish
  std::shared_ptr<const Normal> normal;            // none: the layer leaves the shading normal as it is
};

struct Texture {
  std::vector<TextureLayer> layers;  // the bottom one first, as written; each one above shows through its filter
  glm::dmat4 fromWorld{1};           // world space to texture space
  Material bound;                    // each term's largest value anywhere (bounded()), for the tracer's cut-off
  bool bumpy = false;                // whether some layer bends the normal (bounded()): bent() does something
  bool readsNormal = false;          // whether some pattern in it reads the surface's normal (bounded()): slope
  // uv_mapping: the layers read the point (u, v, 0) of the surface's uv coordinates instead of the world point,
  // so the object's transforms do not move them (the POV-Ray 3.7 manual, "UV Mapping").
  bool uvMapped = false;
  // POV-Ray's interior_texture: what a hit sees from inside the surface (its normal facing away from the ray);
  // none: the same texture from both sides (the POV-Ray 3.7 manual, "Interior Texture").
  std::shared_ptr<const Texture> interior;

  // What shading reads at a world point of the surface.
  Material at(const glm::dvec3& point) const { return inSpace(glm::dvec3(fromWorld * glm::dvec4(point, 1))); }
  // The same at a point of texture space.
  Material inSpace(const glm::dvec3& p) const;
  // The unit shading normal n at a world point, bent by the top layer that has a normal.
  glm::dvec3 bent(const glm::dvec3& point, const glm::dvec3& n) const {
    return bentInSpace(glm::dvec3(fromWorld * glm::dvec4(point, 1)), glm::dmat3(fromWorld), n);
  }
  // The same at a point of texture space; toTexture is the linear part of the map from world space to it.
  glm::dvec3 bentInSpace(const glm::dvec3& p, const glm::dmat3& toTexture, const glm::dvec3& n) const;
};

// The texture with `bound`, `bumpy` and `readsNormal` filled in: each term's largest over every colour its pigments can give
// (its interior's too). A blend or a layer mixes colours with weights summing to at most 1, so the largest of the colours bounds it.
Texture bounded(Texture t);

// A layer's material at a colour: ka·C, kd·C, and the terms that do not depend on the colour.
Material layerMaterial(const FinishTerms& f, const Rgbft& c);

}  // namespace rt
