// Limits that keep a file from a stranger from exhausting the machine. Each is checked where the memory would
// be taken, before taking it, and reported as one message the user can act on.
#pragma once

#include <cstdint>
#include <string>

namespace rt {

// The largest scene file read: 1 GiB, about seven million spheres written the course's way. The text is held
// in memory while it is parsed, so a bigger file is far more likely a mistake (a disk image, a log) than a
// scene.
constexpr std::uint64_t kMaxSceneFileBytes = std::uint64_t(1) << 30;

// The most text a POV-Ray scene's #write directives may produce, in all its files together: it is held in memory
// until the scene has parsed, and a runaway #while loop should stop with a message, not fill the memory.
constexpr std::uint64_t kMaxSceneWriteBytes = std::uint64_t(256) << 20;

// Memory budgeted per scene object: its description, its renderable copy and its share of the acceleration
// structure, with room to spare (docs/performance-notes.md, "Memory per object").
constexpr std::uint64_t kBytesPerObject = 1024;

// Address space a thread besides the main one may take: its stack (8 MiB, the usual default) and the 64 MiB
// that glibc reserves for the malloc arena of each thread that allocates. A thread is started only where this
// much is available, so that under a tight ulimit -v the work runs on fewer threads instead of failing.
constexpr std::uint64_t kBytesPerThread = std::uint64_t(72) << 20;

// Bytes this process can still take without pushing the machine into swap or the OOM killer: the kernel's
// MemAvailable, or less if an address-space limit (ulimit -v) leaves less.
std::uint64_t availableMemory();

// "<what> needs N MiB of memory, but only M MiB are available", or "" when `needed` fits in `available`.
std::string memoryShortage(const std::string& what, std::uint64_t needed, std::uint64_t available);

// Millions of tiny objects fit in a file of allowed size but not always in memory. A parser calls this as its
// object count grows from `previous` to `count`: each time the count passes a power of two P from 65536 on
// (so small scenes never ask), P more objects must fit. Returns "" or the message "<what> beyond P objects
// needs …".
std::string objectMemoryShortage(std::uint64_t previous, std::uint64_t count, const std::string& what);

}  // namespace rt
