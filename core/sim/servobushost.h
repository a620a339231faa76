// An emulated STS3032 on a pseudo-terminal, in real time (hatpic-servo-sim, and tests): the
// servo's side of the bus of servo.md, bound to the simulator's ServoPlant and HandInput, for
// hatpic-fw-host to drive as if through a USB–TTL adapter.
//
// Lives on the thread that created it and needs that thread's event loop. Whenever bus bytes
// arrive (QSocketNotifier) and every ~1 ms (precise timer), the plant is advanced by the
// wall-clock time elapsed, in sub-steps of at most 1/ServoPlant::kMinSubStepRate; then the
// bytes are fed to the servo and its answer is written at once.
#pragma once

#include "link/pseudoterminal.h"
#include "sim/handinput.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <cstdint>
#include <memory>

class QSocketNotifier;
class QTimer;

namespace hatpic {

class EmulatedSts3032;
class ServoPlant;

class ServoBusHost : public QObject
{
    Q_OBJECT
public:
    static constexpr double kMaxCatchUp = 0.1; //!< longest time advanced at once [s]
    static constexpr int kTickMs = 1;          //!< plant advance period when the bus is idle [ms]

    struct Config
    {
        std::uint8_t id = 1;            //!< servo id on the bus
        std::int32_t centerTick = 1000; //!< present position when the knob is at θ = 0 [tick]
        double tauLimit = 0.44;         //!< servo torque limit, load ±1000 [N·m]
        double noise = 0;               //!< std-dev of the load reading's noise [N·m]
        std::uint64_t seed = 1;         //!< noise seed
        HandInput hand;                 //!< the operator's hand on the knob
    };

    explicit ServoBusHost(const Config &config, QObject *parent = nullptr);
    ~ServoBusHost() override; //!< stop()

    //! Opens the pty and starts the real-time loop. Empty string on success, else a sentence.
    QString start();
    //! Stops the loop, closes the pty and removes the link (if still ours).
    void stop();
    //! What a process that a fatal signal ends can still do: remove the link.
    //! Async-signal-safe (PseudoTerminal::removeLinkNow).
    void emergencyStop() const noexcept { m_pty.removeLinkNow(); }
    bool isRunning() const { return m_pty.isOpen(); }

    QString slavePath() const { return m_pty.slavePath(); }
    QString createLink(const QString &path); //!< PseudoTerminal::createLink

    const EmulatedSts3032 &servo() const { return *m_servo; }
    const ServoPlant &plant() const { return *m_plant; }
    double time() const { return m_time; } //!< emulated time since start [s]
    bool torqueEnabled() const;            //!< the torque enable register (40) is not 0

Q_SIGNALS:
    //! The torque enable register changed (a WRITE from the master).
    void torqueEnableChanged(bool enabled);

private:
    void advanceToNow();
    void serviceBus();

    Config m_config;
    std::unique_ptr<ServoPlant> m_plant;
    std::unique_ptr<EmulatedSts3032> m_servo;
    PseudoTerminal m_pty;
    QSocketNotifier *m_notifier = nullptr;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;
    qint64 m_lastNs = 0;
    double m_time = 0;
    bool m_torque = false;
};

} // namespace hatpic
