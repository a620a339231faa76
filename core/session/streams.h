// The two periodic streams of a connected session, each on its own timer: the feedback torque
// at the requested rate, and the PING probe that measures the round trip (RttStats).
// What goes on the wire is the protocol driver's business; these only keep the time.
#pragma once

#include "session/rttstats.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>

#include <functional>

namespace hatpic {

class FeedbackStream : public QObject
{
    Q_OBJECT
public:
    using Sender = std::function<void(double tauExt)>;

    explicit FeedbackStream(Sender send, QObject *parent = nullptr);

    //! Sends now, then every 1/rateHz; rateHz ≤ 0 sends nothing.
    void start(double rateHz);
    void stop();
    //! The torque to stream [N·m]; not finite = 0.
    void setTauExt(double tauExt);
    double tauExt() const { return m_tauExt; }
    //! Paused: nothing is sent (e.g. to see the device's watchdog act).
    void setPaused(bool paused) { m_paused = paused; }

private:
    void send();

    Sender m_send;
    QTimer m_timer;
    double m_tauExt = 0; //!< requested feedback [N·m]
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
