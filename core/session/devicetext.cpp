#include "devicetext.h"

#include "protocol/deviceinfo.h"
#include "session/sessionwording.h"

namespace hatpic {

DeviceTextGate::DeviceTextGate(QObject *parent) : QObject(parent), m_interval(this)
{
    m_interval.setSingleShot(true);
    m_interval.setInterval(kIntervalMs);
    // At the end of an interval the held lines are told, and a new interval opens with the
    // next line.
    connect(&m_interval, &QTimer::timeout, this, [this] {
        flush();
        m_passed = 0;
    });
}

void DeviceTextGate::feed(const QString &text)
{
    if (!m_interval.isActive())
        m_interval.start();
    if (m_passed >= kLinesPerInterval) {
        ++m_held;
        return;
    }
    ++m_passed;
    Q_EMIT line(printableDeviceText(text));
}

void DeviceTextGate::flush()
{
    if (m_held == 0)
        return;
    const quint64 held = m_held;
    m_held = 0;
    Q_EMIT line(SessionWording::deviceLinesHeldBack(held, kLinesPerInterval, kIntervalMs));
}

} // namespace hatpic
