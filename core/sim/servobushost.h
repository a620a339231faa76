// Emulated STS3032s on a pseudo-terminal, in real time (hatpic-servo-sim, and tests): the
// servos' side of the bus of servo.md, each bound to a ServoPlant and HandInput of its own, for
// hatpic-fw-host to drive as if through a USB–TTL adapter. One servo by default; up to
// kMaxAxes on one bus, as on the IMU branch's board (ids id, id + 1, …).
//
// Lives on the thread that created it and needs that thread's event loop. Whenever bus bytes
// arrive (QSocketNotifier) and every ~1 ms (precise timer), the plant is advanced by the
// wall-clock time elapsed, in sub-steps of at most 1/ServoPlant::kMinSubStepRate; then the
// bytes are fed to the servo and its answer is written at once.
#pragma once

#include "link/pseudoterminal.h"
#include "model/axes.h"
#include "sim/handinput.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

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
        std::uint8_t id = 1;            //!< the first servo's id on the bus
        std::int32_t centerTick = 1000; //!< present position when the knob is at θ = 0 [tick]
        double tauLimit = 0.44;         //!< servo torque limit, load ±1000 [N·m]
        double noise = 0;               //!< std-dev of the load reading's noise [N·m]
        std::uint64_t seed = 1;         //!< noise seed (servo k's: seed + k)
        HandInput hand;                 //!< the operator's hand on the first servo's knob
        //! Servos on the bus, 1 … kMaxAxes, with ids id … id + servos − 1 (the programs check
        //! both: PtyProgram::readServos).
        int servos = 1;
        std::array<HandInput, kMaxAxes - 1> otherHands{}; //!< on servos 2 … (idle by default)
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

    int servos() const { return int(m_servos.size()); }
    //! Servo `k` (0 = the first, id Config::id) and its knob.
    const EmulatedSts3032 &servo(int k = 0) const { return *m_servos[std::size_t(k)]; }
    const ServoPlant &plant(int k = 0) const { return *m_plants[std::size_t(k)]; }
    double time() const { return m_time; } //!< emulated time since start [s]
    //! Servo `k`'s torque enable register (40) is not 0.
    bool torqueEnabled(int k = 0) const;

Q_SIGNALS:
    //! Servo `k`'s torque enable register changed (a WRITE or SYNC_WRITE from the master).
    void torqueEnableChanged(int k, bool enabled);

private:
    void advanceToNow();
    void serviceBus();

    std::vector<std::unique_ptr<ServoPlant>> m_plants;
    std::vector<std::unique_ptr<EmulatedSts3032>> m_servos;
    std::vector<HandInput> m_hands;
    PseudoTerminal m_pty;
    QSocketNotifier *m_notifier = nullptr;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;
    qint64 m_lastNs = 0;
    double m_time = 0;
    std::vector<bool> m_torque;
};

} // namespace hatpic
