#include "connection/robotsideview.h"

#include <QFormLayout>
#include <QLabel>

#include <cmath>

namespace hatpic {

using namespace Qt::StringLiterals;

namespace {

QString number(double value)
{
    return std::isfinite(value) ? QString::number(value, 'g', 4) : u"–"_s;
}

QString milliseconds(double seconds)
{
    return std::isfinite(seconds) ? QString::number(seconds * 1e3, 'f', 1) + u" ms"_s : u"–"_s;
}

QLabel *row(QFormLayout *form, const QString &label, const QString &name, const QString &tip)
{
    auto *value = new QLabel(form->parentWidget());
    value->setObjectName(name);
    value->setWordWrap(true);
    value->setToolTip(tip);
    form->addRow(label, value);
    return value;
}

} // namespace

RobotSideView::RobotSideView(QWidget *parent) : QGroupBox(tr("Robot side (measured)"), parent)
{
    setObjectName(u"bridge_section_robot"_s);
    auto *form = new QFormLayout(this);
    m_wrench = row(form, tr("Last wrench"), u"bridge_robot_wrench"_s,
                   tr("The chosen component of the last wrench received, and how long ago"));
    m_stampDelay =
        row(form, tr("Stamp → applied"), u"bridge_stamp_delay"_s,
            tr("This machine's wall clock when the bridge applied a wrench, minus the wrench's "
               "header stamp: the one-way delay, when both clocks agree (one machine, NTP or "
               "PTP). Median and 95th percentile of the last %1 stamped wrenches.")
                .arg(bridge::RecentValues::kRecent));
    m_echoDelay =
        row(form, tr("Arrival → device"), u"bridge_echo_delay"_s,
            tr("From a wrench's arrival to the first telemetry sample whose τ_ext shows the "
               "value it asked for (only wrenches that changed τ_ext). Median and 95th "
               "percentile of the last %1.")
                .arg(bridge::RecentValues::kRecent));
    m_arrivals = row(form, tr("Arrivals"), u"bridge_arrivals"_s,
                     tr("The median time between wrenches, and the wrenches lost, estimated: a "
                        "gap longer than %1 × that interval counts round(gap / interval) − 1. "
                        "Neither ROS tells a subscriber what it missed; jitter near half the "
                        "interval counts too many. A silence longer than the stale time is a "
                        "pause, not a loss.")
                         .arg(bridge::WrenchTiming::kGapFactor));
}

void RobotSideView::setStats(const bridge::BridgeStats &s, bridge::Component component)
{
    const auto &t = s.timing;
    m_wrench->setText(std::isfinite(t.age)
                          ? tr("%1 %2 %3, %4 ago")
                                .arg(QString::fromStdString(component.wrenchName()),
                                     number(s.lastWrench), component.angular ? u"N·m"_s : u"N"_s,
                                     milliseconds(t.age))
                          : tr("none yet"));
    const auto spread = [](const bridge::Spread &d, const QString &counted) {
        if (d.count == 0)
            return tr("– (none measured)");
        return tr("%1 median, %2 p95 (%3 %4)")
            .arg(milliseconds(d.median), milliseconds(d.p95), QString::number(d.count), counted);
    };
    m_stampDelay->setText(t.stampDelay.count == 0 && t.unstamped > 0
                              ? tr("– (the wrenches carry no stamp)")
                              : spread(t.stampDelay, tr("stamped")));
    m_echoDelay->setText(spread(t.echoDelay, tr("changes")));
    m_arrivals->setText(
        tr("every %1; ≈ %2 lost (estimated from gaps), %3 pauses")
            .arg(milliseconds(t.interval), QString::number(t.lost), QString::number(t.pauses)));
}

QString RobotSideView::text() const
{
    return tr("wrench %1 | stamp → applied %2 | arrival → device %3 | arrivals %4")
        .arg(m_wrench->text(), m_stampDelay->text(), m_echoDelay->text(), m_arrivals->text());
}

} // namespace hatpic
