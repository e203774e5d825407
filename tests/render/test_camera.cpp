// The course camera (docs/reference/csc473.md §d): the worked check on simple.pov and the simp_cam scenes, in both
// precisions, compared with directions computed independently in float64 (numpy) and with the course's
// printed 4-decimal values.
#include <catch2/catch.hpp>

#include "raytrace/render/camera.hpp"
#include "raytrace/util/format.hpp"
#include "../support/pov_scene.hpp"

namespace {

rt::CameraDesc camera(glm::dvec3 location, glm::dvec3 right) {
  rt::CameraDesc c;
  c.location = location;
  c.up = {0, 1, 0};
  c.right = right;
  c.lookAt = {0, 0, 0};
  return c;
}

const rt::CameraDesc kSimple = camera({0, 0, 14}, {1.33333, 0, 0});

template <class T> T tolerance() { return std::is_same_v<T, float> ? T(2e-6) : T(1e-12); }

template <class T> void checkDir(const rt::Ray<T>& ray, const glm::dvec3& expected) {
  for (int k = 0; k < 3; ++k) {
    CAPTURE(k);
    CHECK(double(ray.dir[k]) == Approx(expected[k]).margin(tolerance<T>()));
  }
}

// The course's pixelray line for a ray.
template <class T> std::string printed(const rt::Ray<T>& ray) {
  return rt::braces(glm::dvec3(ray.origin)) + " -> " + rt::braces(glm::dvec3(ray.dir));
}

}  // namespace

TEMPLATE_TEST_CASE("camera: the worked check of §d on simple.pov at 640x480", "", float, double) {
  using T = TestType;
  const rt::Camera<T> cam(kSimple, 640, 480);
  CHECK(cam.width() == 640);
  CHECK(cam.height() == 480);
  struct Case {
    int x, y;
    glm::dvec3 dir;
    const char* course;  // p1/test1..5 and the firsthit tests
  };
  const Case cases[] = {
      {320, 240, {0.0010416629322267603, 0.0010416655363907124, -0.9999989149350342}, "{0.0010 0.0010 -1.0000}"},
      {170, 120, {-0.2893075472241956, -0.23125309915810827, -0.9288827413882174}, "{-0.2893 -0.2313 -0.9289}"},
      {490, 120, {0.32587117934407567, -0.22839708672067605, -0.9174108922671507}, "{0.3259 -0.2284 -0.9174}"},
      {170, 360, {-0.2891776237296593, 0.23308355033044076, -0.9284655946772742}, "{-0.2892 0.2331 -0.9285}"},
      {490, 360, {0.3257284257472795, 0.23020746878874349, -0.9170090043037084}, "{0.3257 0.2302 -0.9170}"},
      {320, 160, {0.0010276636232874991, -0.16339892460003322, -0.9865595447549174}, "{0.0010 -0.1634 -0.9866}"},
      {400, 240, {0.16539796764875458, 0.0010273191375448183, -0.9862263720429764}, "{0.1654 0.0010 -0.9862}"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.x, c.y);
    const rt::Ray<T> ray = cam.pixelRay(c.x, c.y);
    CHECK(ray.origin == rt::Vec3<T>(0, 0, 14));
    checkDir(ray, c.dir);
    CHECK(double(glm::length(ray.dir)) == Approx(1).margin(tolerance<T>()));
    CHECK(printed(ray) == std::string("{0.0000 0.0000 14.0000} -> ") + c.course);
  }
}

TEMPLATE_TEST_CASE("camera: pixel y grows upward and the corners are symmetric", "", float, double) {
  using T = TestType;
  const rt::Camera<T> cam(kSimple, 640, 480);
  const auto low = cam.pixelRay(0, 0).dir;
  const auto high = cam.pixelRay(639, 479).dir;
  checkDir(cam.pixelRay(0, 0), {-0.5117131567776935, -0.38358562578177213, -0.7687728616920695});
  CHECK(low.y < T(0));
  CHECK(high.x == Approx(-low.x).margin(tolerance<T>()));
  CHECK(high.y == Approx(-low.y).margin(tolerance<T>()));
  CHECK(high.z == Approx(low.z).margin(tolerance<T>()));
}

