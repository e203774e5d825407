// The image formats read back with exact values (stb_image for .png and .hdr, OpenEXR for .exr), format by
// extension, and the safety of the output file: a planted symbolic link, a long name, an interrupting signal.
#include <catch2/catch.hpp>

#include <cmath>
#include <csignal>
#include <limits>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stb/stb_image.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <Imath/half.h>

#include "raytrace/image/exr_file.hpp"
#include "raytrace/image/image_file.hpp"
#include "raytrace/image/output_file.hpp"
#include "raytrace/image/png_file.hpp"
#include "raytrace/util/error.hpp"
#include "temp_dir.hpp"

using Mode = rt::Dialect::ToByte;

namespace {

// A 5 × 3 image of distinct values, some beyond [0, 1].
rt::Image sample() {
  rt::Image image(5, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) image.at(x, y) = rt::Color(0.25f * float(x), 0.5f * float(y), 3.0f - float(x * y));
  }
  return image;
}

}  // namespace

TEST_CASE("image files: the format follows the extension; others are refused with the names to use") {
  CHECK(rt::imageFormat("a.png") == rt::ImageFormat::Png);
  CHECK(rt::imageFormat("dir.d/a.hdr") == rt::ImageFormat::Hdr);
  CHECK(rt::imageFormat("a.exr") == rt::ImageFormat::Exr);
  CHECK_THROWS_WITH(rt::imageFormat("a.jpg"), "cannot write 'a.jpg': unknown image format '.jpg' (name it .png, .hdr or .exr)");
  CHECK(rt::imageFormat("a.PNG") == rt::ImageFormat::Png);
  CHECK_THROWS_WITH(rt::imageFormat(".png"), "cannot write '.png': no image format (name it .png, .hdr or .exr)");
  CHECK_THROWS_WITH(rt::imageFormat("out"), "cannot write 'out': no image format (name it .png, .hdr or .exr)");
  CHECK_THROWS_WITH(rt::imageFormat("v1.0/out"), "cannot write 'v1.0/out': no image format (name it .png, .hdr or .exr)");
}

TEST_CASE("image files: a folder that is missing, not a folder or not writable is found before writing") {
  const rt::test::TempDir dir;
  const std::string file = dir.write("f", "x");
  CHECK_NOTHROW(rt::checkImagePath(dir.file("a.png")));
  CHECK_THROWS_WITH(rt::checkImagePath(dir.file("no/a.png")),
                    "cannot write '" + dir.file("no/a.png") + "': No such file or directory");
  CHECK_THROWS_WITH(rt::checkImagePath(file + "/a.png"), "cannot write '" + file + "/a.png': Not a directory");
  // Issue 35: a read-only image or a FIFO named x.png was replaced without a word.
  const std::string old = dir.write("old.png", "x");
  CHECK_NOTHROW(rt::checkImagePath(old));
  REQUIRE(chmod(old.c_str(), 0444) == 0);
  CHECK_THROWS_WITH(rt::checkImagePath(old),
                    "cannot write '" + old + "': it is read-only (make it writable to replace it)");
  REQUIRE(mkfifo(dir.file("x.png").c_str(), 0600) == 0);
  CHECK_THROWS_WITH(rt::checkImagePath(dir.file("x.png")),
                    "cannot write '" + dir.file("x.png") + "': something other than a file is there");
  REQUIRE(mkdir(dir.file("d.png").c_str(), 0700) == 0);
  CHECK_THROWS_WITH(rt::checkImagePath(dir.file("d.png")),
                    "cannot write '" + dir.file("d.png") + "': something other than a file is there");
}

TEST_CASE("image files: .hdr holds the unclamped radiance to RGBE's 8-bit mantissa") {
  const rt::test::TempDir dir;
  const std::string path = dir.file("a.hdr");
  rt::writeImage(sample(), path, Mode::Round, 1);
  int w = 0, h = 0, n = 0;
  float* px = stbi_loadf(path.c_str(), &w, &h, &n, 3);
  REQUIRE(px);
  CHECK(w == 5);
  CHECK(h == 3);
  const rt::Image expected = sample();
  for (int row = 0; row < 3; ++row) {
    for (int x = 0; x < 5; ++x) {
      for (int c = 0; c < 3; ++c) {
        // RGBE shares one exponent between the channels: each keeps 8 bits below the largest's leading bit.
        // It has no sign: a negative channel is written as 0.
        const float want = std::max(0.0f, expected.at(x, 2 - row)[c]);
        const float largest = std::max({expected.at(x, 2 - row).r, expected.at(x, 2 - row).g, expected.at(x, 2 - row).b});
        CHECK(std::abs(px[(row * 5 + x) * 3 + c] - want) <= largest / 128);
      }
    }
  }
  // Values RGBE represents exactly come back exactly: 0.25 steps below 4 are multiples of 2⁻⁶.
  CHECK(px[(2 * 5 + 1) * 3 + 0] == 0.25f);  // bottom row, x = 1: (0.25, 0, 3)
  CHECK(px[(2 * 5 + 1) * 3 + 2] == 3.0f);
  stbi_image_free(px);
  CHECK(dir.names() == std::vector<std::string>{"a.hdr"});
}

