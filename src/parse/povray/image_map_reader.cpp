// `image_map { [type] "file" [map_type 0|1|2|5] [interpolate 2|4] [once] [filter all F] [transmit all T]
// [filter I, F] [transmit I, F] [gamma G] }` (POV-Ray 3.7 manual, "Image Maps"), and a normal's
// `bump_map { … [bump_size S] [use_index | use_color] }` ("Bump Map"), and the image of a
// `material_map { [type] "file" [map_type 0|1|2|5] TEXTURE… }` ("Material Maps").
#include "raytrace/parse/povray/surface_reader.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>

#include "raytrace/util/palette_image.hpp"

namespace rt::povray {

namespace {

// use_index: a palette image's pixels become their indices, as greys whose intensity is the index itself
// (measured on POV-Ray's renders: the height grows by 1 per index); an image without a palette keeps its colours.
void useIndices(const std::string& path, ImageMap& image) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::optional<PaletteImage> palette = paletteIndices(bytes);
  if (!palette || palette->indices.size() != image.pixels.size()) return;
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i].rgb = Color(float(palette->indices[i]));
}

// What an image is read for: its colours, a bump_map's heights, or a material_map's texture indices.
enum class Use { Colours, Bump, Material };

// material_map: each pixel the index of its texture, modulo the `textures` written (the manual's "Material Maps"):
// a palette image's index, else the 8-bit value of its red channel as the file holds it.
void materialIndices(const std::string& path, size_t textures, ImageMap& image) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::optional<PaletteImage> palette = paletteIndices(bytes);
  const bool indexed = palette && palette->indices.size() == image.pixels.size();
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const long index = indexed ? long(palette->indices[i]) : std::lround(image.pixels[i].rgb.r * 255.0f);
    image.pixels[i] = {Color(float(size_t(index) % textures)), 0, 0};
  }
}

