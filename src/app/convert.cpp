#include "raytrace/app/convert.hpp"

#include <cctype>
#include <charconv>

#include "raytrace/image/output_file.hpp"
#include "raytrace/parse/povray/lexer.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"
#include "raytrace/util/path.hpp"

namespace rt {

namespace {

constexpr const char* kSeeHelp = " (see raytrace help convert)";

// The shortest text that reads back as `v` (std::to_chars' promise), as a float's when the file held floats.
void number(std::string& out, double v, bool single) {
  char text[32];
  const auto r =
      single ? std::to_chars(text, text + sizeof text, float(v)) : std::to_chars(text, text + sizeof text, v);
  out.append(text, r.ptr);
}

template <class List, class Write>
void block(std::string& out, const char* keyword, const List& list, Write&& write) {
  if (list.empty()) return;
  out += "  ";
  out += keyword;
  out += " {\n    " + std::to_string(list.size());
  for (const auto& item : list) {
    out += ",\n    <";
    write(item);
    out += ">";
  }
  out += "\n  }\n";
}

bool isIdentifier(const std::string& name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  for (const char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return !povray::isKeyword(name) && povray::builtinIndex(name) == 0;
}

}  // namespace

std::string mesh2Include(const MeshFile& mesh, const std::string& name, const std::string& source) {
  const bool single = mesh.singlePrecision;
  std::string out = "// " + printable(source, kMaxQuotedPath) +
                    " as a mesh2 (raytrace convert): " + std::to_string(mesh.vertices.size()) + " vertices, " +
                    std::to_string(mesh.faces.size()) + (mesh.faces.size() == 1 ? " triangle" : " triangles") +
                    ".\n#declare " + name + " = mesh2 {\n";
  const auto vector3 = [&](const glm::dvec3& p) {
    for (int k = 0; k < 3; ++k) {
      if (k) out += ", ";
      number(out, p[k], single);
    }
  };
  block(out, "vertex_vectors", mesh.vertices, vector3);
  block(out, "normal_vectors", mesh.normals, vector3);
  block(out, "uv_vectors", mesh.uvs, [&](const glm::dvec2& p) {
    number(out, p.x, single);
    out += ", ";
    number(out, p.y, single);
  });
  const auto indices = [&](const char* keyword, std::array<uint32_t, 3> MeshFile::Face::*member) {
    out += "  ";
    out += keyword;
    out += " {\n    " + std::to_string(mesh.faces.size());
    for (const MeshFile::Face& f : mesh.faces) {
      const std::array<uint32_t, 3>& i = f.*member;
      out += ",\n    <" + std::to_string(i[0]) + ", " + std::to_string(i[1]) + ", " + std::to_string(i[2]) + ">";
    }
    out += "\n  }\n";
  };
  indices("face_indices", &MeshFile::Face::v);
  if (!mesh.normals.empty()) indices("normal_indices", &MeshFile::Face::n);
  if (!mesh.uvs.empty()) indices("uv_indices", &MeshFile::Face::uv);
  return out + "}\n";
}

std::string meshName(const std::string& path) {
  std::string stem = path.substr(path.rfind('/') == std::string::npos ? 0 : path.rfind('/') + 1);
  const size_t dot = stem.rfind('.');
  if (dot != std::string::npos && dot > 0) stem.resize(dot);
  for (char& c : stem) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  if (stem.empty() || !std::isalpha(static_cast<unsigned char>(stem[0]))) return "Mesh_" + stem;
  stem[0] = char(std::toupper(static_cast<unsigned char>(stem[0])));  // POV-Ray's keywords are all lower case
  return stem;
}

int convertCommand(const std::vector<std::string>& words) {
  std::vector<std::string> files;
  std::string name;
  for (size_t i = 0; i < words.size(); ++i) {
    const std::string& w = words[i];
    if (w == "--name") {
      if (i + 1 == words.size()) throw Error("--name needs a value");
      name = words[++i];
      if (!isIdentifier(name)) {
        throw Error(
            "--name must be a POV-Ray identifier (a letter, then letters, digits and _, not a keyword), "
            "found " +
            quote(name));
      }
    } else if (w.size() > 1 && w[0] == '-') {
      throw Error("unknown option " + quote(w) + " for convert" + kSeeHelp);
    } else {
      files.push_back(w);
    }
  }
  if (files.size() != 2) {
    throw Error("convert takes the mesh file and the include to write, found " + std::to_string(files.size()) +
                (files.size() == 1 ? " file" : " files") + kSeeHelp);
  }
  const std::string& input = files[0];
  const std::string& output = files[1];
  if (sameFile(input, output)) {
    throw Error("cannot write " + quote(output, kMaxQuotedPath) +
                ": it is the mesh file, which the include would replace");
  }
  checkWritableFolder(output);
  const MeshFile mesh = readMeshFile(input);
  const std::string text = mesh2Include(mesh, name.empty() ? meshName(input) : name, input);
  OutputFile file(output);
  file.write(text.data(), text.size());
  file.commit();
  return 0;
}

}  // namespace rt
