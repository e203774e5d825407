// What a command receives once its arguments are checked and its scene is loaded, and the helpers the
// command families share.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "raytrace/image/region.hpp"
#include "raytrace/parse/povray/clock.hpp"
#include "raytrace/render/renderer.hpp"
#include "raytrace/render/scene_setup.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

struct Invocation {
  std::string scenePath;
  SceneDesc scene;
  int width = 0, height = 0, x = 0, y = 0;
  // -o: the image file, or for a .cli scene that writes its own images the folder they go into; "" for the
  // default, output.png or the scene's own names.
  std::string output;
  // --tile or --region: the part of the picture to render, written as an OpenEXR tile; `tile` is the --tile
  // value ("" for --region).
  std::optional<Region> region;
  std::string tile;
  RenderOptions options;
  std::ostream* progress = nullptr;  // where render shows its progress line (not with --quiet)
  std::ostream* stats = nullptr;     // --stats: where render reports how long each step took
  bool statsJson = false;            // --stats=json: as one JSON object
  bool display = false;              // --display: show the picture in a window as it renders
  std::string preview;               // --preview: the file the picture so far goes to, every few seconds
  std::ostream* errors = nullptr;    // where a command reports a failure it carries on after (a .cli write)
  bool writeAnywhere = false;        // --allow-write-anywhere: a .cli write or #fopen may leave its folder
  bool resume = false;               // --resume: a tile already at -o, of this very render, is kept
  // What the scene is read with besides its files: -D's declarations and a POV-Ray frame's clock; a tile
  // records them (tile_header.hpp), as they change its pixels.
  std::vector<std::string> declares;
  povray::Clock clock;
  // --manifest: the file that lists, once the images are written, the scene, every file it read and the
  // images, one a line ("" without it): what a frame's stamp hashes (tools/render-parallel --frames).
  std::string manifest;
  double loadSeconds = 0;         // the reading of the scene file
};

// Runs f(scene, camera) at the precision the scene needs (render/scene_setup.hpp).
template <class F> auto withScene(const Invocation& inv, F&& f) {
  return withScene(inv.scene, inv.width, inv.height, inv.options, std::forward<F>(f));
}

// The image commands (image_commands.cpp).
int raycast(const Invocation& inv, std::ostream& out);
int renderImage(const Invocation& inv, std::ostream& out);
// Throws the Error an image command's -o, --tile or --region would meet (an unknown format, a missing or
// unwritable folder, a tile not named .exr), before the scene is read.
void checkOutput(const Invocation& inv);

// The commands that print what the renderer sees (inspect.cpp).
int sceneinfo(const Invocation& inv, std::ostream& out);
int pixelray(const Invocation& inv, std::ostream& out);
int firsthit(const Invocation& inv, std::ostream& out);
int pixelcolor(const Invocation& inv, std::ostream& out);
int printrays(const Invocation& inv, std::ostream& out);
int pixeltrace(const Invocation& inv, std::ostream& out);
int printbvh(const Invocation& inv, std::ostream& out);

}  // namespace rt
