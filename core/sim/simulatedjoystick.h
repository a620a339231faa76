// The in-process simulated joystick as a program holds it: the link source it hands to the
// session (each connection opens a SimLink on a fresh SimulatedDevice of its configuration),
// and the simulated hand, which the program moves directly, from any thread.
#pragma once

#include "link/linksource.h"
#include "protocol/deviceinfo.h"
#include "sim/handinput.h"
#include "sim/simportname.h"
#include "sim/simulateddevice.h"

#include <QMutex>
#include <QObject>
#include <QPointer>

namespace hatpic {

class SimLink;

class SimulatedJoystick : public QObject, public LinkSource
{
    Q_OBJECT
public:
    explicit SimulatedJoystick(const SimulatedDevice::Config &config = {},
                               QObject *parent = nullptr);
    ~SimulatedJoystick() override;

    //! A SimLink on a new simulator of config() (the hand as it is now); `baud` is ignored: the
    //! emulated link's rate is the configuration's.
    ByteLink *makeLink(qint32 baud, QObject *parent) override;
    bool simulated() const override { return true; }

    SimulatedDevice::Config config() const;
    //! The next connection's simulator: `config` (its hand too, without handChanged).
    void setConfig(const SimulatedDevice::Config &config);
    //! The protocol the next connection's simulator speaks: the one chosen (legacy: the
    //! published firmware), or, for Auto, the one configured.
    void answerIn(ProtocolChoice choice);

    //! Moves the simulated hand: the running simulator's at once, the next one's from its start.
    void setHand(const HandInput &hand);
    HandInput hand() const;

    //! The link made last while it lives, else null: the test seams (the session's thread only).
    SimLink *link() const;

Q_SIGNALS:
    void handChanged(const hatpic::HandInput &hand);

private:
    mutable QMutex m_mutex; //!< the configuration is read on the session's thread
    SimulatedDevice::Config m_config;
    QPointer<SimLink> m_link;
};

} // namespace hatpic
