// writePng never leaves a partial or missing image behind: on any failure the previous file is untouched and
// no temporary file remains.
#include "raytrace/image.hpp"

#include <csignal>
#include <string>

#include <catch2/catch.hpp>
#include <sys/resource.h>
#include <sys/stat.h>

#include "raytrace/error.hpp"
#include "temp_dir.hpp"

using rt::test::TempDir;

namespace {

std::string errorOf(const rt::Image& image, const std::string& path) {
  try {
    rt::writePng(image, path, rt::Conventions::ToByte::Round);
  } catch (const rt::Error& e) {
    return e.what();
  }
  return "no error";
}

// A full disk, simulated: with the file size limit at 0 every write fails with EFBIG (SIGXFSZ ignored, as
// main() ignores it). Both are restored when the scope ends.
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

TEST_CASE("a successful write replaces the previous image", "[image]") {
  const TempDir dir("png-ok");
  const std::string path = dir.write("output.png", "previous render");
  rt::writePng(rt::Image(2, 2), path, rt::Conventions::ToByte::Round);
  CHECK(TempDir::read(path).substr(1, 3) == "PNG");
  CHECK(dir.entries() == 1);
}

TEST_CASE("a full disk leaves the previous image whole", "[image]") {
  const TempDir dir("png-full");
  const std::string path = dir.write("output.png", "previous render");
  std::string message;
  {
    const NoRoomToWrite full;
    message = errorOf(rt::Image(64, 64), path);
  }
  CHECK(message == "cannot write '" + path + "': File too large");
  CHECK(TempDir::read(path) == "previous render");
  CHECK(dir.entries() == 1);
}

TEST_CASE("a folder that does not exist is a one-line error", "[image]") {
  const TempDir dir("png-nodir");
  const std::string path = dir.file("no/such/folder/output.png");
  CHECK(errorOf(rt::Image(1, 1), path) == "cannot write '" + path + "': No such file or directory");
  CHECK(dir.entries() == 0);
}

TEST_CASE("a folder in the way of the image is left alone", "[image]") {
  const TempDir dir("png-folder");
  const std::string path = dir.file("output.png");
  REQUIRE(mkdir(path.c_str(), 0755) == 0);
  CHECK(errorOf(rt::Image(1, 1), path) == "cannot write '" + path + "': Is a directory");
  struct stat st;
  REQUIRE(stat(path.c_str(), &st) == 0);
  CHECK(S_ISDIR(st.st_mode));
  CHECK(dir.entries() == 1);
}
