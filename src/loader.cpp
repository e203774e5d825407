#include "raytrace/loader.hpp"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

#include "raytrace/cli_parser.hpp"
#include "raytrace/pov_parser.hpp"

namespace rt {

std::string readFile(const std::string& path) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) throw Error("cannot open '" + path + "': " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw Error("cannot read '" + path + "': it is a directory, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open '" + path + "': " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error("cannot read '" + path + "': " + std::strerror(errno));
  return text.str();
}

std::string extension(const std::string& path) {
  const size_t dot = path.find_last_of("./");
  const bool named = dot != std::string::npos && dot > 0 && path[dot] == '.' && path[dot - 1] != '/';
  std::string ext = named ? path.substr(dot + 1) : "";
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

SceneLanguage sceneLanguage(const std::string& path, const std::string& text) {
  const std::string ext = extension(path);
  if (ext == "pov") return SceneLanguage::Pov;
  if (ext == "cli") return SceneLanguage::Cli;
  return looksLikeCli(text) ? SceneLanguage::Cli : SceneLanguage::Pov;
}

SceneDesc loadScene(const std::string& path) {
  const std::string text = readFile(path);
  return sceneLanguage(path, text) == SceneLanguage::Cli ? parseCli(text, path) : parsePov(text, path);
}

}  // namespace rt
