#include "raytrace/util/path.hpp"

#include <cctype>

namespace rt {

std::string extension(const std::string& path) {
  const size_t dot = path.find_last_of("./");
  const bool named = dot != std::string::npos && dot > 0 && path[dot] == '.' && path[dot - 1] != '/';
  std::string ext = named ? path.substr(dot + 1) : "";
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace rt
