#include "raytrace/image/interrupt_cleanup.hpp"

#include <atomic>
#include <climits>
#include <csignal>
#include <cstring>

#include <unistd.h>

namespace rt {

namespace {

// Every signal whose default action ends the process without the program's doing, bar SIGKILL (which
// cannot be caught) and SIGXFSZ (ignored: a full file is a write error, reported as one).
constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM,
                            SIGPIPE, SIGXCPU, SIGVTALRM, SIGPROF};

// Read by the handler, on any thread, so only what async-signal-safe code may use: a fixed buffer, published
// by a lock-free atomic flag.
char temporary[PATH_MAX + 1];
std::atomic<bool> registered{false};
static_assert(std::atomic<bool>::is_always_lock_free);

void onInterrupt(int sig) {
  if (registered.load(std::memory_order_acquire)) unlink(temporary);
  signal(sig, SIG_DFL);
  raise(sig);  // held back until this handler returns; then the default action ends the program
}

// Checked at every registration rather than once, so that a handler someone else put in since (a test
// harness does) cannot leave a temporary file behind.
void installHandlers() {
  for (const int sig : kSignals) {
    struct sigaction current {};
    sigaction(sig, nullptr, &current);
    if (current.sa_handler == SIG_IGN || current.sa_handler == onInterrupt) continue;
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    sigaction(sig, &action, nullptr);
  }
}

}  // namespace

void registerTemporary(const std::string& path) {
  installHandlers();
  registered.store(false, std::memory_order_release);
  // A longer path cannot be created (ENAMETOOLONG), so there is nothing to remove.
  std::strncpy(temporary, path.c_str(), PATH_MAX);
  temporary[PATH_MAX] = '\0';
  registered.store(true, std::memory_order_release);
}

void clearTemporary() { registered.store(false, std::memory_order_release); }

}  // namespace rt