TEMPLATE_TEST_CASE("camera: simp_cam1..3 at pixel (320, 240), as p2/test6..8", "", float, double) {
  using T = TestType;
  const rt::Ray<T> cam1 = rt::Camera<T>(camera({-14, 0, 0}, {0, 0, 1.3333}), 640, 480).pixelRay(320, 240);
  checkDir(cam1, {0.9999989149594479, 0.0010416655364161435, 0.001041639494777622});
  CHECK(printed(cam1) == "{-14.0000 0.0000 0.0000} -> {1.0000 0.0010 0.0010}");
  const rt::Ray<T> cam2 = rt::Camera<T>(camera({14, 0, 0}, {0, 0, -1.3333}), 640, 480).pixelRay(320, 240);
  checkDir(cam2, {-0.9999989149594479, 0.0010416655364161435, -0.001041639494777622});
  CHECK(printed(cam2) == "{14.0000 0.0000 0.0000} -> {-1.0000 0.0010 -0.0010}");
  const rt::Ray<T> cam3 = rt::Camera<T>(camera({7, 0, 7}, {.94, 0, -.94}), 640, 480).pixelRay(320, 240);
  checkDir(cam3, {-0.706371642004901, 0.0010416655397504607, -0.7078403904159489});
  CHECK(printed(cam3) == "{7.0000 0.0000 7.0000} -> {-0.7064 0.0010 -0.7078}");
}

TEMPLATE_TEST_CASE("camera: pixelRay passes through the pixel's sample point", "", float, double) {
  using T = TestType;
  rt::CameraDesc desc = kSimple;
  const rt::Camera<T> centre(desc, 640, 480);
  CHECK(centre.pixelRay(170, 120).dir == centre.ray(T(170.5), T(120.5)).dir);
  desc.pixelOffset = {0, 1};  // the .cli convention
  const rt::Camera<T> corner(desc, 640, 480);
  CHECK(corner.pixelRay(170, 120).dir == centre.ray(T(170), T(121)).dir);
  // The image centre looks straight down the viewing direction.
  CHECK(centre.ray(T(320), T(240)).dir == rt::Vec3<T>(0, 0, -1));
}

