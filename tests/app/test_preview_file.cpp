// --preview: the picture so far, as the rows arrive, written whole to its file; and a render's last preview
// is its image.
#include <catch2/catch.hpp>

#include <sstream>

#include "raytrace/app/commands.hpp"
#include "raytrace/app/live_picture.hpp"
#include "raytrace/app/preview_file.hpp"
#include "raytrace/image/exr_file.hpp"
#include "temp_dir.hpp"

namespace {

// The pixels of an OpenEXR file, top row first.
std::vector<rt::Color> pixelsOf(const std::string& path) {
  const rt::ExrImage exr = rt::readExr(path);
  const rt::Image& image = exr.pixels;
  return std::vector<rt::Color>(image.data(), image.data() + size_t(image.width()) * size_t(image.height()));
}

}  // namespace

TEST_CASE("preview: the rows that have arrived, black elsewhere, in the region's place") {
  // Columns 2-5 and rows 1-2 (from the top) of an 8 × 4 picture: picture rows 2 and 1 counted upward.
  const rt::Region region{2, 1, 6, 3};
  rt::LivePicture picture(4, region, rt::Dialect::ToByte::Round);
  const std::vector<rt::Color> row{{1, 0, 0}, {0, 0.5f, 0}, {0, 0, 2}};
  picture.row(3, 2, 6, row.data());  // the region's top row, but its first pixel
  CHECK(picture.rowsSeen() == 1);
  const rt::test::TempDir dir;
  const std::string path = dir.file("p.exr");
  std::ostringstream errors;
  {
    rt::PreviewFile preview(picture, path, rt::Dialect::ToByte::Round, errors, 3600);
    preview.write();
    const rt::Color black(0);
    CHECK(pixelsOf(path) == std::vector<rt::Color>{black, row[0], row[1], row[2], black, black, black, black});
    const rt::Rgb8Image bytes = picture.bytes();
    CHECK(std::vector<int>(bytes.data(), bytes.data() + 12) == std::vector<int>{0, 0, 0, 255, 0, 0, 0, 128, 0, 0, 0, 255});
    const std::vector<rt::Color> grey(4, rt::Color(0.25f));
    picture.row(2, 1, 6, grey.data());  // the region's bottom row, whole
  }
  // The last write, when the preview ends, has every row.
  CHECK(pixelsOf(path)[4] == rt::Color(0.25f));
  CHECK(dir.names() == std::vector<std::string>{"p.exr"});
  CHECK(errors.str().empty());
}

TEST_CASE("preview: a render's last preview is its image, and a preview file that cannot be written is refused") {
  const rt::test::TempDir dir;
  const std::string scene = dir.write(
      "s.pov", "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
               "light_source { <-100,100,100> color rgb <1.5,1.5,1.5> }\n"
               "sphere { <0,0,0>, 2 pigment { color rgb <1,0,1> } finish { ambient 0.2 diffuse 0.4 } }\n");
  std::ostringstream out, err;
  CHECK(rt::runCommand({"render", scene, "16", "12", "-o", dir.file("a.exr"), "--preview", dir.file("p.exr")}, out,
                       err) == 0);
  CHECK(err.str().empty());
  CHECK(pixelsOf(dir.file("p.exr")) == pixelsOf(dir.file("a.exr")));
  try {
    rt::runCommand({"render", scene, "16", "12", "-o", dir.file("b.exr"), "--preview", dir.file("p.tga")}, out, err);
    FAIL("no error");
  } catch (const std::exception& e) {
    CHECK(std::string(e.what()) == "cannot write '" + dir.file("p.tga") +
                                       "': unknown image format '.tga' (name it .png, .hdr or .exr)");
  }
}
