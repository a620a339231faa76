#include "telemetry/recordingtrigger.h"

#include "telemetry/numbertext.h"

#include <QStringBuilder>

#include <algorithm>
#include <cmath>

namespace hatpic {

namespace {

double finiteOr0(double v)
{
    return std::isfinite(v) ? v : 0.0;
}

} // namespace

RecordingPlan RecordingPlan::sanitized() const
{
    RecordingPlan p = *this;
    p.level = finiteOr0(level);
    p.preTrigger_s = std::clamp(finiteOr0(preTrigger_s), 0.0, kMaxPreTrigger_s);
    p.duration_s = std::max(finiteOr0(duration_s), 0.0);
    return p;
}

QString triggerEventText(const RecordingPlan &plan)
{
    switch (plan.start) {
    case RecordingPlan::Start::Now:
        return QStringLiteral("trigger: start");
    case RecordingPlan::Start::NextPush:
        return QStringLiteral("trigger: push");
    case RecordingPlan::Start::Threshold:
        break;
    }
    const bool theta = plan.quantity == RecordingPlan::Quantity::Theta;
    const bool rising = plan.edge == RecordingPlan::Edge::Rising;
    return u"trigger: " % (theta ? QStringLiteral("theta") : QStringLiteral("tau")) %
           (rising ? QStringLiteral(" rising") : QStringLiteral(" falling")) % u" through " %
           compactNumberText(plan.level);
}

RecordingTrigger::RecordingTrigger(const RecordingPlan &plan) : m_plan(plan.sanitized()) {}

bool RecordingTrigger::feed(const Sample &sample)
{
    if (m_plan.start != RecordingPlan::Start::Threshold || m_fired)
        return false;
    const double v = m_plan.quantity == RecordingPlan::Quantity::Theta ? sample.theta : sample.tau;
    if (std::isnan(v))
        return false;
    const bool beyond =
        m_plan.edge == RecordingPlan::Edge::Rising ? v >= m_plan.level : v <= m_plan.level;
    const bool fires = m_havePrevious && beyond && !m_previousBeyond;
    m_havePrevious = true;
    m_previousBeyond = beyond;
    m_fired = fires;
    return fires;
}

void RecordingTrigger::reset()
{
    m_havePrevious = false;
    m_previousBeyond = false;
    m_fired = false;
}

} // namespace hatpic