// A camera that gives no finite eye rays is refused where the file sets it, in the arithmetic that renders it:
// never NaN rays and a blank image.
TEMPLATE_TEST_CASE("camera: degenerate cameras are a located error", "", float, double) {
  using T = TestType;
  rt::CameraDesc c = kSimple;
  c.loc = rt::SourceLoc{std::string("s.pov"), 3, 1};
  const auto message = [&](const rt::CameraDesc& desc) -> std::string {
    try {
      rt::Camera<T>(desc, 4, 4);
    } catch (const rt::ParseError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(message(c).empty());
  rt::CameraDesc close = c;
  close.location = {0, 0, 0};
  close.lookAt = {1e-300, 0, 0};
  CHECK(message(close) == "s.pov:3:1: error: the camera gives no image: its look_at is too close to or too far "
                          "from its location to give a direction");
  rt::CameraDesc far = c;
  far.location = {-1e308, 0, 0};
  far.lookAt = {1e308, 0, 0};
  CHECK(message(far) == std::string("s.pov:3:1: error: the camera gives no image: ") +
                            (std::is_same_v<T, float> ? "its location is too large for the arithmetic"
                                                      : "its look_at is too close to or too far from its location "
                                                        "to give a direction"));
  rt::CameraDesc along = c;
  along.up = {0, 0, -1};  // the view direction
  CHECK(message(along) == "s.pov:3:1: error: the camera gives no image: it looks along the plane of its up and "
                          "right vectors");
  rt::CameraDesc tiny = c;
  tiny.up = {0, 1e-300, 0};
  CHECK(message(tiny) == "s.pov:3:1: error: the camera gives no image: its up or right vector is too short");
  rt::CameraDesc huge = c;
  huge.right = {1e200, 0, 0};
  CHECK(message(huge) == "s.pov:3:1: error: the camera gives no image: its up or right vector is too long");
}

TEMPLATE_TEST_CASE("camera: an orthographic camera's rays are parallel, from the picture's point on its plane", "",
                   float, double) {
  rt::CameraDesc c = camera({0, 0, 14}, {4, 0, 0});
  c.up = {0, 3, 0};
  c.projection = rt::projectionNamed("orthographic");
  const rt::Camera<TestType> cam(c, 40, 30);
  // Pixel (0, 0)'s centre is (0.5, 0.5) pixels from the lower-left corner: Us = −½ + 0.5/40.
  const rt::Ray<TestType> corner = cam.pixelRay(0, 0);
  CHECK(corner.origin.x == Approx(-2 + 0.05).epsilon(1e-6));
  CHECK(corner.origin.y == Approx(-1.5 + 0.05).epsilon(1e-6));
  CHECK(corner.origin.z == Approx(14));
  const rt::Ray<TestType> other = cam.pixelRay(39, 29);
  CHECK(other.dir == corner.dir);
  CHECK(corner.dir.z == Approx(-1));
}

TEMPLATE_TEST_CASE("camera: POV-Ray's cylinder projections, against where POV-Ray's rays met the plane z = 10", "",
                   float, double) {
  // A camera at the origin looking along +z, right 4/3, up 1, angle 90, 16×12 pixels. POV-Ray's points (read
  // back from its pictures of a plane coloured by x and by y, to about ±0.25): type 1, pixel (0, 0) meets
  // (−9.01, 6.06); type 2, (−8.33, 8.63); type 3, (−9.01, 0.36); type 4, (−0.59, 8.63).
  struct Case {
    int type;
    double x, y;
  } cases[] = {{1, -9.01, 6.06}, {2, -8.33, 8.63}, {3, -9.01, 0.36}, {4, -0.59, 8.63}};
  for (const Case& k : cases) {
    rt::CameraDesc c = camera({0, 0, 0}, {4.0 / 3, 0, 0});
    c.lookAt = {0, 0, 1};
    c.projection = rt::projectionNamed("cylinder", k.type);
    c.angle = M_PI / 2;
    const rt::Camera<TestType> cam(c, 16, 12);
    // Pixel (0, 0) of the picture's top row is row 11 counted upward.
    const rt::Ray<TestType> ray = cam.pixelRay(0, 11);
    const double t = (10 - double(ray.origin.z)) / double(ray.dir.z);
    CHECK(double(ray.origin.x) + t * double(ray.dir.x) == Approx(k.x).margin(0.25));
    CHECK(double(ray.origin.y) + t * double(ray.dir.y) == Approx(k.y).margin(0.25));
  }
}

TEMPLATE_TEST_CASE("camera: POV-Ray's ultra wide angle and spherical projections, against POV-Ray's rays", "", float,
                   double) {
  // As above; POV-Ray's points for pixel (0, 0): ultra wide angle (−10.62, 8.04), spherical with angle 90
  // (and so 45 up) (−9.01, 4.96).
  struct Case {
    const char* projection;
    double vertical, x, y;
  } cases[] = {{"ultra_wide_angle", 0.75 * M_PI / 2, -10.62, 8.04}, {"spherical", M_PI / 4, -9.01, 4.96}};
  for (const Case& k : cases) {
    rt::CameraDesc c = camera({0, 0, 0}, {4.0 / 3, 0, 0});
    c.lookAt = {0, 0, 1};
    c.projection = rt::projectionNamed(k.projection);
    c.angle = M_PI / 2;
    c.verticalAngle = k.vertical;
    const rt::Ray<TestType> ray = rt::Camera<TestType>(c, 16, 12).pixelRay(0, 11);
    const double t = 10 / double(ray.dir.z);
    CHECK(t * double(ray.dir.x) == Approx(k.x).margin(0.25));
    CHECK(t * double(ray.dir.y) == Approx(k.y).margin(0.25));
  }
}

TEMPLATE_TEST_CASE("camera: POV-Ray's fisheye, omnimax and panoramic projections, against POV-Ray's rays", "", float,
                   double) {
  // A camera at the origin looking along +z, right 4/3, up 1, 16×12 pixels. POV-Ray's directions, read from
  // its 16-bit pictures of a unit sphere round the camera coloured by the direction (to about ±3e-5);
  // pixels counted from the picture's top-left corner.
  struct Case {
    const char* projection;
    double angle;
    int x, row;
    glm::dvec3 dir;
  } cases[] = {
      {"fisheye", 180, 8, 1, {0.10234, 0.92096, 0.37597}},
      {"fisheye", 180, 2, 6, {-0.98813, -0.08983, 0.12465}},
      {"fisheye", 180, 4, 3, {-0.73458, 0.52468, 0.43023}},
      {"fisheye", 270, 8, 1, {0.10808, 0.97263, -0.20574}},
      {"fisheye", 270, 4, 3, {-0.80804, 0.57717, -0.118}},
      {"omnimax", 90, 8, 6, {0.09062, 0.21761, 0.97183}},
      {"omnimax", 90, 0, 6, {-0.987, 0.15801, 0.02971}},
      {"omnimax", 90, 8, 10, {0.08708, -0.48754, 0.86874}},
      {"omnimax", 90, 4, 3, {-0.54363, 0.65246, 0.52798}},
      {"panoramic", 90, 0, 0, {-0.17208, 0.98502, 0.01271}},
      {"panoramic", 90, 0, 6, {-0.99243, -0.09847, 0.07332}},
      {"panoramic", 90, 4, 3, {-0.61337, 0.55642, 0.56054}},
      {"panoramic", 90, 12, 6, {0.84662, -0.10814, 0.52111}},
  };
  for (const Case& k : cases) {
    CAPTURE(k.projection, k.angle, k.x, k.row);
    rt::CameraDesc c = camera({0, 0, 0}, {4.0 / 3, 0, 0});
    c.lookAt = {0, 0, 1};
    c.projection = rt::projectionNamed(k.projection);
    c.angle = glm::radians(k.angle);
    const rt::Ray<TestType> ray = rt::Camera<TestType>(c, 16, 12).pixelRay(k.x, 11 - k.row);
    for (int i = 0; i < 3; ++i) CHECK(double(ray.dir[i]) == Approx(k.dir[i]).margin(1e-4));
  }
}

TEMPLATE_TEST_CASE("camera: a fisheye draws nothing outside its circle, an omnimax nothing below its dome", "", float,
                   double) {
  rt::CameraDesc c = camera({0, 0, 0}, {4.0 / 3, 0, 0});
  c.lookAt = {0, 0, 1};
  c.angle = M_PI;
  c.projection = rt::projectionNamed("fisheye");
  const rt::Camera<TestType> fisheye(c, 16, 12);
  CHECK(fisheye.hasBlanks());
  // POV-Ray's picture is black at (0, 0) and (0, 6) (x = −0.9375·4/3 is outside the circle) and drawn at (2, 6).
  CHECK(fisheye.blank(fisheye.pixelRay(0, 11)));
  CHECK(fisheye.blank(fisheye.pixelRay(0, 5)));
  CHECK_FALSE(fisheye.blank(fisheye.pixelRay(2, 5)));
  c.projection = rt::projectionNamed("omnimax");
  const rt::Camera<TestType> omnimax(c, 16, 12);
  // POV-Ray's picture is black at (15, 11), outside the circle, and at (4, 11), inside it but more than 45°
  // below the view; it is drawn at (5, 11).
  CHECK(omnimax.blank(omnimax.pixelRay(15, 0)));
  CHECK(omnimax.blank(omnimax.pixelRay(4, 0)));
  CHECK_FALSE(omnimax.blank(omnimax.pixelRay(5, 0)));
  c.projection = rt::projectionNamed("panoramic");
  CHECK_FALSE(rt::Camera<TestType>(c, 16, 12).hasBlanks());
}

TEMPLATE_TEST_CASE("camera: a normal bends each eye ray as a surface's, read at the picture's point", "", float,
                   double) {
  // gradient x's slope, sampled on POV-Ray's four points about the picture's point, is (2/15, 0, 0) for a
  // normal of amount 1: the unit direction less it, made unit again. POV-Ray's picture of a plane at z = 10
  // coloured by x (16-bit, gamma 1): the 80×60 picture's pixel (40, 30) meets it at x = −1.2088, 0.1248 plain.
  const rt::SceneDesc scene = rt::test::pov(R"(
camera { location 0 direction z right x*4/3 up y look_at z angle 90 normal { gradient x 1 translate 0.25*x } })");
  const rt::Camera<TestType> cam(scene.camera, 80, 60);
  const rt::Ray<TestType> ray = cam.pixelRay(40, 29);  // row 30 from the top
  rt::CameraDesc plain = scene.camera;
  plain.normal = nullptr;
  const glm::dvec3 d = glm::normalize(glm::dvec3(rt::Camera<double>(plain, 80, 60).pixelRay(40, 29).dir));
  checkDir(ray, glm::normalize(d - glm::dvec3(2.0 / 15, 0, 0)));
  CHECK(10 * double(ray.dir.x) / double(ray.dir.z) == Approx(-1.2088).margin(0.001));
  CHECK(10 * d.x / d.z == Approx(0.1248).margin(0.001));
}
