// ByteLink to an in-process SimulatedDevice, advanced in real time on the session thread.
//
// A ~1 ms precise timer runs the simulator for the elapsed wall-clock time and delivers its
// output bytes, so the session sees the same byte stream (and decodes it on the same path)
// as from a serial port. The test seams below act on that byte stream.
#pragma once

#include "link/bytelink.h"
#include "link/faultinjector.h"
#include "sim/simulateddevice.h"

#include <QElapsedTimer>
#include <QTimer>

#include <memory>

namespace hatpic {

class SimLink : public ByteLink
{
    Q_OBJECT
public:
    static constexpr int kTickMs = 1;           //!< timer period [ms]
    static constexpr double kMaxAdvance = 0.05; //!< longest step after a stall [s]

    explicit SimLink(const SimulatedDevice::Config &config, QObject *parent = nullptr);
    ~SimLink() override;

    bool open() override;
    void close() override;
    bool isOpen() const override;
    void write(const QByteArray &bytes) override;
    QString errorString() const override { return {}; }
    qint32 baud() const override;

    //! The simulator while open, else null (session thread only).
    SimulatedDevice *device() const { return m_device.get(); }
    void setHand(const HandInput &hand);
    //! The faults this link injects (config.faults), or null when it injects none. Its
    //! clock starts when the link first opens and runs on across reopening.
    const FaultInjector *faults() const { return m_faults.get(); }

    // ---- test seams ----
    //! Swallows the next `count` host frames of message type `type` (0 = any type).
    void dropHostFrames(int count, quint8 type = 0);
    //! Host frames swallowed so far.
    int droppedHostFrames() const { return m_dropped; }
    //! Delivers `bytes` to the host as if the device had sent them (e.g. garbage).
    void injectToHost(const QByteArray &bytes);
    //! While silenced the device keeps running but none of its bytes reach the host.
    void setSilenced(bool silenced) { m_silenced = silenced; }
    //! Breaks the link as a vanished port would: closes it and emits failed().
    void sever(const QString &reason);

private:
    void tick();

    SimulatedDevice::Config m_config;
    double faultClock() const { return double(m_faultClock.nsecsElapsed()) * 1e-9; }

    std::unique_ptr<SimulatedDevice> m_device;
    std::unique_ptr<FaultInjector> m_faults;
    QElapsedTimer m_faultClock;
    QTimer m_timer;
    QElapsedTimer m_clock;
    qint64 m_lastNs = 0;
    int m_dropCount = 0;
    quint8 m_dropType = 0;
    int m_dropped = 0;
    bool m_silenced = false;
};

} // namespace hatpic