TEST_CASE("image files: .hdr writes a negative or NaN channel as 0") {
  const rt::test::TempDir dir;
  rt::Image image(1, 1);
  image.at(0, 0) = rt::Color(-1.0f, std::nanf(""), 2.0f);
  rt::writeImage(image, dir.file("a.hdr"), Mode::Round, 1);
  int w = 0, h = 0, n = 0;
  float* px = stbi_loadf(dir.file("a.hdr").c_str(), &w, &h, &n, 3);
  REQUIRE(px);
  CHECK(std::vector<float>(px, px + 3) == std::vector<float>{0, 0, 2});
  stbi_image_free(px);
}

TEST_CASE("image files: .exr holds the exact floats, and a tile its window and attributes") {
  const rt::test::TempDir dir;
  rt::writeImage(sample(), dir.file("a.exr"), Mode::Round, 1);
  const rt::ExrImage whole = rt::readExr(dir.file("a.exr"));
  CHECK(whole.width == 5);
  CHECK(whole.height == 3);
  CHECK(whole.window == rt::Region{0, 0, 5, 3});
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) CHECK(whole.pixels.at(x, y) == sample().at(x, y));
  }
  // A tile: columns 1-3 of the top two rows of a 5 × 3 picture.
  rt::Image part(3, 2);
  part.at(0, 1) = rt::Color(std::nextafter(1.0f, 2.0f), -0.0f, 1e30f);  // the region's top-left
  part.at(2, 0) = rt::Color(std::numeric_limits<float>::denorm_min(), 7, -3);
  rt::writeExr(rt::ExrImage{5, 3, rt::Region{1, 0, 4, 2}, std::move(part), {{"raytrace.scene", "s.pov"}}},
               dir.file("t.exr"));
  const rt::ExrImage tile = rt::readExr(dir.file("t.exr"));
  CHECK(tile.width == 5);
  CHECK(tile.height == 3);
  CHECK(tile.window == rt::Region{1, 0, 4, 2});
  CHECK(tile.attributes == std::map<std::string, std::string>{{"raytrace.scene", "s.pov"}});
  CHECK(tile.pixels.at(0, 1) == rt::Color(std::nextafter(1.0f, 2.0f), 0, 1e30f));
  CHECK(std::signbit(tile.pixels.at(0, 1).g));
  CHECK(tile.pixels.at(2, 0) == rt::Color(std::numeric_limits<float>::denorm_min(), 7, -3));
  CHECK(dir.names() == std::vector<std::string>{"a.exr", "t.exr"});
}

TEST_CASE("image files: reading what is not OpenEXR names the file") {
  const rt::test::TempDir dir;
  const std::string path = dir.write("x.exr", "not an image");
  CHECK_THROWS_WITH(rt::readExr(path), Catch::StartsWith("cannot read '" + path + "': "));
  CHECK_THROWS_WITH(rt::readExr(dir.file("none.exr")), Catch::StartsWith("cannot read '" + dir.file("none.exr") + "': "));
}

