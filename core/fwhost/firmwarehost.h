// hatpic-fw-host's engine: the firmware's device core (fw::DeviceCore<double>) on Linux, with
// the STS3032 on a serial port and protocol v2 served on a pseudo-terminal.
//
// Two contexts, as on the ESP32: the control cycle runs on a thread of its own, paced by
// clock_nanosleep(TIMER_ABSTIME) on CLOCK_MONOTONIC (SCHED_FIFO when the system grants it);
// the link runs on the thread that created this object, from its event loop (a
// QSocketNotifier on the pty and a 1 ms timer call serviceHost()). Only DeviceCore's lock-free
// queues and this class's mutex-guarded statistics cross between them.
#pragma once

#include "firmware/stsbus.h"
#include "fwhost/periodhistogram.h"
#include "link/faultinjector.h"
#include "link/pseudoterminal.h"
#include "model/axes.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

class QSocketNotifier;
class QTimer;

namespace hatpic {

class FdHostPort;
class MonotonicClock;
class ProfileParamStore;
class SerialServoPort;

namespace fw {
template<typename T> class DeviceCore;
template<typename T> class StsActuator;
} // namespace fw

class FirmwareHost : public QObject
{
    Q_OBJECT
public:
    //! USB–TTL adapters deliver replies in USB frames (1 ms on full-speed USB, plus the
    //! driver's latency timer): 5 ms covers them with margin, where the ESP32 uses 1 ms.
    static constexpr std::uint32_t kDefaultServoTimeoutUs = 5000;
    //! The servo's start-up (ping, position mode, present position, torque on) is tried this
    //! often before the servo is declared absent: a servo (or hatpic-servo-sim on a loaded
    //! machine) may answer its first request late. Between attempts the program waits
    //! kServoStartPauseMs, doubling each time (20, 40, 80, 160 ms): at most about 0.3 s and
    //! five timeouts before "does not answer". The ESP32 retries every second, forever.
    static constexpr int kServoStartAttempts = 5;
    static constexpr int kServoStartPauseMs = 20;
    static constexpr int kLinkTickMs = 1; //!< link service period when no bytes arrive [ms]

    struct Config
    {
        QString servoPath;                 //!< serial device of the bus
        std::uint32_t servoBaud = 1000000; //!< [bit/s]
        std::uint8_t servoId = 1;          //!< 0…253 (knob 1's)
        //! Knobs: servos with ids servoId … servoId + servos − 1 on the one bus (1…kMaxAxes;
        //! 4: the IMU branch's board), each run by its own controller.
        int servos = 1;
        std::int32_t centerTick = 1000;                        //!< tick of θ = 0 [tick]
        double rateHz = 1000;                                  //!< control rate [Hz]
        std::uint32_t servoTimeoutUs = kDefaultServoTimeoutUs; //!< bus reply timeout [µs]
        double tauLimit = 0.44;                                //!< torque at load ±1000 [N·m]
        QString stateFile;                                     //!< SAVE_PARAMS target; empty = RAM
        FaultSpec faults;                                      //!< injected on the pty link
        quint64 faultSeed = 1;                                 //!< seed of those faults
    };

    //! Timing and bus counters over a window of cycles.
    struct Report
    {
        double seconds = 0;           //!< wall time the window covers [s]
        std::uint64_t cycles = 0;     //!< control cycles run
        std::int64_t periodP50Us = 0; //!< cycle start to cycle start [µs]
        std::int64_t periodP99Us = 0;
        std::int64_t periodMaxUs = 0;
        std::int64_t busyP99Us = 0; //!< time inside controlCycle (bus transactions) [µs]
        std::int64_t busyMaxUs = 0;
        std::uint64_t late = 0;      //!< cycles more than a period late (schedule skipped)
        std::uint32_t busErrors = 0; //!< failed transactions in the window
        fw::StsBusStats bus;         //!< counters since start
        bool faulted = false;        //!< 100 bus errors in a row on a servo: its torque is off
        double rateHz() const { return seconds > 0 ? double(cycles) / seconds : 0.0; }
    };

    explicit FirmwareHost(const Config &config, QObject *parent = nullptr);
    ~FirmwareHost() override; //!< stop()

    //! Opens the servo port and the pty, brings the servo up (ping, position mode, torque on)
    //! and starts both contexts. Empty string on success, else one sentence.
    QString start();
    //! Stops the control thread, then switches the servo's torque off, closes the pty and
    //! removes the link. Safe to call twice.
    void stop();
    //! What a process that a fatal signal ends can still do (onFatalSignal): ask the control
    //! thread to stop and wait a bounded time for it to leave the bus, switch the torque off
    //! (WRITE 0 at register 40, sent twice), remove the link. Async-signal-safe: atomics,
    //! nanosleep(), write(), poll(), readlink(), unlink(); nothing allocates or locks.
    void emergencyStop() noexcept;
    bool isRunning() const { return m_thread.joinable(); }

    QString slavePath() const { return m_pty.slavePath(); }
    QString createLink(const QString &path); //!< PseudoTerminal::createLink
    //! Things said once at start (an unreadable or invalid state file).
    QStringList warnings() const { return m_warnings; }
    //! The faults injected on the pty link (Config::faults), or null when none are (link
    //! context: read it from the thread that runs the event loop).
    const FaultInjector *faults() const;
    bool realtime() const { return m_realtime.load(); } //!< SCHED_FIFO granted

    //! The statistics since the previous takeReport() (or start), and a new window begun.
    Report takeReport();
    //! The statistics since start.
    Report totalReport();

private:
    struct Shared; // statistics, guarded by its mutex
    //! Why the servo did not come up, from the bus's last error: no answer, or a wrong one.
    QString servoStartFailure(fw::StsBusError error) const;
    void controlLoop();
    void serviceLink();

    Config m_config;
    PseudoTerminal m_pty;
    std::unique_ptr<SerialServoPort> m_servoPort;
    std::unique_ptr<fw::StsBus> m_bus;
    std::vector<std::unique_ptr<fw::StsActuator<double>>> m_actuators; //!< knob 1 first
    std::unique_ptr<MonotonicClock> m_clock;
    std::unique_ptr<ProfileParamStore> m_store;
    std::unique_ptr<FdHostPort> m_hostPort;
    std::unique_ptr<fw::DeviceCore<double>> m_core;
    QSocketNotifier *m_notifier = nullptr;
    QTimer *m_timer = nullptr;
    QStringList m_warnings;

    //! The WRITEs that switch each servo's torque off, encoded at start for emergencyStop().
    struct TorqueOff
    {
        std::array<std::uint8_t, fw::sts::kMaxPacketBytes> bytes{};
        std::size_t size = 0;
    };
    std::array<TorqueOff, kMaxAxes> m_torqueOff{};

    std::thread m_thread;
    std::atomic<bool> m_stopping{false};
    std::atomic<bool> m_controlRunning{false}; //!< the control thread may still use the bus
    std::atomic<bool> m_realtime{false};
    std::unique_ptr<Shared> m_shared;
};

} // namespace hatpic
