// Runs a SimulatedDevice in real time behind a pseudo-terminal (hatpic-sim, and tests).
//
// Lives on the thread that created it and needs that thread's event loop. A ~1 ms precise
// timer advances the device by the measured elapsed time; host bytes are read from the pty
// master through a QSocketNotifier; device bytes are written non-blocking, with at most
// kMaxPendingBytes kept when the pty does not take them.
#pragma once

#include "link/faultinjector.h"
#include "link/pseudoterminal.h"
#include "sim/simulateddevice.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <memory>

class QSocketNotifier;
class QTimer;

namespace hatpic {

class SimulatorHost : public QObject
{
    Q_OBJECT
public:
    static constexpr qsizetype kMaxPendingBytes = 64 * 1024; //!< output kept when pty is full
    static constexpr double kMaxCatchUp = 0.1; //!< longest time advanced in one tick [s]
    static constexpr int kTickMs = 1;          //!< real-time timer period [ms]

    explicit SimulatorHost(const SimulatedDevice::Config &config, QObject *parent = nullptr);
    ~SimulatorHost() override; //!< stops, closes the pty and removes the link

    //! Opens the pseudo-terminal and starts the real-time loop. Returns an empty string on
    //! success, else one sentence saying why it failed.
    QString start();
    //! Stops the loop, closes the pty and removes the link (if still ours).
    void stop();
    //! What a process that a fatal signal ends can still do: remove the link.
    //! Async-signal-safe (PseudoTerminal::removeLinkNow).
    void emergencyStop() const noexcept { m_pty.removeLinkNow(); }
    bool isRunning() const { return m_pty.isOpen(); }

    //! The slave's path (e.g. "/dev/pts/3") that a client opens; empty before start().
    QString slavePath() const { return m_pty.slavePath(); }

    //! Creates a symlink at `path` to the slave (after start()). An existing symlink there
    //! is replaced; any other file is refused. Returns an empty string or the error.
    QString createLink(const QString &path);
    QString linkPath() const { return m_pty.linkPath(); }

    SimulatedDevice &device() { return *m_device; }
    const SimulatedDevice &device() const { return *m_device; }

    quint64 bytesDiscarded() const { return m_discarded; } //!< output the pty never took
    //! The faults injected (config.faults, clock from start()), or null when none are.
    const FaultInjector *faults() const { return m_faults.get(); }

private:
    void advanceToNow();
    void readHost();
    void writeOutput();

    double seconds() const { return double(m_clock.nsecsElapsed()) * 1e-9; }

    std::unique_ptr<SimulatedDevice> m_device;
    std::unique_ptr<FaultInjector> m_faults;
    PseudoTerminal m_pty;
    QSocketNotifier *m_readNotifier = nullptr;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;
    qint64 m_lastNs = 0;
    QByteArray m_pending;
    quint64 m_discarded = 0;
};

} // namespace hatpic
