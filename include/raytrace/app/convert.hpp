// `raytrace convert model.obj model.inc`: a mesh file (parse/mesh_file.hpp) written as a POV-Ray mesh2 include.
#pragma once

#include <string>
#include <vector>

#include "raytrace/parse/mesh_file.hpp"

namespace rt {

// The include's text: `#declare <name> = mesh2 { … }` with the mesh's vectors and indices, each number in the
// fewest digits that read back as the same value.
std::string mesh2Include(const MeshFile& mesh, const std::string& name, const std::string& source);

// The identifier a file's name gives: its name without folder and extension, capitalised, other characters than
// letters, digits and _ made _ ("my-model.obj" gives My_model); one not beginning with a letter after "Mesh_".
std::string meshName(const std::string& path);

// The command's words: the mesh file, the include, and --name NAME. Returns the exit status.
int convertCommand(const std::vector<std::string>& words);

}  // namespace rt
