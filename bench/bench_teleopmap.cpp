// bench_teleopmap [--threads N] [--duration S] — the stability map's speed: a 10 × 10 map
// (one-way delays 0 … 0.3 s, gains 0.005 … 0.05 N·m/N) of 20 s runs of robot.md's loop, in
// process on virtual time, spread over the threads (default 2, this machine's cores). Prints
// the wall time of the whole map (the target: under 10 s, issue 25), the CPU time per cell and
// the loop's cycles per CPU second, best of 3 maps. docs/performance.md quotes it.
#include "teleop/stabilitymap.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>

using namespace hatpic;

namespace {

double processCpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) * 1e-9;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    teleop::MapSpec spec;
    spec.threads = 2;
    spec.base.duration = 20;
    for (qsizetype i = 1; i + 1 < args.size(); i += 2) {
        if (args[i] == u"--threads")
            spec.threads = args[i + 1].toInt();
        else if (args[i] == u"--duration")
            spec.base.duration = args[i + 1].toDouble();
    }
    QString error;
    spec.delays = *teleop::parseValueList(QStringLiteral("0:0.3/10"), &error);
    spec.gains = *teleop::parseValueList(QStringLiteral("0.005:0.05/10"), &error);
    if (const QString problem = teleop::checkSpec(spec); !problem.isEmpty()) {
        std::fprintf(stderr, "bench_teleopmap: %s\n", qPrintable(problem));
        return 4;
    }
    double bestWall = 1e300, bestCpu = 1e300;
    qsizetype settled = 0;
    for (int run = 0; run < 3; ++run) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = processCpuSeconds();
        const auto cells = teleop::runMap(spec);
        const double cpu = processCpuSeconds() - c0;
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        bestWall = std::min(bestWall, wall);
        bestCpu = std::min(bestCpu, cpu);
        settled = std::count_if(cells.begin(), cells.end(),
                                [](const auto &c) { return c.result.settled; });
    }
    const qsizetype cells = spec.cellCount();
    const double cycles = double(cells) * (spec.base.duration * 1000 + 1);
    std::printf("map %lld cells × %g s on %d threads: wall %.2f s (best of 3), CPU %.1f ms per "
                "cell, %.0f loop cycles per CPU second; %lld cells settled\n",
                static_cast<long long>(cells), spec.base.duration, spec.threads, bestWall,
                1e3 * bestCpu / double(cells), cycles / bestCpu, static_cast<long long>(settled));
    return 0;
}
