#include "raytrace/util/path.hpp"

#include <cctype>

#include <sys/stat.h>

namespace rt {

std::string extension(const std::string& path) {
  const size_t dot = path.find_last_of("./");
  const bool named = dot != std::string::npos && dot > 0 && path[dot] == '.' && path[dot - 1] != '/';
  std::string ext = named ? path.substr(dot + 1) : "";
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool sameFile(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  return stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

}  // namespace rt