// An image_map, a bump_map (then bump_size, use_index and use_color are read into `bump`) or a material_map's
// image of `textures` textures, whose texture and transform items the caller has taken out.
std::shared_ptr<const ImageMap> readImage(const Node& n, ReadingContext& context, Use use, BumpMapSettings* bump,
                                          size_t textures = 0) {
  const bool colours = use == Use::Colours;
  static constexpr std::string_view kTypes[] = {"gif", "hdr", "jpeg", "pgm", "png", "ppm", "sys", "tga"};
  static constexpr std::string_view kRefusedTypes[] = {"exr", "iff", "tiff"};
  std::string name;
  SourceLoc nameAt = n.loc;
  ImageMap settings;
  double fileGamma = 0;
  std::optional<float> filterAll, transmitAll;
  std::vector<PaletteChannel> channels;
  bool refused = false;
  // The float after item i (i moves onto it), which follows the keyword `key`.
  const auto number = [&](size_t& i, const Item& key, const char* what) {
    const Value* v = valueAfter(n, i);
    if (!v || v->type != Value::Type::Float) throw ParseError(key.loc, "'" + std::string(key.word) + "' needs " + what);
    return v->v[0];
  };
  for (size_t i = 0; i < n.items.size(); ++i) {
    const Item& it = n.items[i];
    if (it.kind == Item::Kind::Value && it.value.type == Value::Type::String && name.empty()) {
      name = it.value.str();
      nameAt = it.loc;
      continue;
    }
    if (it.kind != Item::Kind::Keyword) {
      context.refuse(it, "a value in image_map");
      refused = true;
      continue;
    }
    const std::string_view w = it.word;
    if (std::find(std::begin(kTypes), std::end(kTypes), w) != std::end(kTypes)) continue;
    if (std::find(std::begin(kRefusedTypes), std::end(kRefusedTypes), w) != std::end(kRefusedTypes)) {
      context.refuse(it.loc, "image_map " + std::string(w));
      refused = true;
    } else if (w == "once" && use != Use::Material) {
      settings.once = true;
    } else if (w == "map_type") {
      const double type = number(i, it, "0, 1, 2 or 5");
      if (type == 0 || type == 1 || type == 2 || type == 5) {
        settings.mapping = type == 0   ? ImageMap::Mapping::Planar
                           : type == 1 ? ImageMap::Mapping::Spherical
                           : type == 2 ? ImageMap::Mapping::Cylindrical
                                       : ImageMap::Mapping::Torus;
      } else {
        context.refuse(it.loc, "image_map map_type " + std::to_string(int(type)));
        refused = true;
      }
    } else if (w == "interpolate" && use != Use::Material) {
      const double kind = number(i, it, "2 or 4");
      if (kind == 2 || kind == 4) {
        settings.interpolation = kind == 2 ? ImageMap::Interpolation::Bilinear : ImageMap::Interpolation::NormalizedDistance;
      } else {
        context.refuse(it.loc, "image_map interpolate " + std::to_string(int(kind)));
        refused = true;
      }
    } else if (w == "gamma" && colours) {
      if (i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Keyword && n.items[i + 1].word == "srgb") {
        ++i;
        fileGamma = 0;
      } else {
        fileGamma = number(i, it, "a float or srgb");
        if (!(fileGamma > 0)) throw ParseError(it.loc, "the image map's gamma must be greater than 0");
      }
    } else if (colours && (w == "filter" || w == "transmit") && i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Keyword &&
               n.items[i + 1].word == "all") {
      ++i;
      (w == "filter" ? filterAll : transmitAll) = float(number(i, it, "a float"));
    } else if (colours && (w == "filter" || w == "transmit")) {
      const int index = int(number(i, it, "a palette index and an amount"));
      channels.push_back({index, w == "transmit", float(number(i, it, "a palette index and an amount"))});
    } else if (bump && w == "bump_size") {
      bump->size = number(i, it, "a float");
    } else if (bump && (w == "use_index" || w == "use_color" || w == "use_colour")) {
      bump->useIndex = w == "use_index";
    } else {
      // use_color, use_index, premultiplied; a material_map's once and interpolate …
      context.refuse(it.loc, std::string(n.keyword) + " " + std::string(w));
      refused = true;
    }
  }
  if (name.empty()) throw ParseError(n.loc, std::string(n.keyword) + " needs an image file");
  if (refused) return nullptr;
  const std::string path = context.findFile ? context.findFile(name) : name;
  if (path.empty()) throw ParseError(nameAt, "cannot find the image map \"" + name + "\"");
  const std::optional<double> working = context.imageGamma ? context.imageGamma() : std::optional<double>(1.0);
  // Before #version 3.7 a file's values are the scene's colours as they are; from 3.7 on they are decoded
  // (sRGB unless `gamma` says otherwise) and put in the scene's working gamma (measured against POV-Ray 3.7).
  // A bump map's file holds linear heights: its values are taken as they are (the manual, "Bump Map").
  auto image = !colours ? std::make_shared<ImageMap>(readImageFile(path, -1, 1, nameAt))
                        : std::make_shared<ImageMap>(readImageFile(path, working ? fileGamma : -1, working.value_or(1), nameAt, channels));
  if (bump && bump->useIndex) useIndices(path, *image);
  if (use == Use::Material) materialIndices(path, textures, *image);
  image->mapping = settings.mapping;
  image->interpolation = settings.interpolation;
  image->once = settings.once;
  for (Rgbft& c : image->pixels) {
    if (filterAll) c.filter = *filterAll;
    if (transmitAll) c.transmit = *transmitAll;
  }
  image->findExtremes();
  return image;
}

}  // namespace

std::shared_ptr<const ImageMap> readImageMap(const Node& n, ReadingContext& context) {
  return readImage(n, context, Use::Colours, nullptr);
}

std::shared_ptr<const ImageMap> readBumpMap(const Node& n, ReadingContext& context, BumpMapSettings& settings) {
  return readImage(n, context, Use::Bump, &settings);
}

std::shared_ptr<const ImageMap> readMaterialMapImage(const Node& n, size_t textures, ReadingContext& context) {
  return readImage(n, context, Use::Material, nullptr, textures);
}

}  // namespace rt::povray
