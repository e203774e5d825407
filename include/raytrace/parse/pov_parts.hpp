// A large POV text read in parts on several threads: where to cut it, and the parts' scenes put together.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "raytrace/scene/description.hpp"

namespace rt {

// Texts of at least this size are large: worth a thread as a part of a file (about 2 ms of reading), and
// worth reserving room for their objects.
constexpr size_t kMinPartBytes = size_t(256) << 10;

// The objects to reserve room for in a text of `bytes`: as many as a typical file of this size holds, so that a
// large file does not copy its objects into ever larger arrays as it is read (pages are only taken once
// objects fill them). A power of two, so that the array still doubles where parseObject() checks the memory
// (powers of two): it never grows past a check that would have stopped it. None for a small text.
size_t objectRoom(size_t bytes);

// What one part of a text holds: its statements, and how many of them were cameras.
struct PovPart {
  SceneDesc scene;
  int cameras;
};

// Reads `part`, one of `parts` read at once, as a file whose first line is `firstLine`, with room for `room`
// objects reserved; throws ParseError or std::bad_alloc where it cannot.
using PovPartReader = std::function<PovPart(std::string_view part, int firstLine, size_t room, std::uint64_t parts)>;

// Where to cut the text into about `count` parts of equal size: each cut is at the start of a line that a
// statement keyword opens, the first after its even share. Some may fall inside a statement or a comment
// after all; parseParts() finds out.
std::vector<size_t> partStarts(std::string_view text, int count);

// Reads the parts at once, as if each were a file. Together they mean what the whole file means when every
// part reads to its end without an error, so that each cut lay between two statements and outside any comment
// (a comment cannot hide a cut: a line comment ends before it, and a block comment left open is an error), and
// when the file has one camera (a second camera statement changes the first's). Otherwise nothing, and the
// whole file is read in one piece, for its exact error or meaning.
std::optional<SceneDesc> parseParts(std::string_view text, const std::vector<size_t>& starts, int threads,
                                    const PovPartReader& read);

}  // namespace rt
