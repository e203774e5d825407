// Work spread over threads: the renderer's tiles, the PNG encoder's segments, a large scene's objects.
#pragma once

#include <cstddef>
#include <functional>

namespace rt {

// The number of threads a render uses unless told otherwise: every core the machine reports.
int defaultThreads();

// Runs task(i) for every i in [0, count) on `threads` threads, the calling one included, handing out indices in
// increasing order as threads become free. What a task computes must not depend on which thread runs it. If a
// task throws, no new index is started and the first exception is rethrown once all threads have stopped. The
// threads besides the caller are kept from one call to the next; a call made while they run another call's
// tasks (from inside a task, or from another thread) runs all its tasks on its own thread.
void parallelFor(int count, int threads, const std::function<void(int)>& task);

// Starts the threads parallelFor runs on besides the calling one, for `threads` threads, without waiting for
// them: started before a step that runs on one thread (reading a file), they are running by the time the
// parallel work comes. parallelFor starts any it lacks itself; where the system refuses a thread (ulimit -u,
// memory for its stack), it runs on the threads it has.
void startHelpers(int threads);

// Objects per task where a scene's objects are made or bounded on several threads: enough work to pay for
// handing it out, and chunks enough to share out.
constexpr size_t kObjectChunk = 4096;

// parallelFor over the items [0, count) in chunks of `chunk` items: task(begin, end) for each chunk. For work
// per item too small to hand out one by one, as building a scene's objects.
void parallelForChunks(size_t count, size_t chunk, int threads, const std::function<void(size_t, size_t)>& task);

}  // namespace rt
