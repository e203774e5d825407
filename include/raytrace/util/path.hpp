// File names.
#pragma once

#include <string>

namespace rt {

// A file name's extension in lower case without the dot: "png" for "a/b.PNG", "" for "a.d/b" or ".png" (a
// hidden file's name is no extension).
std::string extension(const std::string& path);

// Whether `a` and `b` name one existing file (the same device and inode), however they are spelt.
bool sameFile(const std::string& a, const std::string& b);

// Whether a path a scene file names stays in the folder it is rendered into: it is relative and never goes
// up. A scene from someone else must not create or replace files elsewhere unless the user says so.
bool staysInFolder(const std::string& path);

// Whether the folder a relative `path` names inside `folder` is, through a symbolic link on the way, somewhere
// else. A folder that does not exist is not: writing there fails on its own.
bool linksOut(const std::string& folder, const std::string& path);

}  // namespace rt