// Issue 35: 27 bytes declaring a 2 GiB attribute took 2.1 GB before OpenEXR found the file short; a FIFO
// blocked merge for ever; OpenEXR's own message repeated the path over several lines.
TEST_CASE("image files: an OpenEXR header is checked against the file before OpenEXR allocates what it says") {
  const rt::test::TempDir dir;
  // Magic, version 2, then an attribute "a" of type "s" declaring 0x7fffffff bytes, and 11 bytes more.
  const std::string huge("\x76\x2f\x31\x01\x02\x00\x00\x00" "a\0s\0\xff\xff\xff\x7f" "12345678901", 27);
  const std::string path = dir.write("huge.exr", huge);
  CHECK_THROWS_WITH(rt::readExr(path), "cannot read '" + path +
                                           "': its attribute 'a' declares 2147483647 bytes, but only 11 are left in the file");
  const std::string multi = dir.write("multi.exr", std::string("\x76\x2f\x31\x01\x02\x10\x00\x00\0", 9));
  CHECK_THROWS_WITH(rt::readExr(multi),
                    "cannot read '" + multi + "': it is a multi-part or deep OpenEXR file, not a tile");
  REQUIRE(mkfifo(dir.file("fifo.exr").c_str(), 0600) == 0);
  CHECK_THROWS_WITH(rt::readExr(dir.file("fifo.exr")),
                    "cannot read '" + dir.file("fifo.exr") + "': it is not a regular file");
  // Re-saved lossily, as half floats (DWAB's loss) or with PXR24, a tile is not the render's floats: refused.
  for (const auto& [compression, type] : {std::pair{Imf::DWAB_COMPRESSION, Imf::HALF},
                                          std::pair{Imf::PXR24_COMPRESSION, Imf::FLOAT}}) {
    Imf::Header header(4, 4);
    header.compression() = compression;
    for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(type));
    std::vector<float> floats(16, 0.5f);
    std::vector<half> halves(16, half(0.5f));
    char* base = type == Imf::HALF ? reinterpret_cast<char*>(halves.data()) : reinterpret_cast<char*>(floats.data());
    const size_t size = type == Imf::HALF ? sizeof(half) : sizeof(float);
    {
      Imf::OutputFile file(dir.file("saved.exr").c_str(), header);
      Imf::FrameBuffer frame;
      for (const char* c : {"R", "G", "B"}) frame.insert(c, Imf::Slice(type, base, size, 4 * size));
      file.setFrameBuffer(frame);
      file.writePixels(4);
    }
    CHECK_THROWS_WITH(rt::readExr(dir.file("saved.exr")),
                      "cannot read '" + dir.file("saved.exr") + "': " +
                          (type == Imf::HALF ? std::string("its R channel is not 32-bit float")
                                             : "it is compressed with PXR24, which rounds its floats: they are not "
                                               "the render's"));
  }
  // A file cut short: OpenEXR's message, on one line.
  rt::writeExr(rt::Image(4, 4), dir.file("whole.exr"));
  const std::string cut = dir.write("cut.exr", rt::test::readAll(dir.file("whole.exr")).substr(0, 340));
  try {
    rt::readExr(cut);
    FAIL("read a file cut short");
  } catch (const rt::Error& e) {
    CHECK(std::string(e.what()).find('\n') == std::string::npos);
  }
}

TEST_CASE("output file: a symbolic link planted at any name in the folder is never written through") {
  const rt::test::TempDir dir;
  const std::string victim = dir.write("victim.txt", "keep me");
  // The old temporary name, and a spread of names: the new one is random, so none of them is used, and a
  // link is not followed even if it were (O_EXCL | O_NOFOLLOW).
  REQUIRE(symlink(victim.c_str(), dir.file("out.png.tmp" + std::to_string(getpid())).c_str()) == 0);
  rt::writeFile(dir.file("out.png"), {'a', 'b'});
  CHECK(rt::test::readAll(victim) == "keep me");
  CHECK(rt::test::readAll(dir.file("out.png")) == "ab");
  CHECK(dir.names().size() == 3);
}

TEST_CASE("output file: a name of 251 characters, the most with room for no suffix, is written") {
  const rt::test::TempDir dir;
  const std::string name = std::string(247, 'n') + ".png";
  rt::writeFile(dir.file(name), {'x'});
  CHECK(dir.names() == std::vector<std::string>{name});
  const std::string tooLong = std::string(252, 'n') + ".png";
  // The message quotes the path's first 256 characters (util/message.hpp).
  CHECK_THROWS_WITH(rt::writeFile(dir.file(tooLong), {'x'}),
                    "cannot write '" + dir.file(tooLong).substr(0, 256) + "...': File name too long");
  CHECK(dir.names() == std::vector<std::string>{name});
}

// Issue 35: QUIT, USR1, ALRM, PIPE and XCPU used to leave the temporary file behind.
TEST_CASE("output file: a signal that ends the process while writing removes the temporary file, keeps the old one") {
  for (const int sig : {SIGTERM, SIGINT, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGPIPE, SIGXCPU, SIGVTALRM,
                        SIGPROF}) {
    CAPTURE(sig);
    const rt::test::TempDir dir;
    const std::string target = dir.write("out.png", "the previous picture");
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      // The signal arrives in the middle of the writing: the file is open, half written, never committed.
      rt::OutputFile file(target);
      file.write("half", 4);
      raise(sig);
      _exit(0);  // not reached: the signal ends the process
    }
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    CHECK(dir.names() == std::vector<std::string>{"out.png"});
    CHECK(rt::test::readAll(target) == "the previous picture");
  }
}

TEST_CASE("output file: a file not committed is removed, and the previous one kept") {
  const rt::test::TempDir dir;
  const std::string target = dir.write("out.png", "old");
  {
    rt::OutputFile file(target);
    file.write("new", 3);
  }
  CHECK(dir.names() == std::vector<std::string>{"out.png"});
  CHECK(rt::test::readAll(target) == "old");
}
