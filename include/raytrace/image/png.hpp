// PNG encoding of 8-bit RGB pixels (W3C PNG specification, 2nd edition, ISO/IEC 15948).
#pragma once

#include <vector>

namespace rt {

// The complete PNG file for `rgb` (width × height × 3 bytes, top row first). Rows are filtered with "Up" and
// compressed by zlib at level 1 in independent segments of about 128 KiB, `threads` at a time, each in an IDAT
// chunk of its own whose CRC its thread computes. The bytes depend only on the pixels, never on the thread
// count.
std::vector<unsigned char> encodePng(const unsigned char* rgb, int width, int height, int threads);

}  // namespace rt
