// Reading a scene file from disk in whichever language it is written.
#pragma once

#include <string>

#include "raytrace/scene_desc.hpp"

namespace rt {

// The whole file as bytes. Throws Error with a one-line reason for a missing, unreadable or non-regular file
// (a directory, a FIFO, a device) and for one larger than kMaxSceneFileBytes (limits.hpp).
std::string readFile(const std::string& path);

// A file name's extension in lower case without the dot: "png" for "a/b.PNG", "" for "a.d/b" or ".png" (a
// hidden file's name is no extension).
std::string extension(const std::string& path);

// The language of a scene file: from its extension (.pov, .cli, any case) when it has one of those, otherwise
// from its text (looksLikeCli), with the POV subset as the fallback.
SceneLanguage sceneLanguage(const std::string& path, const std::string& text);

// Reads and parses a scene in its language (sceneLanguage), a large POV file on up to `threads` threads.
SceneDesc loadScene(const std::string& path, int threads = 1);

}  // namespace rt
