#include "raytrace/image/png.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>

#include "raytrace/util/error.hpp"
#include "raytrace/util/parallel.hpp"

namespace rt {

namespace {

// Raw bytes per independently compressed segment: 30 segments at 1280×960, so that the threads finish close
// together; 64 KiB to 16 MiB segments give files within 0.3 % of each other on the bench scenes.
constexpr size_t kSegmentBytes = size_t(1) << 17;

const unsigned char kIdat[] = {'I', 'D', 'A', 'T'};

void putU32(std::vector<unsigned char>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>(v >> shift));
}

// A chunk: length, type, data, CRC-32 of type and data (§5.3).
void putChunk(std::vector<unsigned char>& out, const char* type, const unsigned char* data, size_t size) {
  putU32(out, uint32_t(size));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  putU32(out, uint32_t(crc32(0, out.data() + start, uInt(size + 4))));
}

// A segment of the zlib stream (RFC 1950), the data of an IDAT chunk of its own.
struct Segment {
  std::unique_ptr<unsigned char[]> data;  // the first also holds the stream's header
  size_t size = 0;
  uLong crc = 0;        // CRC-32 of "IDAT" and the data: the chunk's, but for the last one's trailer
  uLong adler = 1;      // Adler-32 of the segment's filtered rows
  size_t filtered = 0;  // their size
};

// A raw deflate stream at the fastest level, ended however its owner leaves.
struct Deflater {
  z_stream z{};
  Deflater() {
    if (deflateInit2(&z, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) throw Error("cannot start zlib");
  }
  ~Deflater() { deflateEnd(&z); }
  Deflater(const Deflater&) = delete;
  Deflater& operator=(const Deflater&) = delete;
};

// Rows [first, last) filtered and deflated, with everything their chunk needs computed on this thread. Every
// segment but the last ends with a sync flush, which byte-aligns it without marking the final block, so the
// segments concatenate into one valid deflate stream (RFC 1951 §3.2.3; the technique of pigz).
Segment compress(const unsigned char* rgb, size_t stride, int first, int last, bool final) {
  // zlib's 256 KiB of state first, the segment's output after it: freed below the output, which is kept, the
  // state's memory is what the next segment's state reuses, not fresh pages (docs/performance-notes.md,
  // "PNG segments").
  Deflater deflater;
  z_stream& z = deflater.z;
  Segment s;
  s.filtered = (stride + 1) * size_t(last - first);
  // The zlib header: deflate with a 32 KiB window, at the fastest level (RFC 1950 §2.2).
  const size_t header = first == 0 ? 2 : 0;
  // 16 bytes more than deflateBound cover the sync flush's empty stored block. Left unset: only the pages
  // deflate writes are ever touched, a few KiB of a smooth image's 128.
  const size_t capacity = header + deflateBound(&z, uLong(s.filtered)) + 16;
  s.data.reset(new unsigned char[capacity]);
  if (header) s.data[0] = 0x78, s.data[1] = 0x01;
  z.next_out = s.data.get() + header;
  z.avail_out = uInt(capacity - header);
  // Each row with filter type 2, "Up" (§9.2): each byte minus the byte above it, so smooth vertical gradients
  // become small numbers that deflate well. It is cheap and needs no per-row choice. Rows go to zlib one at a
  // time, as it copies them into its window anyway.
  std::vector<unsigned char> row(stride + 1);
  row[0] = 2;
  int status = Z_OK;
  for (int y = first; y < last && status == Z_OK; ++y) {
    const unsigned char* pixels = rgb + size_t(y) * stride;
    unsigned char* to = row.data() + 1;
    if (y == 0) {
      std::copy(pixels, pixels + stride, to);
    } else {
      for (size_t i = 0; i < stride; ++i) to[i] = static_cast<unsigned char>(pixels[i] - pixels[i - stride]);
    }
    s.adler = adler32(s.adler, row.data(), uInt(row.size()));
    z.next_in = row.data();
    z.avail_in = uInt(row.size());
    status = deflate(&z, y + 1 < last ? Z_NO_FLUSH : final ? Z_FINISH : Z_SYNC_FLUSH);
  }
  s.size = header + z.total_out;
  // A flush that filled the buffer to the last byte may not be complete (zlib.h, deflate()).
  if (status != (final ? Z_STREAM_END : Z_OK) || z.avail_out == 0) throw Error("zlib failed to compress the image");
  s.crc = crc32(crc32(0, kIdat, 4), s.data.get(), uInt(s.size));
  return s;
}

}  // namespace

std::vector<unsigned char> encodePng(const unsigned char* rgb, int width, int height, int threads) {
  const size_t stride = size_t(width) * 3;
  const int rowsPerSegment = int(std::max<size_t>(1, kSegmentBytes / (stride + 1)));
  const int count = (height + rowsPerSegment - 1) / rowsPerSegment;
  std::vector<Segment> segments(static_cast<size_t>(count));
  parallelFor(count, threads, [&](int s) {
    const int first = s * rowsPerSegment, last = std::min(height, first + rowsPerSegment);
    segments[size_t(s)] = compress(rgb, stride, first, last, s == count - 1);
  });

  std::vector<unsigned char> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  size_t size = png.size() + 25 + 12 + 4;  // IHDR and IEND chunks, the stream's trailer
  for (const Segment& s : segments) size += s.size + 12;
  png.reserve(size);
  std::vector<unsigned char> header;
  putU32(header, uint32_t(width));
  putU32(header, uint32_t(height));
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits per channel, RGB, deflate, adaptive filters, no interlace
  putChunk(png, "IHDR", header.data(), header.size());
  // The stream's trailer, in the last chunk, is the Adler-32 of all filtered bytes.
  uLong adler = segments[0].adler;
  for (size_t s = 1; s < segments.size(); ++s) {
    adler = adler32_combine(adler, segments[s].adler, z_off_t(segments[s].filtered));
  }
  for (size_t s = 0; s < segments.size(); ++s) {
    const bool final = s + 1 == segments.size();
    const Segment& segment = segments[s];
    putU32(png, uint32_t(segment.size + (final ? 4 : 0)));
    png.insert(png.end(), kIdat, kIdat + 4);
    png.insert(png.end(), segment.data.get(), segment.data.get() + segment.size);
    uLong crc = segment.crc;
    if (final) {
      putU32(png, uint32_t(adler));
      crc = crc32(crc, png.data() + png.size() - 4, 4);
    }
    putU32(png, uint32_t(crc));
  }
  putChunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace rt
