// `image_map { [type] "file" [map_type 0|1|2] [interpolate 2|4] [once] [filter all F] [transmit all T]
// [filter I, F] [transmit I, F] [gamma G] }` (POV-Ray 3.7 manual, "Image Maps").
#include "raytrace/parse/povray/surface_reader.hpp"

#include <algorithm>

namespace rt::povray {

std::shared_ptr<const ImageMap> readImageMap(const Node& n, ReadingContext& context) {
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
      name = it.value.s;
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
    } else if (w == "once") {
      settings.once = true;
    } else if (w == "map_type") {
      const double type = number(i, it, "0, 1 or 2");
      if (type == 0 || type == 1 || type == 2) {
        settings.mapping = type == 0 ? ImageMap::Mapping::Planar
                           : type == 1 ? ImageMap::Mapping::Spherical
                                       : ImageMap::Mapping::Cylindrical;
      } else {
        context.refuse(it.loc, "image_map map_type " + std::to_string(int(type)));
        refused = true;
      }
    } else if (w == "interpolate") {
      const double kind = number(i, it, "2 or 4");
      if (kind == 2 || kind == 4) {
        settings.interpolation = kind == 2 ? ImageMap::Interpolation::Bilinear : ImageMap::Interpolation::NormalizedDistance;
      } else {
        context.refuse(it.loc, "image_map interpolate " + std::to_string(int(kind)));
        refused = true;
      }
    } else if (w == "gamma") {
      if (i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Keyword && n.items[i + 1].word == "srgb") {
        ++i;
        fileGamma = 0;
      } else {
        fileGamma = number(i, it, "a float or srgb");
        if (!(fileGamma > 0)) throw ParseError(it.loc, "the image map's gamma must be greater than 0");
      }
    } else if ((w == "filter" || w == "transmit") && i + 1 < n.items.size() && n.items[i + 1].kind == Item::Kind::Keyword &&
               n.items[i + 1].word == "all") {
      ++i;
      (w == "filter" ? filterAll : transmitAll) = float(number(i, it, "a float"));
    } else if (w == "filter" || w == "transmit") {
      const int index = int(number(i, it, "a palette index and an amount"));
      channels.push_back({index, w == "transmit", float(number(i, it, "a palette index and an amount"))});
    } else {
      // use_color, use_index, premultiplied …
      context.refuse(it.loc, "image_map " + std::string(w));
      refused = true;
    }
  }
  if (name.empty()) throw ParseError(n.loc, "image_map needs an image file");
  if (refused) return nullptr;
  const std::string path = context.findFile ? context.findFile(name) : name;
  if (path.empty()) throw ParseError(nameAt, "cannot find the image map \"" + name + "\"");
  const std::optional<double> working = context.imageGamma ? context.imageGamma() : std::optional<double>(1.0);
  // Before #version 3.7 a file's values are the scene's colours as they are; from 3.7 on they are decoded
  // (sRGB unless `gamma` says otherwise) and put in the scene's working gamma (measured against POV-Ray 3.7).
  auto image = std::make_shared<ImageMap>(readImageFile(path, working ? fileGamma : -1, working.value_or(1), nameAt, channels));
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

}  // namespace rt::povray
