// A parallel loop on standard threads: f(i) for i in [0, count) on up to `threads` threads (0: one
// per core), each index once, in no fixed order. The first exception (lowest index) is rethrown
// after every thread has stopped. Results must not depend on which thread ran an index.
#pragma once

#include <functional>

namespace shapeproc::core {

// Threads a parallel loop uses: `threads` (0: one per core), at most `count`, at least 1.
int loop_threads(int threads, long long count);

void parallel_for(long long count, int threads, const std::function<void(long long)>& f);

}  // namespace shapeproc::core
