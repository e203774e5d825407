// Text from the input as a message shows it: one readable line however long or strange the input is.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

// The most characters of one piece of input a message quotes (a word, a number, an argument), and of a file
// name (paths run longer); the rest is cut and marked "...".
constexpr std::size_t kMaxQuoted = 60;
constexpr std::size_t kMaxQuotedPath = 256;

// `text` as it can stand in a one-line message: control bytes escaped (\n, \t, \r, \xNN) and cut to `most`
// characters with "..." after them.
std::string printable(std::string_view text, std::size_t most = kMaxQuoted);

// printable(text, most) between single quotes: "'name.pov'".
std::string quote(std::string_view text, std::size_t most = kMaxQuoted);

// A count with thousands separators: "299,999".
std::string thousands(std::size_t n);

// Message lines "file:line:col: warning: text" with each repeated "warning: text" kept once, at its first
// place, followed by " (and N more like it)": 300,000 identical warnings are one line.
std::vector<std::string> collapseRepeats(const std::vector<std::string>& lines);

}  // namespace rt
