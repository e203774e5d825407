#include "raytrace/image/exr_file.hpp"

#include <exception>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "raytrace/image/output_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"

namespace rt {

namespace {

constexpr const char* kChannels[] = {"R", "G", "B"};
constexpr long long kMaxExrSide = 32768;  // the largest side a render takes (commands.cpp)

// OpenEXR's output in memory: it seeks back to fill in its line offset table, which a file being written
// through OutputFile would allow too, but its bytes then go out in one write.
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (at_ + size_t(n) > bytes_.size()) bytes_.resize(at_ + size_t(n));
    std::copy(c, c + n, bytes_.begin() + long(at_));
    at_ += size_t(n);
  }
  uint64_t tellp() override { return at_; }
  void seekp(uint64_t pos) override { at_ = size_t(pos); }
  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  std::vector<unsigned char> bytes_;
  size_t at_ = 0;
};

Imath::Box2i box(const Region& r) { return Imath::Box2i({r.x0, r.y0}, {r.x1 - 1, r.y1 - 1}); }

// Slices of the three channels of `pixels`, which hold the pixels of `window`.
Imf::FrameBuffer frameBuffer(const Image& pixels, const Region& window) {
  Imf::FrameBuffer frame;
  for (int c = 0; c < 3; ++c) {
    const float* base = &pixels.data()->r + c;
    frame.insert(kChannels[c], Imf::Slice::Make(Imf::FLOAT, base, box(window), sizeof(Color)));
  }
  return frame;
}

void writeExr(const Image& pixels, const Region& window, int width, int height,
              const std::map<std::string, std::string>& attributes, const std::string& path) {
  MemoryStream stream;
  try {
    Imf::Header header(box(wholeImage(width, height)), box(window));
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* c : kChannels) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    for (const auto& [name, value] : attributes) header.insert(name, Imf::StringAttribute(value));
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frameBuffer(pixels, window));
    file.writePixels(window.height());
  } catch (const std::exception& e) {
    throw Error("cannot write " + quote(path, kMaxQuotedPath) + ": " + e.what());
  }
  writeFile(path, stream.bytes());
}

// The side of a picture read from a file: at least one pixel, at most what a render makes.
int side(int lo, int hi, const char* what) {
  const long long n = static_cast<long long>(hi) - lo + 1;
  if (n < 1 || n > kMaxExrSide) {
    throw Error("its " + std::string(what) + " window is " + std::to_string(n) + " pixels wide or high");
  }
  return int(n);
}

}  // namespace

void writeExr(const ExrImage& image, const std::string& path) {
  writeExr(image.pixels, image.window, image.width, image.height, image.attributes, path);
}

void writeExr(const Image& image, const std::string& path) {
  writeExr(image, wholeImage(image.width(), image.height()), image.width(), image.height(), {}, path);
}

ExrImage readExr(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const Imath::Box2i display = header.displayWindow(), data = header.dataWindow();
    const int width = side(display.min.x, display.max.x, "display");
    const int height = side(display.min.y, display.max.y, "display");
    const Region window{data.min.x - display.min.x, data.min.y - display.min.y, data.max.x - display.min.x + 1,
                        data.max.y - display.min.y + 1};
    Image pixels(side(data.min.x, data.max.x, "data"), side(data.min.y, data.max.y, "data"));
    for (const char* c : kChannels) {
      if (!header.channels().findChannel(c)) throw Error("it has no " + std::string(c) + " channel");
    }
    std::map<std::string, std::string> attributes;
    for (auto a = header.begin(); a != header.end(); ++a) {
      if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a.attribute())) attributes[a.name()] = s->value();
    }
    file.setFrameBuffer(frameBuffer(pixels, Region{data.min.x, data.min.y, data.max.x + 1, data.max.y + 1}));
    file.readPixels(data.min.y, data.max.y);
    return ExrImage{width, height, window, std::move(pixels), std::move(attributes)};
  } catch (const std::exception& e) {
    throw Error("cannot read " + quote(path, kMaxQuotedPath) + ": " + e.what());
  }
}

}  // namespace rt
