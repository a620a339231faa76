#include "sim/cyclelog.h"

#include "model/cyclequantities.h"

#include <type_traits>

namespace hatpic {

namespace {

using Cycle = SimulatedDevice::Cycle;

template<typename T> QByteArray number(T value)
{
    if constexpr (std::is_integral_v<T>)
        return QByteArray::number(qulonglong(value));
    else
        return QByteArray::number(double(value), 'g', 9);
}

} // namespace

QByteArray cycleLogHeader()
{
    QByteArray line = "t_s";
    forEachCycleQuantity<Cycle>([&line](const CycleQuantity &q, auto) {
        line += ',' + QByteArray(q.name.data(), qsizetype(q.name.size()));
    });
    return line + ",tau_total";
}

QByteArray cycleLogLine(const Cycle &cycle)
{
    QByteArray line = number(cycle.t);
    forEachCycleQuantity<Cycle>(
        [&](const CycleQuantity &, auto member) { line += ',' + number(cycle.*member); });
    return line + ',' + number(cycle.tau_total);
}

} // namespace hatpic
