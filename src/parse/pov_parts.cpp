#include "raytrace/parse/pov_parts.hpp"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <new>

#include "raytrace/util/error.hpp"
#include "raytrace/util/parallel.hpp"

namespace rt {

namespace {

// Fewer bytes than an object takes in the files we know: the benchmark's spheres take 160, the course's
// objects more (each has a pigment and a finish). A denser file just grows its array once or twice more.
constexpr size_t kTypicalObjectBytes = 128;

// Line ends (LF, CRLF, lone CR) in `text`, as the tokenizer counts them. LFs are counted in runs of 255
// bytes, whose count fits in a byte: a loop the compiler vectorizes (docs/performance-notes.md).
int lineEnds(std::string_view text) {
  size_t n = 0;
  for (size_t run = 0; run < text.size(); run += 255) {
    const size_t end = std::min(text.size(), run + 255);
    unsigned char lf = 0;
    for (size_t i = run; i < end; ++i) lf += text[i] == '\n';
    n += lf;
  }
  for (size_t at = text.find('\r'); at != std::string_view::npos; at = text.find('\r', at + 1)) {
    if (at + 1 == text.size() || text[at + 1] != '\n') ++n;
  }
  return int(n);
}

// Whether a statement keyword opens the line that starts at `at`, after blanks.
bool statementStartsLine(std::string_view text, size_t at) {
  while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
  size_t end = at;
  while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) ++end;
  const std::string_view word = text.substr(at, end - at);
  return word == "camera" || word == "light_source" || isShapeKeyword(word);
}

}  // namespace

size_t objectRoom(size_t bytes) {
  if (bytes < kMinPartBytes) return 0;
  size_t room = 1;
  while (room < bytes / kTypicalObjectBytes) room *= 2;
  return room;
}

std::vector<size_t> partStarts(std::string_view text, int count) {
  std::vector<size_t> starts{0};
  for (int k = 1; k < count; ++k) {
    const size_t from = std::max(starts.back() + 1, text.size() / size_t(count) * size_t(k));
    for (size_t at = text.find_first_of("\n\r", from); at != std::string_view::npos;
         at = text.find_first_of("\n\r", at + 1)) {
      const size_t line = at + 1;  // a CR followed by LF does not end the line; its LF does
      if (text[at] == '\r' && line < text.size() && text[line] == '\n') continue;
      if (statementStartsLine(text, line)) {
        starts.push_back(line);
        break;
      }
    }
  }
  return starts;
}

std::optional<SceneDesc> parseParts(std::string_view text, const std::vector<size_t>& starts, int threads,
                                    const PovPartReader& read) {
  const size_t n = starts.size();
  std::vector<int> firstLines{1};
  for (size_t k = 1; k < n; ++k) {
    firstLines.push_back(firstLines.back() + lineEnds(text.substr(starts[k - 1], starts[k] - starts[k - 1])));
  }
  std::vector<std::optional<PovPart>> parts(n);
  parallelFor(int(n), threads, [&](int k) {
    const size_t begin = starts[size_t(k)], end = size_t(k) + 1 < n ? starts[size_t(k) + 1] : text.size();
    try {
      // The first part's list becomes the scene's, with room for the objects of the whole text, so that only
      // the other parts' objects are copied into it. The room of every part together is within the memory
      // parsePov() found for the whole text.
      const size_t room = objectRoom(k == 0 ? text.size() : end - begin);
      parts[size_t(k)] = read(text.substr(begin, end - begin), firstLines[size_t(k)], room, n);
    } catch (const ParseError&) {  // reported by the reading of the whole file
    } catch (const std::bad_alloc&) {  // so is a lack of memory, where the file's own checks see it
    }
  });
  int cameras = 0;
  size_t objects = 0;
  for (const auto& part : parts) {
    if (!part) return std::nullopt;
    cameras += part->cameras;
    objects += part->scene.objects.size();
  }
  if (cameras != 1) return std::nullopt;
  SceneDesc scene = std::move(parts[0]->scene);
  scene.objects.reserve(objects);
  for (size_t k = 1; k < n; ++k) {
    SceneDesc& s = parts[k]->scene;
    if (parts[k]->cameras == 1) scene.camera = s.camera;
    scene.lights.insert(scene.lights.end(), s.lights.begin(), s.lights.end());
    std::move(s.objects.begin(), s.objects.end(), std::back_inserter(scene.objects));
    std::move(s.warnings.begin(), s.warnings.end(), std::back_inserter(scene.warnings));
    s = SceneDesc();  // its memory back before the next part's objects are moved
  }
  return scene;
}

}  // namespace rt
