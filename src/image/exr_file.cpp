#include "raytrace/image/exr_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <exception>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <vector>

#include <sys/stat.h>

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

std::uint32_t littleEndian(const std::string& bytes, size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = v << 8 | static_cast<unsigned char>(bytes[at + size_t(i)]);
  return v;
}

// Whether an attribute's value of `type` is as long as its declared size says: OpenEXR reads the types below by
// their own structure, not by the size, so a value that disagrees would set its reading apart from ours (and
// a preview's or a string vector's own counts would be allocated unchecked).
bool consistent(const std::string& type, const std::string& value) {
  static const std::map<std::string, size_t> fixed = {
      {"box2i", 16}, {"box2f", 16},   {"compression", 1}, {"lineOrder", 1}, {"envmap", 1},  {"deepImageState", 1},
      {"float", 4},  {"double", 8},   {"int", 4},         {"v2i", 8},       {"v2f", 8},     {"v2d", 16},
      {"v3i", 12},   {"v3f", 12},     {"v3d", 24},        {"m33f", 36},     {"m33d", 72},   {"m44f", 64},
      {"m44d", 128}, {"tiledesc", 9}, {"chromaticities", 32}, {"keycode", 28}, {"timecode", 8}, {"rational", 8}};
  const size_t n = value.size();
  if (const auto it = fixed.find(type); it != fixed.end()) return n == it->second;
  if (type == "chlist") {  // names, each with 16 bytes of description, then an empty name
    for (size_t at = 0; at < n;) {
      const size_t end = value.find('\0', at);
      if (end == std::string::npos) return false;
      if (end == at) return end + 1 == n;
      at = end + 1 + 16;
    }
    return false;
  }
  if (type == "preview") return n >= 8 && n - 8 == std::uint64_t(littleEndian(value, 0)) * littleEndian(value, 4) * 4;
  if (type == "stringvector") {  // strings, each after its length
    for (size_t at = 0; at < n;) {
      if (n - at < 4 || littleEndian(value, at) > n - at - 4) return false;
      at += 4 + littleEndian(value, at);
    }
  }
  return true;
}

// OpenEXR's decompressor allocates a block of lines for every channel at the data window's width as soon as the
// file is opened, so the windows and channels are checked first: sides no longer than a render's, and only the
// channels a tile has, each once (478 bytes declaring a 2-billion-pixel line took 1.5 GB).
void checkLineBuffers(const std::string& name, const std::string& type, const std::string& value) {
  if (type == "box2i" && (name == "dataWindow" || name == "displayWindow")) {
    const char* what = name == "dataWindow" ? "data" : "display";
    const auto at = [&](size_t i) { return static_cast<std::int32_t>(littleEndian(value, i)); };
    side(at(0), at(8), what);
    side(at(4), at(12), what);
  }
  if (name == "channels" && type == "chlist") {
    std::set<std::string> seen;
    for (size_t at = 0; value[at] != '\0'; at += 16 + 1) {
      const std::string channel = value.c_str() + at;
      at += channel.size();
      if (std::find_if(std::begin(kChannels), std::end(kChannels), [&](const char* c) { return channel == c; }) ==
          std::end(kChannels)) {
        throw Error("it has a channel " + quote(channel) + ", which no tile has");
      }
      if (!seen.insert(channel).second) throw Error("it has the channel " + quote(channel) + " twice");
    }
  }
}

// The header checked against the file before OpenEXR reads it: it allocates what an attribute declares, so 27
// bytes declaring 2 GiB would take 2 GiB. A value cannot be longer than the bytes left in the file, nor other
// than its type's structure says. Also refused here: what is not a regular file (a FIFO would block), a
// multi-part or deep file (not a tile).
void checkHeader(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) throw Error(std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw Error("it is not a regular file");
  std::ifstream in(path, std::ios::binary);
  unsigned char start[8];
  if (!in.read(reinterpret_cast<char*>(start), 8)) throw Error("it is too short for an OpenEXR file");
  if (start[0] != 0x76 || start[1] != 0x2f || start[2] != 0x31 || start[3] != 0x01) {
    throw Error("it is not an OpenEXR file");
  }
  if (start[5] & 0x18) throw Error("it is a multi-part or deep OpenEXR file, not a tile");
  const std::uint64_t size = std::uint64_t(st.st_size);
  constexpr size_t kMaxName = 255;  // OpenEXR's longest attribute or type name
  for (;;) {
    std::string name, type;
    if (!std::getline(in, name, '\0')) throw Error("its header ends early");
    if (name.empty()) return;
    if (!std::getline(in, type, '\0')) throw Error("its header ends early");
    if (name.size() > kMaxName || type.size() > kMaxName) throw Error("its header has a name too long");
    std::string n(4, '\0');
    if (!in.read(n.data(), 4)) throw Error("its header ends early");
    const std::uint64_t bytes = littleEndian(n, 0);
    const std::uint64_t at = std::uint64_t(in.tellg());
    if (bytes > size - at) {
      throw Error("its attribute " + quote(name) + " declares " + std::to_string(bytes) + " bytes, but only " +
                  std::to_string(size - at) + " are left in the file");
    }
    std::string value(bytes, '\0');
    in.read(value.data(), std::streamsize(bytes));
    if (!consistent(type, value)) {
      throw Error("its attribute " + quote(name) + " of type " + quote(type) + " is not " + std::to_string(bytes) +
                  " bytes long, as it declares");
    }
    checkLineBuffers(name, type, value);
  }
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
    checkHeader(path);
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const Imath::Box2i display = header.displayWindow(), data = header.dataWindow();
    const int width = side(display.min.x, display.max.x, "display");
    const int height = side(display.min.y, display.max.y, "display");
    const Region window{data.min.x - display.min.x, data.min.y - display.min.y, data.max.x - display.min.x + 1,
                        data.max.y - display.min.y + 1};
    Image pixels(side(data.min.x, data.max.x, "data"), side(data.min.y, data.max.y, "data"));
    for (const char* c : kChannels) {
      const Imf::Channel* channel = header.channels().findChannel(c);
      if (!channel) throw Error("it has no " + std::string(c) + " channel");
      if (channel->type != Imf::FLOAT) throw Error("its " + std::string(c) + " channel is not 32-bit float");
    }
    // A tile re-saved lossily keeps its attributes but not the render's floats. B44 and DWA lose only half
    // floats, refused above; PXR24 rounds 32-bit ones.
    if (header.compression() == Imf::PXR24_COMPRESSION) {
      throw Error("it is compressed with PXR24, which rounds its floats: they are not the render's");
    }
    std::map<std::string, std::string> attributes;
    for (auto a = header.begin(); a != header.end(); ++a) {
      if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a.attribute())) attributes[a.name()] = s->value();
    }
    file.setFrameBuffer(frameBuffer(pixels, Region{data.min.x, data.min.y, data.max.x + 1, data.max.y + 1}));
    file.readPixels(data.min.y, data.max.y);
    return ExrImage{width, height, window, std::move(pixels), std::move(attributes)};
  } catch (const std::exception& e) {
    // One bounded line: OpenEXR's own messages repeat the path, unquoted, over several lines.
    throw Error("cannot read " + quote(path, kMaxQuotedPath) + ": " + printable(e.what(), kMaxQuotedPath));
  }
}

}  // namespace rt
