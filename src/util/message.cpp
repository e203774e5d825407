#include "raytrace/util/message.hpp"

#include <algorithm>
#include <cstdio>
#include <unordered_map>

namespace rt {

std::string printable(std::string_view text, size_t most) {
  std::string out;
  const size_t shown = std::min(text.size(), most);
  for (size_t i = 0; i < shown; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
    } else {
      out += char(c);
    }
  }
  if (shown < text.size()) out += "...";
  return out;
}

std::string quote(std::string_view text, size_t most) { return "'" + printable(text, most) + "'"; }

std::string thousands(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

namespace {

// The part of "file:line:col: warning: text" from its kind on ("warning: text"), or the whole line.
std::string_view what(std::string_view line) {
  for (const std::string_view kind : {": warning: ", ": error: "}) {
    const size_t at = line.find(kind);
    if (at != std::string_view::npos) return line.substr(at + 2);
  }
  return line;
}

}  // namespace

std::vector<std::string> collapseRepeats(const std::vector<std::string>& lines) {
  std::unordered_map<std::string_view, size_t> seen;  // what → its index in `firsts`
  std::vector<size_t> firsts, counts;
  for (size_t i = 0; i < lines.size(); ++i) {
    const auto [it, added] = seen.emplace(what(lines[i]), firsts.size());
    if (added) {
      firsts.push_back(i);
      counts.push_back(0);
    } else {
      ++counts[it->second];
    }
  }
  std::vector<std::string> out;
  for (size_t k = 0; k < firsts.size(); ++k) {
    out.push_back(lines[firsts[k]]);
    if (counts[k] > 0) out.back() += " (and " + thousands(counts[k]) + " more like it)";
  }
  return out;
}

}  // namespace rt
