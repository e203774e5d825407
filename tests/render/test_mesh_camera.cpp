// POV-Ray's mesh_camera (manual, "Mesh projection"; src/scene/projections/mesh_camera.cpp): each distribution
// on tiny meshes, against rays computed by hand from the rules measured on POV-Ray's pictures of the same
// scenes (an emitting plane coloured by x behind the camera mesh, read back pixel by pixel).
#include <catch2/catch.hpp>

#include "../support/pov_scene.hpp"
#include "raytrace/render/camera.hpp"
#include "raytrace/shapes/mesh.hpp"

namespace {

using rt::test::pov;
using rt::test::povFailure;

// Six faces side by side along x, face k's centroid at (k + 1/3, 1/3, 0), normal +z.
const std::string kStrip = "#declare M = mesh { #for (k, 0, 5) triangle { <k,0,0>, <k+1,0,0>, <k,1,0> } #end }\n";

// The ray of pixel (column, row), row 0 the picture's top, as pixelray gives it (its y counts from the bottom).
rt::Ray<double> pixel(const rt::SceneDesc& s, int w, int h, int column, int row) {
  return rt::Camera<double>(s.camera, w, h).pixelRay(column, h - 1 - row);
}

void checkRay(const rt::Ray<double>& ray, glm::dvec3 origin, glm::dvec3 dir) {
  for (int i = 0; i < 3; ++i) {
    CAPTURE(i);
    CHECK(ray.origin[i] == Approx(origin[i]).margin(1e-12));
    CHECK(ray.dir[i] == Approx(dir[i]).margin(1e-12));
  }
}

}  // namespace

