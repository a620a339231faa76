// What bench_bridge's measuring peer takes its figures with (benchpeer.h).
#include "benchpeer.h"

#include <QByteArray>
#include <QFile>
#include <QList>
#include <QString>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <thread>

using namespace std::chrono_literals;

namespace hatpic::bench {

//! utime + stime of a process [s]; −1 when it cannot be read.
double cpuSeconds(qint64 pid)
{
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray text = stat.readAll();
    // Fields after the command name in parentheses (which may hold spaces): state is field 3,
    // utime field 14, stime field 15 (proc(5)).
    const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
    if (fields.size() < 13)
        return -1;
    return double(fields[11].toLongLong() + fields[12].toLongLong()) / double(sysconf(_SC_CLK_TCK));
}

//! Nearest-rank percentile of sorted values.
double percentile(const std::vector<double> &sorted, double p)
{
    if (sorted.empty())
        return NAN;
    const auto rank = std::size_t(std::ceil(p * double(sorted.size())));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

void printRow(const char *what, std::vector<double> values, const char *note)
{
    std::sort(values.begin(), values.end());
    std::printf("%-40s %7zu %8.2f %8.2f %8.2f %8.2f  %s\n", what, values.size(),
                percentile(values, 0.50), percentile(values, 0.95), percentile(values, 0.99),
                values.empty() ? NAN : values.back(), note);
}

ros::WrenchStamped wrenchOf(double force)
{
    ros::WrenchStamped w;
    w.header.stamp = ros::timeFromSeconds(wallSeconds());
    w.header.frameId = "bench";
    w.wrench.force.z = force;
    return w;
}

RoundTrips measureRoundTrips(ros::Publisher &publisher, FeedbackProbe &feedback, int steps)
{
    RoundTrips r;
    feedback.expect(kGain * kForce / 2);
    const auto warmUpEnd = Clock::now() + 20s;
    while (Clock::now() < warmUpEnd && !r.warmedUp) {
        publisher.publish(wrenchOf(kForce / 2));
        r.warmedUp = feedback.waitUntil(Clock::now() + kStepPeriod).has_value();
    }
    if (!r.warmedUp)
        return r;
    std::this_thread::sleep_for(kStepPeriod);
    r.ms.reserve(std::size_t(steps));
    auto next = Clock::now();
    for (int i = 0; i < steps; ++i) {
        const double force = i % 2 == 0 ? -kForce : kForce;
        feedback.expect(kGain * force);
        std::this_thread::sleep_until(next);
        const auto sent = Clock::now();
        publisher.publish(wrenchOf(force));
        if (const auto seen = feedback.waitUntil(sent + kEchoTimeout))
            r.ms.push_back(msBetween(sent, *seen));
        else
            ++r.lost;
        next = std::max(sent + kStepPeriod, Clock::now());
    }
    return r;
}

} // namespace hatpic::bench
