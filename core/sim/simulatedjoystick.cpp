#include "simulatedjoystick.h"

#include "sim/simlink.h"

#include <QMutexLocker>

namespace hatpic {

SimulatedJoystick::SimulatedJoystick(const SimulatedDevice::Config &config, QObject *parent)
    : QObject(parent), m_config(config)
{
    qRegisterMetaType<HandInput>(); // handChanged crosses to the session's thread
}

SimulatedJoystick::~SimulatedJoystick() = default;

ByteLink *SimulatedJoystick::makeLink(qint32 baud, QObject *parent)
{
    Q_UNUSED(baud);
    auto *link = new SimLink(config(), parent);
    // The link lives on the session's thread: a hand moved here reaches it queued, in order; one
    // moved while the link was being made is taken now.
    connect(this, &SimulatedJoystick::handChanged, link, &SimLink::setHand);
    link->setHand(hand());
    const QMutexLocker lock(&m_mutex);
    m_link = link;
    return link;
}

SimulatedDevice::Config SimulatedJoystick::config() const
{
    const QMutexLocker lock(&m_mutex);
    return m_config;
}

void SimulatedJoystick::setConfig(const SimulatedDevice::Config &config)
{
    const QMutexLocker lock(&m_mutex);
    m_config = config;
}

void SimulatedJoystick::answerIn(ProtocolChoice choice)
{
    const QMutexLocker lock(&m_mutex);
    if (const auto protocol = chosenProtocol(choice))
        m_config.protocol = *protocol;
}

void SimulatedJoystick::setHand(const HandInput &hand)
{
    {
        const QMutexLocker lock(&m_mutex);
        m_config.hand = hand;
    }
    Q_EMIT handChanged(hand);
}

HandInput SimulatedJoystick::hand() const
{
    const QMutexLocker lock(&m_mutex);
    return m_config.hand;
}

SimLink *SimulatedJoystick::link() const
{
    const QMutexLocker lock(&m_mutex);
    return m_link.data();
}

} // namespace hatpic
