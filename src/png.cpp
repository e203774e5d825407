#include "raytrace/png.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "raytrace/error.hpp"
#include "raytrace/parallel.hpp"

namespace rt {

namespace {

constexpr size_t kSegmentBytes = size_t(1) << 18;  // raw bytes per independently compressed segment
constexpr size_t kMaxChunk = size_t(1) << 30;      // IDAT data per chunk, below the 2³¹ − 1 limit (§5.3)

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

// Rows [first, last) with filter type 2, "Up" (§9.2): each byte minus the byte above it, so smooth vertical
// gradients become small numbers that deflate well. It is cheap and needs no per-row choice.
std::vector<unsigned char> filterRows(const unsigned char* rgb, size_t stride, int first, int last) {
  std::vector<unsigned char> out((stride + 1) * size_t(last - first));
  unsigned char* to = out.data();
  for (int y = first; y < last; ++y) {
    const unsigned char* row = rgb + size_t(y) * stride;
    *to++ = 2;
    if (y == 0) {
      std::copy(row, row + stride, to);
    } else {
      for (size_t i = 0; i < stride; ++i) to[i] = static_cast<unsigned char>(row[i] - row[i - stride]);
    }
    to += stride;
  }
  return out;
}

// Raw deflate of one segment. Every segment but the last ends with a sync flush, which byte-aligns it without
// marking the final block, so the segments concatenate into one valid deflate stream (RFC 1951 §3.2.3; the
// technique of pigz).
std::vector<unsigned char> deflateSegment(std::vector<unsigned char>& data, bool last) {
  z_stream z{};
  if (deflateInit2(&z, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) throw Error("cannot start zlib");
  std::vector<unsigned char> out(deflateBound(&z, uLong(data.size())) + 16);
  z.next_in = data.data();
  z.avail_in = uInt(data.size());
  z.next_out = out.data();
  z.avail_out = uInt(out.size());
  const int status = deflate(&z, last ? Z_FINISH : Z_SYNC_FLUSH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (status != (last ? Z_STREAM_END : Z_OK)) throw Error("zlib failed to compress the image");
  return out;
}

}  // namespace

std::vector<unsigned char> encodePng(const unsigned char* rgb, int width, int height, int threads) {
  const size_t stride = size_t(width) * 3;
  const int rowsPerSegment = int(std::max<size_t>(1, kSegmentBytes / (stride + 1)));
  const int segments = (height + rowsPerSegment - 1) / rowsPerSegment;
  const size_t count = size_t(segments);
  std::vector<std::vector<unsigned char>> compressed(count);
  std::vector<uLong> adlers(count);
  std::vector<size_t> sizes(count);
  parallelFor(segments, threads, [&](int s) {
    const int first = s * rowsPerSegment, last = std::min(height, first + rowsPerSegment);
    std::vector<unsigned char> filtered = filterRows(rgb, stride, first, last);
    adlers[size_t(s)] = adler32(1, filtered.data(), uInt(filtered.size()));
    sizes[size_t(s)] = filtered.size();
    compressed[size_t(s)] = deflateSegment(filtered, s == segments - 1);
  });

  // The zlib stream (RFC 1950): header for deflate with a 32 KiB window at the fastest level, the segments,
  // and the Adler-32 of all filtered bytes.
  std::vector<unsigned char> stream{0x78, 0x01};
  uLong adler = adlers[0];
  for (int s = 0; s < segments; ++s) {
    stream.insert(stream.end(), compressed[size_t(s)].begin(), compressed[size_t(s)].end());
    if (s > 0) adler = adler32_combine(adler, adlers[size_t(s)], z_off_t(sizes[size_t(s)]));
  }
  putU32(stream, uint32_t(adler));

  std::vector<unsigned char> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<unsigned char> header;
  putU32(header, uint32_t(width));
  putU32(header, uint32_t(height));
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits per channel, RGB, deflate, adaptive filters, no interlace
  putChunk(png, "IHDR", header.data(), header.size());
  for (size_t at = 0; at < stream.size(); at += kMaxChunk) {
    putChunk(png, "IDAT", stream.data() + at, std::min(kMaxChunk, stream.size() - at));
  }
  putChunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace rt
