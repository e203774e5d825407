// User-facing errors. Thrown once where the problem is found, caught only in main(), printed as one line.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

#include "raytrace/util/message.hpp"

namespace rt {

// The name of a scene file, shared by every location in it. A scene has a location per token, so a location
// must be free to make and copy: names are interned for the life of the process (a handful of files), and a
// FileName is a pointer to one.
class FileName {
 public:
  FileName() = default;
  FileName(const std::string& name);  // NOLINT: implicit
  const std::string& str() const;
  friend bool operator==(const FileName& a, const std::string& b) { return a.str() == b; }

 private:
  const std::string* name_ = nullptr;  // into the intern table; null for no file
};

// A position in a scene file; line and column are 1-based, as editors show them.
struct SourceLoc {
  FileName file;
  int line = 0;
  int col = 0;

  // As messages show it: the file name printable (message.hpp), so a newline in it cannot split the line.
  std::string str() const {
    return printable(file.str(), kMaxQuotedPath) + ":" + std::to_string(line) + ":" + std::to_string(col);
  }
};

// Any error the user can fix: bad arguments, unreadable files, impossible values.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An error at a place in a scene file; what() reads "file:line:col: error: message".
class ParseError : public Error {
 public:
  ParseError(const SourceLoc& loc, const std::string& message)
      : Error(loc.str() + ": error: " + message), loc_(loc) {}
  const SourceLoc& loc() const { return loc_; }

 private:
  SourceLoc loc_;
};

}  // namespace rt
