// Colour to byte conversion and the image writer: exact bytes after a round trip through stb_image, no temporary
// file left behind, and an existing file untouched when the write fails.
#include <catch2/catch.hpp>

#include <csignal>
#include <cmath>
#include <limits>

#include <sys/fsuid.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stb/stb_image.h>

#include "raytrace/util/error.hpp"
#include "raytrace/image/image.hpp"
#include "raytrace/image/image_file.hpp"
#include "temp_dir.hpp"

using rt::Dialect;
using rt::toByte;
using Mode = Dialect::ToByte;

namespace {

// While alive, file permissions are checked as an unprivileged user, so that a read-only directory is
// read-only even when the tests run as root (root's fsuid change drops CAP_DAC_OVERRIDE; setfsuid(2)).
class Unprivileged {
 public:
  Unprivileged() : previous_(geteuid() == 0 ? setfsuid(65534) : -1) {}
  ~Unprivileged() {
    if (previous_ >= 0) setfsuid(uid_t(previous_));
  }

 private:
  int previous_;
};

// While alive, the disk is full as far as this process can tell: with the file size limit at 0 every write
// fails with EFBIG, and SIGXFSZ is ignored as main() ignores it.
class NoRoomToWrite {
 public:
  NoRoomToWrite() {
    getrlimit(RLIMIT_FSIZE, &saved_);
    rlimit none = saved_;
    none.rlim_cur = 0;
    setrlimit(RLIMIT_FSIZE, &none);
    previous_ = std::signal(SIGXFSZ, SIG_IGN);
  }
  ~NoRoomToWrite() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_);
  }

 private:
  rlimit saved_{};
  void (*previous_)(int) = nullptr;
};

}  // namespace

TEST_CASE("image: toByte rounds (course) or truncates (.cli)") {
  CHECK(toByte(0.0f, Mode::Round) == 0);
  CHECK(toByte(1.0f, Mode::Round) == 255);
  CHECK(toByte(0.5f, Mode::Round) == 128);     // 127.5 rounds up
  CHECK(toByte(0.5f, Mode::Truncate) == 127);
  CHECK(toByte(0.2f, Mode::Round) == 51);
  CHECK(toByte(0.2f, Mode::Truncate) == 51);
  CHECK(toByte(0.998f, Mode::Round) == 254);   // 254.49
  CHECK(toByte(0.999f, Mode::Round) == 255);   // 254.745
  CHECK(toByte(0.999f, Mode::Truncate) == 254);
  CHECK(toByte(1.0f / 255.0f, Mode::Truncate) == 1);
}

TEST_CASE("image: toByte clamps and maps NaN to black") {
  for (const Mode mode : {Mode::Round, Mode::Truncate}) {
    CHECK(toByte(1.5f, mode) == 255);
    CHECK(toByte(-0.5f, mode) == 0);
    CHECK(toByte(std::numeric_limits<float>::infinity(), mode) == 255);
    CHECK(toByte(-std::numeric_limits<float>::infinity(), mode) == 0);
    CHECK(toByte(std::nanf(""), mode) == 0);
    CHECK(toByte(-0.0f, mode) == 0);
  }
}

TEST_CASE("image: at(x, y) counts y upward from the bottom row") {
  rt::Image image(3, 2);
  image.at(0, 0) = rt::Color(1, 0, 0);
  image.at(2, 1) = rt::Color(0, 0, 1);
  CHECK(image.width() == 3);
  CHECK(image.height() == 2);
  CHECK(image.at(0, 0) == rt::Color(1, 0, 0));
  CHECK(image.at(2, 1) == rt::Color(0, 0, 1));
  CHECK(image.at(1, 0) == rt::Color(0));
}