TEST_CASE("mesh camera: distribution 0 counts a mesh's faces across the rows, the first two rows alike") {
  const rt::SceneDesc s = pov(kStrip + "camera { mesh_camera { 1 0 mesh { M } } }");
  // POV-Ray's 4×3 picture: rows 0 and 1 show faces 0 to 3, row 2 faces 4 and 5 and then black.
  for (int row : {0, 1}) {
    for (int column = 0; column < 4; ++column) {
      CAPTURE(row, column);
      checkRay(pixel(s, 4, 3, column, row), {column + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
    }
  }
  checkRay(pixel(s, 4, 3, 1, 2), {5 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  const rt::Camera<double> camera(s.camera, 4, 3);
  CHECK(camera.hasBlanks());
  CHECK(camera.blank(camera.pixelRay(2, 0)));
  CHECK(camera.raysPerPixel() == 1);
}

TEST_CASE("mesh camera: the location's z moves the origin off the face, a negative direction turns the ray") {
  // A face ten units wide: the normal is unit, so the origin moves by the location's z itself.
  const std::string mesh = "#declare M = mesh { triangle { <0,0,0>, <10,0,0>, <0,10,0> } }\n";
  checkRay(pixel(pov(mesh + "camera { mesh_camera { 1 0 mesh { M } } location <0,0,-0.3> }"), 1, 1, 0, 0),
           {10.0 / 3, 10.0 / 3, 0.3}, {0, 0, -1});
  checkRay(pixel(pov(mesh + "camera { mesh_camera { 1 0 mesh { M } } location <0,0,-0.3> direction -z }"), 1, 1, 0, 0),
           {10.0 / 3, 10.0 / 3, 0.3}, {0, 0, 1});
  // The mesh's transforms move its faces.
  checkRay(pixel(pov(mesh + "camera { mesh_camera { 1 0 mesh { M rotate 90*y translate x } } }"), 1, 1, 0, 0),
           {1, 10.0 / 3, -10.0 / 3}, {-1, 0, 0});
}

TEST_CASE("mesh camera: `mesh { Name … }` is the declared mesh under its transforms, in the scene too") {
  const rt::SceneDesc s = pov(kStrip + "mesh { M translate x }");
  REQUIRE(s.objects.size() == 1);
  CHECK(std::get<rt::MeshDesc>(s.objects[0].shape).data->faces.size() == 6);
  CHECK(s.objects[0].worldFromObject()[3][0] == 1);
}

TEST_CASE("mesh camera: distribution 1 sums the meshes, distribution 2 sets them side by side") {
  const std::string two = kStrip + "camera { mesh_camera { 1 D mesh { M } mesh { M translate 10*x } } }";
  const rt::SceneDesc summed = pov("#declare D = 1;\n" + two);
  // 4×3: row 2 shows faces 4 and 5 of the first mesh, then faces 0 and 1 of the second.
  checkRay(pixel(summed, 4, 3, 1, 2), {5 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  checkRay(pixel(summed, 4, 3, 2, 2), {10 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  const rt::SceneDesc sides = pov("#declare D = 2;\n" + two);
  // Two blocks of two columns, each on its own mesh at face row·2 + column, the column the picture's: POV-Ray's
  // right block shows faces 2 and 3, then 4 and 5.
  checkRay(pixel(sides, 4, 3, 1, 0), {1 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  checkRay(pixel(sides, 4, 3, 0, 2), {2 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  checkRay(pixel(sides, 4, 3, 2, 0), {12 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  checkRay(pixel(sides, 4, 3, 3, 2), {15 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
}

TEST_CASE("mesh camera: several rays a pixel take one mesh each (0) or the next picture's worth of faces (1)") {
  const std::string two = kStrip + "camera { mesh_camera { 2 D mesh { M } mesh { M translate 10*x } } }";
  const rt::Camera<double> byMesh(pov("#declare D = 0;\n" + two).camera, 2, 2);
  CHECK(byMesh.raysPerPixel() == 2);
  // Pixel (1, 0) from the bottom is row 1, which takes row 0's faces.
  checkRay(byMesh.meshRay(1, 0, 0), {1 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  checkRay(byMesh.meshRay(1, 0, 1), {11 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  const rt::Camera<double> summed(pov("#declare D = 1;\n" + two).camera, 2, 2);
  // Ray 1 of column 1 in either row (row 1 counts as row 0) is face 2·2 + 1 = 5.
  checkRay(summed.meshRay(1, 1, 1), {5 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  checkRay(summed.meshRay(1, 0, 1), {5 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  // 3×2: ray 1 of the top-left pixel is face 6, the second mesh's first.
  const rt::Camera<double> wider(pov("#declare D = 1;\n" + two).camera, 3, 2);
  checkRay(wider.meshRay(0, 1, 1), {10 + 1.0 / 3, 1.0 / 3, 0}, {0, 0, -1});
  const rt::SceneDesc far = pov(kStrip + "camera { mesh_camera { 2 1 mesh { M } } }");
  CHECK(rt::Camera<double>::blank(rt::Camera<double>(far.camera, 4, 3).meshRay(0, 0, 1)));
}

TEST_CASE("mesh camera: distribution 3 starts each ray at the point of the faces' uv map the pixel falls on") {
  // A 10 × 10 square mapped onto the unit square of uv.
  const std::string square =
      "#declare M = mesh { triangle { <0,0,0>, <10,0,0>, <10,10,0> uv_vectors <0,0>, <1,0>, <1,1> }\n"
      "  triangle { <0,0,0>, <10,10,0>, <0,10,0> uv_vectors <0,0>, <1,1>, <0,1> } }\n"
      "camera { mesh_camera { 1 3 mesh { M } } }";
  const rt::SceneDesc s = pov(square);
  // POV-Ray's 10×10 picture: column c at u = c/10, row r at v = 1 − r/10, except the last column (u = 0.85)
  // and the top row (v = 0.95).
  checkRay(pixel(s, 10, 10, 0, 9), {0, 1, 0}, {0, 0, -1});
  checkRay(pixel(s, 10, 10, 3, 4), {3, 6, 0}, {0, 0, -1});
  checkRay(pixel(s, 10, 10, 8, 1), {8, 9, 0}, {0, 0, -1});
  checkRay(pixel(s, 10, 10, 9, 0), {8.5, 9.5, 0}, {0, 0, -1});
}

TEST_CASE("mesh camera: smooth blends the corner normals of distribution 3, turned to the face's side") {
  // The face's normal is +z; the corner normals lean along x and point to −z, so they are turned over.
  const std::string mesh =
      "#declare M = mesh2 { vertex_vectors { 3, <0,0,0>, <10,0,0>, <0,10,0> }\n"
      "  normal_vectors { 3, <-1,0,-1>, <1,0,-1>, <0,0,-1> } uv_vectors { 3, <0,0>, <1,0>, <0,1> }\n"
      "  face_indices { 1, <0,1,2> } }\n";
  const rt::SceneDesc smooth = pov(mesh + "camera { mesh_camera { 1 3 mesh { M } smooth } }");
  // Column 2 of 10, row 7: u = 0.2, v = 0.3, weights (0.5, 0.2, 0.3): normal ∝ (−0.3, 0, −1), turned to +z.
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 0, 1));
  checkRay(pixel(smooth, 10, 10, 2, 7), {2, 3, 0}, -n);
  checkRay(pixel(pov(mesh + "camera { mesh_camera { 1 3 mesh { M } } }"), 10, 10, 2, 7), {2, 3, 0}, {0, 0, -1});
}

TEST_CASE("mesh camera: bad settings stop the scene, a max distance is refused") {
  CHECK(povFailure(kStrip + "camera { mesh_camera { 1 4 mesh { M } } }") ==
        "scene.pov:3:10: error: a mesh_camera's distribution type must be 0, 1, 2 or 3");
  CHECK(povFailure(kStrip + "camera { mesh_camera { 2 0 mesh { M } } }") ==
        "scene.pov:3:10: error: a mesh_camera of distribution 0 needs a mesh for each ray per pixel");
  CHECK(povFailure(kStrip + "camera { mesh_camera { 2 2 mesh { M } mesh { M } } }") ==
        "scene.pov:3:10: error: a mesh_camera of distribution 2 takes 1 ray per pixel");
  CHECK(povFailure(kStrip + "camera { mesh_camera { 1 0 } }") == "scene.pov:3:10: error: a mesh_camera needs a mesh");
  CHECK(povFailure(kStrip + "camera { mesh_camera { 1 0 5 mesh { M } } }") ==
        "scene.pov:3:28: error: 'mesh_camera's max distance' is not supported yet");
  CHECK(povFailure(kStrip + "camera { mesh_camera { 1 0 0 mesh { M } } }") == "no error");
}
