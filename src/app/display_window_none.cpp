// --display in a build without SDL2 (CMakeLists.txt): the one message, and no window.
#include "raytrace/app/display_window.hpp"

namespace rt {

struct DisplayWindow::Impl {};

DisplayWindow::DisplayWindow(const LivePicture&, std::ostream& errors) {
  errors << "raytrace: warning: --display: this raytrace was built without SDL2, so it shows no window; "
            "rendering on\n";
}

DisplayWindow::~DisplayWindow() = default;

bool DisplayWindow::open() const { return false; }

}  // namespace rt
