#include "raytrace/util/path.hpp"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdlib>

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

bool staysInFolder(const std::string& path) {
  if (path.empty() || path[0] == '/') return false;
  for (size_t start = 0; start <= path.size();) {
    const size_t end = std::min(path.find('/', start), path.size());
    if (path.compare(start, end - start, "..") == 0) return false;
    start = end + 1;
  }
  return true;
}

bool linksOut(const std::string& folder, const std::string& path) {
  const size_t slash = path.rfind('/');
  char base[PATH_MAX], parent[PATH_MAX];
  if (slash == std::string::npos || !realpath(folder.c_str(), base) ||
      !realpath((folder + "/" + path.substr(0, slash)).c_str(), parent)) {
    return false;
  }
  const std::string inside = std::string(base) == "/" ? "/" : std::string(base) + "/";
  return std::string(parent) != base && std::string(parent).compare(0, inside.size(), inside) != 0;
}

}  // namespace rt
