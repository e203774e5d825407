// --display: a window that shows the picture as render computes it, tile by tile (SDL2).
#pragma once

#include <memory>
#include <ostream>

#include "raytrace/app/live_picture.hpp"

namespace rt {

class DisplayWindow {
 public:
  // Opens a window showing `picture` and keeps it up to date. Without a display (or in a build without SDL2)
  // says so on `errors` in one line and shows nothing; the render goes on either way.
  DisplayWindow(const LivePicture& picture, std::ostream& errors);
  // Shows the finished picture; when standard input is a terminal, waits for the window to be closed (or a key
  // pressed in it) so that the picture can be looked at, then closes it.
  ~DisplayWindow();
  DisplayWindow(const DisplayWindow&) = delete;
  DisplayWindow& operator=(const DisplayWindow&) = delete;

  // Whether the window is showing.
  bool open() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rt
