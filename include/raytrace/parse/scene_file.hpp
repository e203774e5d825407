// Reading a scene file from disk in whichever language it is written.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/parse/povray/clock.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

// A file's bytes, in memory of their own.
class FileText {
 public:
  // Room for `capacity` bytes, none of them set: zero-filling a large file's memory before reading over it
  // would take a third as long as the read itself.
  explicit FileText(size_t capacity) : bytes_(new char[capacity]) {}

  char* data() { return bytes_.get(); }
  void resize(size_t size) { size_ = size; }  // at most the capacity
  std::string_view view() const { return {bytes_.get(), size_}; }

 private:
  std::unique_ptr<char[]> bytes_;
  size_t size_ = 0;
};

// The whole file. Throws Error with a one-line reason for a missing, unreadable or non-regular file (a
// directory, a FIFO, a device) and for one larger than kMaxSceneFileBytes (limits.hpp). A large file is read on
// `threads` threads at once.
FileText readFile(const std::string& path, int threads = 1);

// The language of a scene file: from its extension (.pov, .cli, any case) when it has one of those, otherwise
// from its text (looksLikeCs3451), with the POV subset as the fallback.
SceneLanguage sceneLanguage(const std::string& path, std::string_view text);

// How a .pov file is read: by the rule of docs/povray-language.md (POV-Ray 3.7 when it uses a directive or
// global_settings, else the course's subset), or as the command line's --dialect says.
enum class DialectChoice { Auto, Course, PovRay };

struct LoadOptions {
  DialectChoice dialect = DialectChoice::Auto;
  std::vector<std::string> libraryPaths;  // -L: folders a POV-Ray scene's #include searches
  int width = 320, height = 240;          // POV-Ray's image_width and image_height
  std::vector<std::string> declares;      // -D name=value: identifiers a POV-Ray scene starts with
  std::string writeFolder;                // the output image's folder, where a POV-Ray scene's #write files go
  bool writeAnywhere = false;             // --allow-write-anywhere: they may go anywhere
  povray::Clock clock;                    // a POV-Ray animation frame's clock (povray_command_line.hpp)
};

// The POV language a .pov file is read in.
SceneLanguage povDialect(std::string_view text, DialectChoice dialect);

// Reads and parses a scene in its language (sceneLanguage), a large POV file on up to `threads` threads.
SceneDesc loadScene(const std::string& path, int threads = 1, const LoadOptions& options = {});

}  // namespace rt
