#include "simlink.h"

#include "protocol/v2codec.h"

#include <algorithm>

namespace hatpic {

namespace {

// The message type of one whole host frame, or 0 when it does not decode.
quint8 hostFrameType(const QByteArray &bytes)
{
    v2::FrameDecoder decoder(v2::Direction::FromHost);
    QList<v2::Frame> frames;
    decoder.feed(bytes, frames);
    return frames.isEmpty() ? quint8(0) : v2::messageType(frames.first().message);
}

} // namespace

SimLink::SimLink(const SimulatedDevice::Config &config, QObject *parent)
    : ByteLink(parent), m_config(config), m_faults(makeFaultInjector(config)), m_timer(this)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(kTickMs);
    connect(&m_timer, &QTimer::timeout, this, &SimLink::tick);
}

SimLink::~SimLink() = default;

bool SimLink::open()
{
    if (m_device)
        return true;
    m_device = std::make_unique<SimulatedDevice>(m_config);
    m_clock.start();
    if (!m_faultClock.isValid())
        m_faultClock.start();
    m_lastNs = 0;
    m_timer.start();
    return true;
}

void SimLink::close()
{
    m_timer.stop();
    m_device.reset();
}

bool SimLink::isOpen() const
{
    return m_device != nullptr;
}

qint32 SimLink::baud() const
{
    if (m_device)
        return m_device->baud();
    if (m_config.baud > 0)
        return m_config.baud;
    return defaultBaud(m_config.wireProtocol());
}

void SimLink::write(const QByteArray &bytes)
{
    if (!m_device)
        return;
    if (m_dropCount > 0 && (m_dropType == 0 || hostFrameType(bytes) == m_dropType)) {
        --m_dropCount;
        ++m_dropped;
        return;
    }
    if (m_faults)
        m_device->receive(m_faults->toDevice(bytes, faultClock()));
    else
        m_device->receive(bytes);
}

void SimLink::setHand(const HandInput &hand)
{
    m_config.hand = hand;
    if (m_device)
        m_device->setHand(hand);
}

void SimLink::dropHostFrames(int count, quint8 type)
{
    m_dropCount = std::max(0, count);
    m_dropType = type;
}

void SimLink::injectToHost(const QByteArray &bytes)
{
    if (m_device && !bytes.isEmpty())
        Q_EMIT bytesReceived(bytes);
}

void SimLink::sever(const QString &reason)
{
    if (!m_device)
        return;
    close();
    Q_EMIT failed(reason);
}

void SimLink::tick()
{
    if (!m_device)
        return;
    const qint64 now = m_clock.nsecsElapsed();
    const double dt = std::min(kMaxAdvance, static_cast<double>(now - m_lastNs) * 1e-9);
    m_lastNs = now;
    if (m_faults) // host frames held back by a delay reach the device when due
        m_device->receive(m_faults->toDevice({}, faultClock()));
    if (dt > 0)
        m_device->advance(dt);
    QByteArray out = m_device->takeOutput();
    if (m_faults)
        out = m_faults->toHost(out, faultClock());
    if (!out.isEmpty() && !m_silenced)
        Q_EMIT bytesReceived(out);
}

} // namespace hatpic
