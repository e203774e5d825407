// The surface blocks of a POV-Ray object (pigment, finish, texture, material, interior) read into a Surface,
// and the Material or Texture shading reads made of one. Part of the scene builder (scene_builder.cpp).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/geometry/transform.hpp"
#include "raytrace/parse/povray/value.hpp"
#include "raytrace/surface/image_map.hpp"
#include "raytrace/surface/texture.hpp"

namespace rt::povray {

// What every reader of one scene file shares: the refusal policy, where the files the scene names are, and the
// scene-wide settings that readers need. Each reader takes the one context.
struct ReadingContext {
  // The first thing met that POV-Ray has and raytrace cannot draw yet: reading goes on, so that a real mistake
  // later in the file is still reported as one.
  struct Unsupported {
    SourceLoc loc;
    std::string what;
  };
  std::optional<Unsupported> firstRefusal;
  void refuse(const SourceLoc& loc, std::string_view what) {
    if (!firstRefusal) firstRefusal = Unsupported{loc, std::string(what)};
  }
  void refuse(const Item& it, std::string_view otherwise);  // names the item's keyword, or `otherwise`

  // Where a file the scene names is (empty when it is not found).
  std::function<std::string(const std::string&)> findFile;

  // The scene's noise generator, which patterns read when drawn since global_settings may set it after them.
  std::shared_ptr<NoiseGenerator> sceneNoise = std::make_shared<NoiseGenerator>(NoiseGenerator::RangeCorrected);
  // global_settings' irid_wavelength (POV-Ray 3.7 manual, "Irid_Wavelength"), read by iridescent finishes the same way.
  std::shared_ptr<glm::dvec3> iridWavelength = std::make_shared<glm::dvec3>(0.70, 0.52, 0.48);
  // The scene's working gamma for an image map's colours when it is read: assumed_gamma, or nothing before
  // #version 3.7, which takes them as they are.
  std::function<std::optional<double>()> imageGamma;
  // How each pattern read was made, its kind and settings, so that a later block which modifies it (`texture {
  // T pigment { octaves 3 } }`) makes it again with its own modifiers, as POV-Ray does.
  struct PatternRecipe {
    const PatternKind* kind;
    PatternArgs args;
  };
  std::shared_ptr<std::map<std::shared_ptr<const Pattern>, PatternRecipe>> patternRecipes =
      std::make_shared<std::map<std::shared_ptr<const Pattern>, PatternRecipe>>();
};

// `image_map { [type] "file" … }` (image_map_reader.cpp); nothing when something in it is refused.
std::shared_ptr<const ImageMap> readImageMap(const Node& n, ReadingContext& context);
// A bump_map's own settings: its bump_size, when written, and use_index.
struct BumpMapSettings {
  std::optional<double> size;
  bool useIndex = false;
};
// `bump_map { [type] "file" … }` (image_map_reader.cpp): its image, its values left linear; nothing when
// something in it is refused.
std::shared_ptr<const ImageMap> readBumpMap(const Node& n, ReadingContext& context, BumpMapSettings& settings);
// The image of a `material_map { [type] "file" [map_type T] … }` without its textures and transforms
// (image_map_reader.cpp): each pixel's red the index of its texture among `textures`; nothing when refused.
std::shared_ptr<const ImageMap> readMaterialMapImage(const Node& n, size_t textures, ReadingContext& context);

// `media { … }` in an interior (media_reader.cpp); nothing when something in it is refused.
std::optional<Media> readMedia(const Node& n, ReadingContext& context);

glm::dvec3 vec3(const Value& v);
Rgbft colourOf(const Value& v);
// The value after n.items[i], if it is one (i moves onto it).
const Value* valueAfter(const Node& n, size_t& i);
// turbulence, octaves, omega and lambda into t (i moves past the value); false for any other item.
bool readTurbulence(const Node& n, size_t& i, Turbulence& t);
// translate, rotate, scale and transform items as steps; false for any other item.
bool readTransform(const Node& n, size_t& i, std::vector<TransformStep>& steps, ReadingContext& context);
// A `transform { … }` block's items as steps.
void readTransformBlock(const Node& n, std::vector<TransformStep>& steps, ReadingContext& context);

// A finish with POV-Ray 3.7's defaults.
struct PovFinish {
  Color ambient{0.1f};
  Color emission{0};
  double crand = 0;
  // A reflection block's minimum (unset: `reflection` at every angle), falloff, metallic and fresnel (Material).
  std::optional<double> reflectionMin;
  double reflectionFalloff = 1;
  double reflectionMetallic = 0;
  bool reflectionFresnel = false;
  Color reflectionTint{1};     // a colour `reflection` over its largest channel, which is `reflection`
  Color reflectionMinTint{1};  // the same for the minimum
  bool conserveEnergy = false;
  std::shared_ptr<const Iridescence> irid;  // `irid { … }` with an amount other than 0
  double diffuse = 0.6, phong = 0, phongSize = 40, specular = 0, roughness = 0.05, reflection = 0, brilliance = 1, metallic = 0;
};

// A `warp { … }` in a pigment, after the first `after` of its transforms.
struct WarpMark {
  size_t after;
  std::shared_ptr<const Warp> warp;
};

// The warp a `warp { … }` block describes (warp_reader.cpp); nothing when it is refused or moves no point.
std::shared_ptr<const Warp> readWarp(const Node& n, ReadingContext& context);

// The pigment's fromTexture, and its warps between its transforms.
void placeTransforms(Pigment& p, const std::vector<TransformStep>& steps, const std::vector<WarpMark>& warps);
// The same for a normal.
void placeTransforms(Normal& n, const std::vector<TransformStep>& steps, const std::vector<WarpMark>& warps);

struct SurfaceLayer {
  Pigment pigment;                       // POV-Ray's default pigment is black
  std::vector<TransformStep> steps;      // the pigment's and texture's own transforms, in order
  std::vector<WarpMark> warps;           // the pigment's warps among them
  PovFinish finish;
  std::shared_ptr<const TexturePattern> pattern;  // a pattern of whole textures instead
  std::optional<Normal> normal;
  std::vector<TransformStep> normalSteps;  // the normal's own transforms, then the texture's written after it
  std::vector<WarpMark> normalWarps;       // the normal's warps among them
};

struct Surface {
  std::vector<SurfaceLayer> layers{1};  // the bottom layer first
  double ior = 1;
  double fadeDistance = 0, fadePower = 0;  // the interior's fade (Material)
  Color fadeColor{0};
  double caustics = 0;         // the interior's faked caustics (Material)
  std::vector<Media> media;  // the interior's (Material)
  bool uvMapped = false;       // uv_mapping in the object, or in one of its pigments, normals or textures
  bool doubleIlluminate = false;  // the object's double_illuminate (Material)
  std::shared_ptr<const Surface> inside;  // the interior_texture's, seen from inside (Texture::interior)
  bool patterned() const;  // whether some layer's colour varies, or there are layers: a Texture is needed
};

// A pigment block on its own, its transforms folded into its fromTexture: a map's or a list's entry, a sky's layer.
std::shared_ptr<const Pigment> nestedPigment(const Node& n, ReadingContext& context);

// A normal block on its own, its transforms folded into its fromTexture: a camera's.
std::shared_ptr<const Normal> aloneNormal(const Node& n, ReadingContext& context);

// The `pattern { … }` of a pattern function as a pigment without colours, whose value() the function returns.
std::shared_ptr<const Pigment> patternPigment(const Node& n, ReadingContext& context);

// pigment, finish, normal, texture, material or interior into `s`; anything else is refused. A texture inside a
// texture pattern starts as `defaults` (#default).
void readSurfaceItem(const Node& n, Surface& s, const Surface& defaults, ReadingContext& context);

// The finish terms of the surface's top layer (its finish and the interior's settings).
FinishTerms topTerms(const Surface& s);
// The constant material of the surface's top layer; its ambient is not yet scaled by ambient_light.
Material constantMaterial(const Surface& s);
// The finish as written, for sceneinfo.
Finish writtenFinish(const Surface& s);
// The surface as a texture whose texture space is the world space of an object moved by `after`.
Texture makeTexture(const Surface& s, const std::vector<TransformStep>& after);

}  // namespace rt::povray
