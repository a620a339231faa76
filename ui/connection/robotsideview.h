// The Bridge panel's "Robot side" section (ros.md § In the tuner: the Bridge panel): the last
// wrench and its age, its one-way delay by its stamp, the time until the device showed the
// τ_ext it asked for (median and 95th percentile of the recent ones), and the wrenches lost on
// the way, estimated from the gaps between arrivals. It only shows what Bridge::stats() measured.
#pragma once

#include "bridge/bridge.h"

#include <QGroupBox>

class QLabel;

namespace hatpic {

class RobotSideView : public QGroupBox
{
    Q_OBJECT
public:
    explicit RobotSideView(QWidget *parent = nullptr);

    //! The bridge's statistics now; `component` names the wrench's component fed back.
    void setStats(const bridge::BridgeStats &stats, bridge::Component component);
    //! The rows as one line of text (for the panel's status text).
    QString text() const;

private:
    QLabel *m_wrench = nullptr;
    QLabel *m_stampDelay = nullptr;
    QLabel *m_echoDelay = nullptr;
    QLabel *m_arrivals = nullptr;
};

} // namespace hatpic
