// The two streams of a connected session: the feedback torque (sent on change, capped in rate,
// kept alive on a timer), and the PING probe that measures the round trip (RttStats).
// What goes on the wire is the protocol driver's business; these only keep the time.
#pragma once

#include "model/axes.h"
#include "session/rttstats.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>

#include <functional>

namespace hatpic {

//! The feedback torque to the device: a new τ_ext goes out at once (the robot path must add
//! no delay), at most maxRateHz frames per second (a change that comes sooner waits for the
//! rest of that interval), and the last value again every kKeepAliveMs so that the device's
//! 200 ms feedback watchdog never trips while the host holds a torque.
class FeedbackStream : public QObject
{
    Q_OBJECT
public:
    //! Longest time between two frames while running [ms]: a quarter of the device's
    //! feedback watchdog (200 ms, protocol.md), so a lost frame or two never trips it.
    static constexpr int kKeepAliveMs = 50;

    using Sender = std::function<void(const AxisTorques &tauExt)>;

    explicit FeedbackStream(Sender send, QObject *parent = nullptr);

    //! Sends now, then on every change (at most maxRateHz per second) and every kKeepAliveMs;
    //! maxRateHz ≤ 0 sends nothing.
    void start(double maxRateHz);
    void stop();
    //! The torque to stream to each knob [N·m]; not finite = 0. A change is sent at once when
    //! the rate allows, else at the end of the current interval.
    void setTorques(const AxisTorques &tauExt);
    //! Knob 1's torque; the other knobs' stay as they are.
    void setTauExt(double tauExt);
    double tauExt() const { return m_tauExt[0]; }
    const AxisTorques &torques() const { return m_tauExt; }
    //! Paused: nothing is sent (e.g. to see the device's watchdog act).
    void setPaused(bool paused) { m_paused = paused; }

private:
    void send();

    Sender m_send;
    QTimer m_keepAlive; //!< restarted by every frame
    QTimer m_deferred;  //!< a change that came within the minimum interval
    QElapsedTimer m_sinceSend;
    qint64 m_minIntervalNs = 0; //!< 1/maxRateHz [ns]
    AxisTorques m_tauExt{};     //!< requested feedback, per knob [N·m]
    bool m_running = false;
    bool m_paused = false;
};

class PingProbe : public QObject
{
    Q_OBJECT
public:
    static constexpr int kPingIntervalMs = 1000; //!< PING period [ms]
    static constexpr int kMaxPendingPings = 16;  //!< unanswered PING tokens remembered

    //! Sends a PING with `token` now; false when it cannot (busy, or no PING in the protocol).
    using Sender = std::function<bool(quint32 token)>;

    PingProbe(const QElapsedTimer &clock, Sender send, QObject *parent = nullptr);

    //! Pings now and then every kPingIntervalMs.
    void start();
    void stop();                //!< forgets the unanswered probes; keeps the figures
    void clear();               //!< and the figures
    void onPong(quint32 token); //!< a PONG arrived
    const RttStats &rtt() const { return m_rtt; }

private:
    void ping();

    const QElapsedTimer &m_clock;
    Sender m_send;
    QTimer m_timer;
    quint32 m_token = 0;
    QHash<quint32, qint64> m_pending; //!< token → send time [ns]
    RttStats m_rtt;
};

} // namespace hatpic
