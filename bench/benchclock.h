// Timing for the benchmarks: the CPU time of the calling thread, best of several runs.
//
// CPU time, not wall time: the benchmarks run on a shared 2-core machine where other builds
// take turns on the cores, and a thread that is waiting for its turn uses no CPU time. The
// figures are therefore "per core" (work done per second of one core actually spent on it);
// caches and the other hyperthread still feel the load, so the best of several runs is taken.
#pragma once

#include <algorithm>
#include <ctime>

namespace benchclock {

//! CPU time of the calling thread [ns].
inline double threadNs()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

//! Runs `run(n)` `runs` times and returns the smallest CPU time per operation [ns].
template<typename F> double bestNsPer(long n, F &&run, int runs = 5)
{
    double best = 1e300;
    for (int r = 0; r < runs; ++r) {
        const double t0 = threadNs();
        run(n);
        best = std::min(best, (threadNs() - t0) / double(n));
    }
    return best;
}

} // namespace benchclock
