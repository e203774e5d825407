// File names.
#pragma once

#include <string>

namespace rt {

// A file name's extension in lower case without the dot: "png" for "a/b.PNG", "" for "a.d/b" or ".png" (a
// hidden file's name is no extension).
std::string extension(const std::string& path);

// Whether `a` and `b` name one existing file (the same device and inode), however they are spelt.
bool sameFile(const std::string& a, const std::string& b);

}  // namespace rt
