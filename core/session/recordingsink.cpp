#include "recordingsink.h"

#include "session/sessiontypes.h"
#include "telemetry/numbertext.h"

#include <QStringBuilder>
#include <QStringList>

namespace hatpic {

namespace {

QString describeHostChange(const HostParams &from, const HostParams &to)
{
    QStringList parts;
    auto onOff = [](bool on) { return on ? QStringLiteral("on") : QStringLiteral("off"); };
    if (from.v_max != to.v_max)
        parts << u"v_max " % compactNumberText(from.v_max) % u" → " % compactNumberText(to.v_max);
    if (from.mode != to.mode) {
        parts << u"mode " % QString::fromLatin1(referenceModeName(from.mode)) % u" → " %
                     QString::fromLatin1(referenceModeName(to.mode));
    }
    if (from.ref_deadzone != to.ref_deadzone)
        parts << u"ref_deadzone " % onOff(from.ref_deadzone) % u" → " % onOff(to.ref_deadzone);
    if (from.tau_limit != to.tau_limit) {
        parts << u"tau_limit " % compactNumberText(from.tau_limit) % u" → " %
                     compactNumberText(to.tau_limit);
    }
    return parts.join(QStringLiteral("; "));
}

} // namespace

RecordingSink::RecordingSink(QObject *parent) : QObject(parent), m_timer(this)
{
    m_timer.setInterval(RecordingWriter::kFlushIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &RecordingSink::onFlushTick);
}

bool RecordingSink::open(const QString &csvPath, const RecordingMetadata &metadata)
{
    m_gap.reset();
    m_gaps = 0;
    if (!m_writer.open(csvPath, metadata)) {
        report(m_writer.error());
        return false;
    }
    m_timer.start();
    report({});
    return true;
}

void RecordingSink::reportArmed(const QString &csvPath, const QString &trigger)
{
    RecordingStatus status;
    status.armed = true;
    status.path = csvPath;
    status.trigger = trigger;
    Q_EMIT statusChanged(status);
}

void RecordingSink::reportDisarmed(const QString &csvPath)
{
    RecordingStatus status;
    status.path = csvPath;
    Q_EMIT statusChanged(status);
}

void RecordingSink::close(const QString &error)
{
    if (m_gap) {
        addEvent(gapText() % u"; the recording ended before the device came back");
        m_gap.reset();
    }
    m_timer.stop();
    const bool wasOpen = m_writer.isOpen();
    m_writer.close();
    if (wasOpen || !error.isEmpty())
        report(error.isEmpty() ? m_writer.error() : error);
}

void RecordingSink::suspend(double lostAfter_s, const StateDetail &why)
{
    if (!m_writer.isOpen() || m_gap)
        return;
    m_gap = Gap{lostAfter_s, why};
    ++m_gaps;
    report({});
}

void RecordingSink::resume(const QStringList &changes, bool unread)
{
    if (!m_gap)
        return;
    addEvent(gapText() % u"; recording resumed" %
             (unread ? QStringLiteral("; the device's parameters were not read back") : QString()));
    for (const QString &change : changes)
        addEvent(change % u" (after the gap)");
    m_gap.reset();
    report({});
}

void RecordingSink::closeForOtherDevice(const QStringList &differences)
{
    if (!m_gap)
        return;
    addEvent(gapText() % u"; a different device answered (" % differences.join(u"; ") %
             u"), so the recording ended at the loss");
    m_gap.reset();
    close();
}

QString RecordingSink::gapText() const
{
    QString why;
    if (const auto *silent = m_gap->why.as<state::Silent>()) {
        why = u"no data for " % QString::number(silent->silenceMs) % u" ms";
    } else {
        const auto *failed = m_gap->why.as<state::LinkFailed>(); // the other kind of loss
        why = u"port error: " % (failed ? failed->error : QString());
    }
    return u"gap: link lost after t_s " % compactNumberText(m_gap->lostAfter_s) % u" (" % why %
           u')';
}

void RecordingSink::append(const SampleBatch &batch)
{
    if (m_writer.isOpen() && !m_writer.append(batch))
        close(m_writer.error());
}

void RecordingSink::addEvent(const QString &text)
{
    if (m_writer.isOpen())
        m_writer.addEvent(text);
}

void RecordingSink::tuningApplied(const DeviceTuning &from, const DeviceTuning &to)
{
    const QString change = describeTuningChange(from, to);
    if (!change.isEmpty())
        addEvent(change);
    else
        addEvent(to.params ? QStringLiteral("SET_PARAMS (no change)")
                           : QStringLiteral("SET_EFFECTS (no change)"));
}

void RecordingSink::tuningReadBack(const DeviceTuning &from, const DeviceTuning &to)
{
    addEvent(describeTuningChange(from, to) % u" (read back)");
}

void RecordingSink::zeroed(double theta0Before)
{
    addEvent(u"ZERO: theta0 := current angle (was " % compactNumberText(theta0Before) % u')');
}

void RecordingSink::hostChanged(const HostParams &from, const HostParams &to)
{
    addEvent(describeHostChange(from, to));
}

void RecordingSink::referenceReset()
{
    addEvent(QStringLiteral("p_ref reset to 0"));
}

void RecordingSink::report(const QString &error)
{
    RecordingStatus status = m_writer.status();
    status.waiting = status.active && m_gap.has_value();
    status.gaps = m_gaps;
    if (!error.isEmpty())
        status.error = error;
    Q_EMIT statusChanged(status);
}

void RecordingSink::onFlushTick()
{
    if (!m_writer.isOpen()) {
        m_timer.stop();
        return;
    }
    Q_EMIT aboutToFlush();
    if (m_writer.isOpen() && !m_writer.flush()) {
        close(m_writer.error());
        return;
    }
    if (m_writer.isOpen())
        report({});
}

} // namespace hatpic
