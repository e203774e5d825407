// The one compilation of stb_image_write, with libdeflate as its zlib compressor: stb's own deflate is several
// times slower and compresses less (docs/performance.md).
#include <cstdlib>

#include <libdeflate.h>

namespace {

// STBIW_ZLIB_COMPRESS: a zlib stream (RFC 1950) of `data` in memory from malloc, which stb frees, or null.
// libdeflate's fastest level: a render's image is written once, and its size matters less than its time.
unsigned char* deflateForStb(unsigned char* data, int size, int* outSize, int /*quality*/) {
  libdeflate_compressor* compressor = libdeflate_alloc_compressor(1);
  if (!compressor) return nullptr;
  const size_t bound = libdeflate_zlib_compress_bound(compressor, size_t(size));
  auto* out = static_cast<unsigned char*>(std::malloc(bound));
  const size_t written = out ? libdeflate_zlib_compress(compressor, data, size_t(size), out, bound) : 0;
  libdeflate_free_compressor(compressor);
  if (written == 0) {
    std::free(out);
    return nullptr;
  }
  *outSize = int(written);
  return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS deflateForStb
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
