// PLY (Greg Turk's polygon file format): a text header of elements and their properties, then the elements'
// values as text or as binary numbers of either byte order. The vertex element's x y z, nx ny nz and u v (or
// s t, texture_u texture_v) and the face element's vertex_indices list are kept; other elements and properties
// are read past.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "raytrace/parse/mesh_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"

namespace rt {

namespace {

using mesh_file::lineOf;

enum class Format { Ascii, Little, Big };

struct Type {
  const char* name;
  const char* alias;
  int size;
  bool integer, isSigned;
};

constexpr Type kTypes[] = {
    {"char", "int8", 1, true, true},      {"uchar", "uint8", 1, true, false},    {"short", "int16", 2, true, true},
    {"ushort", "uint16", 2, true, false}, {"int", "int32", 4, true, true},       {"uint", "uint32", 4, true, false},
    {"float", "float32", 4, false, true}, {"double", "float64", 8, false, true},
};

struct Property {
  std::string name;
  const Type* type = nullptr;
  const Type* countType = nullptr;  // a list's, or null for a single value
};

struct Element {
  std::string name;
  uint64_t count = 0;
  uint64_t line = 0;  // of its header line
  std::vector<Property> properties;
};

// The words of a header line.
std::vector<std::string> words(std::string_view line) {
  std::vector<std::string> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.emplace_back(line.substr(start, i - start));
  }
  return out;
}

class PlyReader {
 public:
  PlyReader(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  MeshFile read() {
    readHeader();
    for (const Element& e : elements_) {
      if (e.name == "vertex") readVertices(e);
      else readFaces(e);
    }
    if (format_ == Format::Ascii) {
      skipSpace();
      if (pos_ < bytes_.size()) fail("there is more after the last element's values");
    }
    mesh_file::checkNotEmpty(name_, mesh_);
    return std::move(mesh_);
  }

 private:
  std::string_view bytes_;
  const std::string& name_;
  size_t pos_ = 0;
  uint64_t line_ = 1;  // of pos_, in the header and in an ascii body
  Format format_ = Format::Ascii;
  std::vector<Element> elements_;
  uint64_t vertexCount_ = 0;
  MeshFile mesh_;

  // Where a value begins: its line in a header or an ascii body, its byte offset in a binary body.
  struct Place {
    size_t pos;
    uint64_t line;
  };
  Place place() const { return {pos_, line_}; }
  std::string where(const Place& p) const {
    if (p.line == 0) return printable(name_, kMaxQuotedPath) + ":byte " + std::to_string(p.pos);
    return lineOf(name_, p.line);
  }
  [[noreturn]] void fail(const std::string& message) const { throw MeshFileError(where(place()), message); }

  // The next header line, without its end.
  std::string_view headerLine() {
    const size_t end = bytes_.find('\n', pos_);
    if (end == std::string_view::npos) fail("the header ends before its end_header line");
    std::string_view line = bytes_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return line;
  }

  const Type* type(const std::string& word) const {
    for (const Type& t : kTypes) {
      if (word == t.name || word == t.alias) return &t;
    }
    fail("unknown property type " + quote(word) + " (char, uchar, short, ushort, int, uint, float, double)");
  }

  uint64_t count(const std::string& word) const {
    char* end = nullptr;
    errno = 0;
    const unsigned long long n = word.empty() || word[0] == '-' ? 0 : std::strtoull(word.c_str(), &end, 10);
    if (!end || *end || errno) fail("an element count must be a whole number, found " + quote(word));
    return n;
  }

  void readHeader() {
    if (words(headerLine()) != std::vector<std::string>{"ply"}) fail("a PLY file begins with the line \"ply\"");
    bool formatSeen = false;
    for (++line_;; ++line_) {
      const std::vector<std::string> w = words(headerLine());
      const std::string first = w.empty() ? "" : w[0];
      if (first == "end_header" && w.size() == 1) break;
      if (first == "comment" || first == "obj_info") continue;
      if (first == "format") {
        if (w.size() != 3 || w[2] != "1.0")
          fail("the format line must be: format <ascii | binary_little_endian | binary_big_endian> 1.0");
        if (w[1] == "ascii") format_ = Format::Ascii;
        else if (w[1] == "binary_little_endian") format_ = Format::Little;
        else if (w[1] == "binary_big_endian") format_ = Format::Big;
        else fail("unknown format " + quote(w[1]) + " (ascii, binary_little_endian, binary_big_endian)");
        formatSeen = true;
      } else if (first == "element") {
        if (w.size() != 3) fail("an element line must be: element <name> <count>");
        for (const Element& e : elements_) {
          if (e.name == w[1]) fail("a second " + quote(w[1]) + " element");
        }
        elements_.push_back({w[1], count(w[2]), line_, {}});
      } else if (first == "property") {
        if (elements_.empty()) fail("a property before any element");
        Property p;
        if (w.size() == 5 && w[1] == "list") {
          p.countType = type(w[2]);
          if (!p.countType->integer) fail("a list's count type must be an integer type, found " + quote(w[2]));
          p.type = type(w[3]);
          p.name = w[4];
        } else if (w.size() == 3) {
          p.type = type(w[1]);
          p.name = w[2];
        } else {
          fail("a property line must be: property <type> <name>, or property list <type> <type> <name>");
        }
        elements_.back().properties.push_back(p);
      } else {
        fail("a header line begins with format, element, property, comment, obj_info or end_header, found " +
             quote(first));
      }
    }
    if (!formatSeen) fail("the header has no format line");
    if (format_ != Format::Ascii) line_ = 0;  // from here on, places are byte offsets
    else ++line_;
    checkCounts();
  }

  // Each element's least size times its count must fit in what the file has left: an absurd count is refused
  // before anything is allocated for it.
  void checkCounts() {
    const uint64_t left = bytes_.size() - pos_;
    for (const Element& e : elements_) {
      uint64_t least = 0;
      for (const Property& p : e.properties) {
        // A value in text is a digit and a space at least (the last value of the file without its space).
        least += format_ == Format::Ascii ? 2 : uint64_t(p.countType ? p.countType->size : p.type->size);
      }
      if (least == 0 && e.count > 0) {
        throw MeshFileError(lineOf(name_, e.line), "the element " + quote(e.name) + " has no properties");
      }
      if (least > 0 && e.count > (left + 1) / least) {
        throw MeshFileError(lineOf(name_, e.line), std::to_string(e.count) + " " + e.name + " elements need " +
                                                       "more bytes than the file has after its header");
      }
      if (e.name == "vertex") vertexCount_ = e.count;
    }
  }

  void skipSpace() {
    for (; pos_ < bytes_.size(); ++pos_) {
      const char c = bytes_[pos_];
      if (c == '\n') ++line_;
      else if (c != ' ' && c != '\t' && c != '\r') break;
    }
  }

  // The next value, as a double (which holds every PLY number exactly: none is wider than 32 bits but double).
  double value(const Type& t) {
    if (format_ == Format::Ascii) {
      skipSpace();
      const size_t start = pos_;
      while (pos_ < bytes_.size() && !std::strchr(" \t\r\n", bytes_[pos_])) ++pos_;
      if (pos_ == start) fail("the file ends inside an element");
      const std::string word(bytes_.substr(start, pos_ - start));
      char* end = nullptr;
      const double v = std::strtod(word.c_str(), &end);
      if (*end) fail("expected a number, found " + quote(word));
      if (t.integer && (v != std::floor(v) || std::fabs(v) > 4294967295.0)) {
        fail("expected a whole number (" + std::string(t.name) + "), found " + quote(word));
      }
      return v;
    }
    if (bytes_.size() - pos_ < size_t(t.size)) fail("the file ends inside an element");
    unsigned char b[8];
    std::memcpy(b, bytes_.data() + pos_, size_t(t.size));
    const bool swap = (format_ == Format::Big) == (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__);
    if (swap) {
      for (int i = 0; i < t.size / 2; ++i) std::swap(b[i], b[t.size - 1 - i]);
    }
    pos_ += size_t(t.size);
    const auto as = [&](auto x) {
      std::memcpy(&x, b, sizeof x);
      return double(x);
    };
    switch (t.size * 4 + (t.integer ? (t.isSigned ? 1 : 0) : 2)) {
      case 5:
        return as(int8_t());
      case 4:
        return as(uint8_t());
      case 9:
        return as(int16_t());
      case 8:
        return as(uint16_t());
      case 17:
        return as(int32_t());
      case 16:
        return as(uint32_t());
      case 18:
        return as(float());
      default:
        return as(double());
    }
  }

  // One element's values: each list handed to `list` with the place it began, the single values dropped.
  template <class List>
  void readLists(const Element& e, List&& list) {
    std::vector<double> items;
    for (uint64_t i = 0; i < e.count; ++i) {
      for (const Property& p : e.properties) {
        if (!p.countType) {
          value(*p.type);
          continue;
        }
        skipSpaceInText();
        const Place at = place();
        const double n = value(*p.countType);
        if (n < 0) fail("a list's length is negative: " + std::to_string(int64_t(n)));
        const uint64_t least = format_ == Format::Ascii ? 2 : uint64_t(p.type->size);
        if (uint64_t(n) > (bytes_.size() - pos_ + 1) / least)
          fail("a list of " + std::to_string(uint64_t(n)) + " values is longer than the rest of the file");
        items.resize(size_t(n));
        for (double& v : items) v = value(*p.type);
        list(p, items, at);
      }
    }
  }

  // The face element's corner lists; any other element's values read past.
  void readFaces(const Element& e) {
    readLists(e, [&](const Property& p, const std::vector<double>& items, const Place& at) {
      if (e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index")) face(items, where(at));
    });
  }

  void face(const std::vector<double>& corners, const std::string& at) {
    if (corners.size() < 3) {
      throw MeshFileError(at, "a face needs 3 corners or more, found " + std::to_string(corners.size()));
    }
    std::vector<uint32_t> v(corners.size());
    for (size_t k = 0; k < corners.size(); ++k) {
      if (corners[k] < 0 || corners[k] >= double(vertexCount_) || corners[k] != std::floor(corners[k])) {
        throw MeshFileError(at, "vertex index " + format(corners[k]) + " is not one of the " +
                                    std::to_string(vertexCount_) + " vertices (counted from 0)");
      }
      v[k] = uint32_t(corners[k]);
    }
    // A polygon is a fan of triangles from its first corner.
    for (size_t k = 1; k + 1 < v.size(); ++k) {
      if (mesh_.faces.size() == mesh_.faces.capacity()) {
        mesh_file::checkMemory(at, (2 * mesh_.faces.size() + 1) * sizeof(MeshFile::Face));
      }
      MeshFile::Face f;
      f.v = {v[0], v[k], v[k + 1]};
      mesh_.faces.push_back(f);
    }
  }

  static std::string format(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
  }

  void readVertices(const Element& e) {
    const auto find = [&](std::initializer_list<const char*> names) -> std::optional<size_t> {
      for (const char* n : names) {
        for (size_t i = 0; i < e.properties.size(); ++i) {
          if (e.properties[i].name == n && !e.properties[i].countType) return i;
        }
      }
      return std::nullopt;
    };
    const std::string at = lineOf(name_, e.line);
    const auto x = find({"x"}), y = find({"y"}), z = find({"z"});
    if (!x || !y || !z) throw MeshFileError(at, "the vertex element has no x, y and z properties");
    const auto nx = find({"nx"}), ny = find({"ny"}), nz = find({"nz"});
    const auto u = find({"u", "s", "texture_u", "texture_s"}), v = find({"v", "t", "texture_v", "texture_t"});
    const bool normals = nx && ny && nz, uvs = u && v;
    mesh_file::checkMemory(at, e.count * (sizeof(glm::dvec3) * (normals ? 2 : 1) + (uvs ? sizeof(glm::dvec2) : 0)));
    bool single = format_ != Format::Ascii;
    for (const Property& p : e.properties) {
      if (p.type->size == 8 && !p.type->integer) single = false;
    }
    mesh_.singlePrecision = single;
    mesh_.vertices.reserve(size_t(e.count));
    if (normals) mesh_.normals.reserve(size_t(e.count));
    if (uvs) mesh_.uvs.reserve(size_t(e.count));
    std::vector<double> values(e.properties.size());
    for (uint64_t i = 0; i < e.count; ++i) {
      skipSpaceInText();
      const Place start = place();
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const Property& p = e.properties[k];
        if (!p.countType) {
          values[k] = value(*p.type);
          continue;
        }
        const double n = value(*p.countType);
        const uint64_t least = format_ == Format::Ascii ? 2 : uint64_t(p.type->size);
        if (n < 0 || uint64_t(n) > (bytes_.size() - pos_ + 1) / least)
          fail("a list's length " + format(n) + " does not fit in the file");
        for (uint64_t j = 0; j < uint64_t(n); ++j) value(*p.type);
      }
      // The place is made only for the message: a string per vertex would cost more than reading it.
      const auto check = [&](const glm::dvec3& p, const char* what) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
          mesh_file::checkFinite(where(start), p, what);
        }
        return p;
      };
      mesh_.vertices.push_back(check({values[*x], values[*y], values[*z]}, "a vertex coordinate"));
      if (normals) mesh_.normals.push_back(check({values[*nx], values[*ny], values[*nz]}, "a normal coordinate"));
      if (uvs) mesh_.uvs.push_back(glm::dvec2(check({values[*u], values[*v], 0}, "a uv coordinate")));
    }
  }

  // In an ascii body, to the next value, so that a vertex's place is the line its values begin on.
  void skipSpaceInText() {
    if (format_ == Format::Ascii) skipSpace();
  }
};

}  // namespace

MeshFile readPly(std::string_view bytes, const std::string& name) {
  PlyReader reader(bytes, name);
  MeshFile mesh = reader.read();
  // Each vertex has its own normal and uv: a face indexes them as it indexes the vertices.
  for (MeshFile::Face& f : mesh.faces) {
    if (!mesh.normals.empty()) f.n = f.v;
    if (!mesh.uvs.empty()) f.uv = f.v;
  }
  return mesh;
}

}  // namespace rt
