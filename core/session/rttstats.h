// Round-trip times of PING/PONG: last, median over a bounded window, and maximum.
#pragma once

#include <QList>
#include <QtGlobal>

namespace hatpic {

class RttStats
{
public:
    static constexpr int kWindow = 32; //!< samples the median is taken over

    void add(double ms);
    void clear();

    bool isEmpty() const { return m_count == 0; }
    double last() const { return m_last; } //!< -1 when none [ms]
    double median() const;                 //!< over the last kWindow samples; -1 when none [ms]
    double max() const { return m_max; }   //!< since clear(); -1 when none [ms]
    quint64 count() const { return m_count; }

private:
    QList<double> m_window; //!< ring of the last kWindow samples
    int m_next = 0;
    quint64 m_count = 0;
    double m_last = -1;
    double m_max = -1;
};

} // namespace hatpic
