// --display with SDL2. Every SDL call is made on the window's own thread; the render's threads only fill the
// LivePicture, which the window copies from a few times a second.
#include "raytrace/app/display_window.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <future>
#include <mutex>
#include <string>
#include <thread>

#include <unistd.h>

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include "raytrace/image/png_file.hpp"
#include "raytrace/util/error.hpp"

namespace rt {

namespace {

// How often the window catches up with the render.
constexpr std::chrono::milliseconds kFrame(100);

// Whether the environment variable is set to something.
bool isSet(const char* name) {
  const char* value = std::getenv(name);
  return value && *value;
}

// Where the test of the window (tests/display.sh) asks for what the window shows at the end, as a PNG.
constexpr const char* kCaptureVariable = "RAYTRACE_DISPLAY_CAPTURE";

}  // namespace

struct DisplayWindow::Impl {
  const LivePicture& picture;
  std::ostream& errors;
  std::mutex mutex;
  std::condition_variable wake;
  bool stopping = false;
  bool open = false;
  std::thread thread;

  SDL_Window* window = nullptr;
  SDL_Renderer* renderer = nullptr;
  SDL_Texture* texture = nullptr;

  Impl(const LivePicture& p, std::ostream& e) : picture(p), errors(e) {}

  // Opens the window: "" or why it could not be opened.
  std::string start() {
    // SDL would otherwise turn Ctrl-C into a window event, and the render would not stop.
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "nearest");
    // Without a display SDL falls back to drawing off screen, which shows nothing; SDL_VIDEODRIVER still
    // chooses any driver on purpose.
    const bool chosen = isSet("SDL_VIDEODRIVER");
    if (!chosen && !isSet("DISPLAY") && !isSet("WAYLAND_DISPLAY")) {
      return "no display to show the picture on (neither DISPLAY nor WAYLAND_DISPLAY is set)";
    }
    if (SDL_Init(SDL_INIT_VIDEO) != 0) return std::string("no display to show the picture on (") + SDL_GetError() + ")";
    const std::string driver = SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "";
    if (!chosen && (driver == "offscreen" || driver == "dummy")) {
      SDL_Quit();
      return "no display to show the picture on";
    }
    // The picture's size, shrunk to fit the screen if it is larger, keeping its shape.
    int w = picture.width(), h = picture.height();
    SDL_Rect screen;
    if (SDL_GetDisplayUsableBounds(0, &screen) == 0 && (w > screen.w || h > screen.h)) {
      const double scale = std::min(double(screen.w) / w, double(screen.h) / h);
      w = std::max(1, int(w * scale));
      h = std::max(1, int(h * scale));
    }
    window = SDL_CreateWindow("raytrace", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, w, h, 0);
    if (window) renderer = SDL_CreateRenderer(window, -1, 0);
    if (renderer) {
      texture = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING, picture.width(),
                                  picture.height());
    }
    if (!texture) {
      const std::string why = std::string("cannot open a window (") + SDL_GetError() + ")";
      stop();
      return why;
    }
    SDL_RenderSetLogicalSize(renderer, picture.width(), picture.height());
    return "";
  }

  // Shows the picture as it stands; with `capture`, also writes what the window shows there.
  void draw(const char* capture) {
    const Rgb8Image bytes = picture.bytes();
    SDL_UpdateTexture(texture, nullptr, bytes.data(), bytes.width() * 3);
    SDL_RenderClear(renderer);
    SDL_RenderCopy(renderer, texture, nullptr, nullptr);
    // Read before SDL_RenderPresent, which may leave the back buffer undefined.
    if (capture) {
      int w = 0, h = 0;
      SDL_GetRendererOutputSize(renderer, &w, &h);
      Rgb8Image shown(w, h);
      try {
        if (SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_RGB24, shown.at(0, h - 1), w * 3) != 0) {
          throw Error(std::string("cannot read the window back (") + SDL_GetError() + ")");
        }
        writePng(shown, capture);
      } catch (const Error& e) {
        errors << "raytrace: warning: --display: " << e.what() << "\n";
      }
    }
    SDL_RenderPresent(renderer);
  }

  // Handles the window's events; false once the user has closed it (or pressed a key, when `keyCloses`).
  bool keepOpen(bool keyCloses) {
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
      if (event.type == SDL_QUIT || (keyCloses && event.type == SDL_KEYDOWN)) return false;
    }
    return true;
  }

  void run() {
    uint64_t shown = 0;
    bool showing = true;
    std::unique_lock<std::mutex> lock(mutex);
    for (bool done = false; !done;) {
      done = wake.wait_for(lock, kFrame, [this] { return stopping; });
      lock.unlock();
      showing = showing && keepOpen(false);
      if (!showing) SDL_HideWindow(window);
      const uint64_t rows = picture.rowsSeen();
      if (showing && rows != shown && !done) {
        draw(nullptr);
        shown = rows;
      }
      lock.lock();
    }
    lock.unlock();
    if (showing) {
      draw(std::getenv(kCaptureVariable));
      // Someone at a terminal gets to look at the finished picture.
      if (isatty(STDIN_FILENO)) {
        errors << "raytrace: the picture is done: close its window (or press a key in it) to finish\n";
        while (keepOpen(true)) SDL_Delay(50);
      }
    }
    stop();
  }

  void stop() {
    if (texture) SDL_DestroyTexture(texture);
    if (renderer) SDL_DestroyRenderer(renderer);
    if (window) SDL_DestroyWindow(window);
    texture = nullptr, renderer = nullptr, window = nullptr;
    SDL_Quit();
  }
};

DisplayWindow::DisplayWindow(const LivePicture& picture, std::ostream& errors)
    : impl_(std::make_unique<Impl>(picture, errors)) {
  std::promise<std::string> started;
  std::future<std::string> why = started.get_future();
  impl_->thread = std::thread([this, started = std::move(started)]() mutable {
    const std::string problem = impl_->start();
    started.set_value(problem);
    if (problem.empty()) impl_->run();
  });
  const std::string problem = why.get();
  if (problem.empty()) {
    impl_->open = true;
  } else {
    impl_->thread.join();
    errors << "raytrace: warning: --display: " << problem << "; rendering on\n";
  }
}

DisplayWindow::~DisplayWindow() {
  if (!impl_->open) return;
  {
    const std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->stopping = true;
  }
  impl_->wake.notify_one();
  impl_->thread.join();
}

bool DisplayWindow::open() const { return impl_->open; }

}  // namespace rt
