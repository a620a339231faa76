// When a live push goes out: on every edit while live push is on, at most one push in flight
// and one per interval, and the last edit is always sent (a timer sends it once the interval
// has passed). It decides only when; the editor says whether a push may start now and sends
// it (pushDue).
#pragma once

#include <QElapsedTimer>
#include <QObject>

#include <functional>

class QTimer;

namespace hatpic {

class LivePush : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultIntervalMs = 100; //!< ≤ 10 live pushes per second

    //! `ready`: whether a push may start now (the edited set is valid, the device takes
    //! parameters, no push is in flight).
    explicit LivePush(std::function<bool()> ready, QObject *parent = nullptr);

    void setEnabled(bool enabled);      //!< off: forgets a pending edit
    void setInterval(int milliseconds); //!< negative: 0

    //! The edited set changed: it is to be sent, now or when the interval has passed.
    void edited();
    //! A push starts (live or not): nothing is pending, the interval counts from now.
    void pushStarted();
    //! The device no longer takes parameters: forgets a pending edit.
    void cancel();
    //! Sends the pending edit if it may go now (a push finished, the timer fired).
    void retry();

Q_SIGNALS:
    void pushDue(); //!< push the edited set now

private:
    std::function<bool()> m_ready;
    bool m_enabled = false;
    bool m_pending = false;
    int m_interval = kDefaultIntervalMs; //!< [ms]
    QElapsedTimer m_sinceLastPush;
    QTimer *m_timer = nullptr;
};

} // namespace hatpic