TEST_CASE("image: writeImage of a .png round-trips through stb_image, bottom row last, and leaves no temporary file") {
  const rt::test::TempDir dir;
  rt::Image image(3, 2);
  image.at(0, 0) = rt::Color(1, 0, 0);          // bottom-left
  image.at(2, 1) = rt::Color(0.5f, 0.2f, 2.0f);  // top-right
  image.at(1, 1) = rt::Color(std::nanf(""), -1, 0.999f);
  for (const Mode mode : {Mode::Round, Mode::Truncate}) {
    const std::string path = dir.file("out.png");
    rt::writeImage(image, path, mode, 1);
    CHECK(dir.names() == std::vector<std::string>{"out.png"});
    int w = 0, h = 0, n = 0;
    unsigned char* px = stbi_load(path.c_str(), &w, &h, &n, 3);
    REQUIRE(px);
    CHECK(w == 3);
    CHECK(h == 2);
    CHECK(n == 3);
    const std::vector<unsigned char> bytes(px, px + 3 * 2 * 3);
    stbi_image_free(px);
    const unsigned char half = mode == Mode::Round ? 128 : 127;
    const unsigned char nearlyOne = mode == Mode::Round ? 255 : 254;
    // Top row first, as PNG stores it.
    CHECK(bytes == std::vector<unsigned char>{0, 0, 0,     0, 0, nearlyOne,  half, 51, 255,
                                              255, 0, 0,   0, 0, 0,          0, 0, 0});
  }
}

TEST_CASE("image: a failed write leaves an existing file untouched and no temporary file") {
  const rt::test::TempDir dir;
  const std::string target = dir.write("output.png", "the previous picture");
  REQUIRE(chmod(dir.path().c_str(), 0555) == 0);
  {
    const Unprivileged guard;
    CHECK_THROWS_WITH(rt::writeImage(rt::Image(2, 2), target, Mode::Round, 1),
                      "cannot write '" + target + "': Permission denied");
  }
  REQUIRE(chmod(dir.path().c_str(), 0755) == 0);
  CHECK(rt::test::readAll(target) == "the previous picture");
  CHECK(dir.names() == std::vector<std::string>{"output.png"});
}

TEST_CASE("image: a target that cannot be replaced is reported and the temporary file removed") {
  const rt::test::TempDir dir;
  dir.write("keep", "x");
  const std::string sub = dir.file("output.png");
  REQUIRE(mkdir(sub.c_str(), 0755) == 0);
  std::ofstream(sub + "/inside") << "y";
  CHECK_THROWS_WITH(rt::writeImage(rt::Image(2, 2), sub, Mode::Round, 1), "cannot write '" + sub + "': Is a directory");
  CHECK(dir.names() == std::vector<std::string>{"keep", "output.png"});
  CHECK(rt::test::readAll(sub + "/inside") == "y");
  CHECK_THROWS_WITH(rt::writeImage(rt::Image(2, 2), dir.file("missing/out.png"), Mode::Round, 1),
                    "cannot write '" + dir.file("missing/out.png") + "': No such file or directory");
}

TEST_CASE("image: a full disk leaves an existing file untouched and no temporary file") {
  const rt::test::TempDir dir;
  const std::string target = dir.write("output.png", "the previous picture");
  {
    const NoRoomToWrite full;
    CHECK_THROWS_WITH(rt::writeImage(rt::Image(64, 64), target, Mode::Round, 1),
                      "cannot write '" + target + "': File too large");
  }
  CHECK(rt::test::readAll(target) == "the previous picture");
  CHECK(dir.names() == std::vector<std::string>{"output.png"});
}

TEST_CASE("image: toByte rounds half up exactly as std::lround and truncates as a cast") {
  for (int k = 0; k <= 255; ++k) {
    // Every float within 64 steps of each rounding boundary k + 0.5 (after the ×255).
    float c = (float(k) + 0.5f) / 255.0f;
    for (int i = 0; i < 64; ++i) c = std::nextafter(c, 0.0f);
    for (int i = 0; i < 128; ++i, c = std::nextafter(c, 2.0f)) {
      const float v = std::min(c, 1.0f) * 255.0f;
      CHECK(int(rt::toByte(c, Mode::Round)) == std::lround(v));
      CHECK(int(rt::toByte(c, Mode::Truncate)) == int(v));
    }
  }
}
