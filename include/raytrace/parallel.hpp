// Work spread over threads: the renderer's tiles and the PNG encoder's segments.
#pragma once

#include <functional>

namespace rt {

// The number of threads a render uses unless told otherwise: every core the machine reports.
int defaultThreads();

// Runs task(i) for every i in [0, count) on `threads` threads, the calling one included, handing out indices in
// increasing order as threads become free. What a task computes must not depend on which thread runs it. If a
// task throws, no new index is started and the first exception is rethrown once all threads have stopped.
void parallelFor(int count, int threads, const std::function<void(int)>& task);

}  // namespace rt
