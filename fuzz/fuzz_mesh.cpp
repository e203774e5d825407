// libFuzzer target for the mesh files `raytrace convert` reads (parse/mesh_file.hpp): each input is read as an
// OBJ and as a PLY. Any bytes must either read or throw rt::Error: any other exception, a crash, a sanitizer
// report, a hang or a blown memory limit is a finding. What reads is written as a mesh2 include too.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "raytrace/app/convert.hpp"
#include "raytrace/parse/mesh_file.hpp"
#include "raytrace/util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (const bool obj : {true, false}) {
    try {
      const rt::MeshFile mesh = obj ? rt::readObj(bytes, "fuzz.obj") : rt::readPly(bytes, "fuzz.ply");
      const std::string include = rt::mesh2Include(mesh, "Fuzz", "fuzz");
      (void)include;
    } catch (const rt::Error&) {
    }
  }
  return 0;
}
