#include "editor/synctracker.h"

#include "session/sessionwording.h"

#include <QCoreApplication>

namespace hatpic {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("hatpic::ParameterEditor", text);
}

} // namespace

void SyncTracker::setCanPush(bool canPush, const QString &reason)
{
    m_canPush = canPush;
    m_cannotPushReason = reason;
    if (!canPush)
        m_pushing.reset();
}

void SyncTracker::setDevice(const DeviceTuning &device)
{
    m_device = device;
    if (!device.params) {
        m_pushing.reset();
        m_pushed.reset();
        m_failure.reset();
        m_rejectedField.clear();
    } else if (m_failure == SyncState::AwaitingReadback) {
        m_failure.reset(); // read at last
    }
}

void SyncTracker::setEffectsTracked(bool tracked)
{
    m_effectsTracked = tracked;
    if (!tracked)
        m_device.effects.reset();
}

void SyncTracker::setPassivityTracked(bool tracked)
{
    m_passivityTracked = tracked;
    if (!tracked)
        m_device.passivity.reset();
}

DeviceTuning SyncTracker::counted(const DeviceTuning &tuning) const
{
    return {tuning.params, m_effectsTracked ? tuning.effects : std::nullopt,
            m_passivityTracked ? tuning.passivity : std::nullopt};
}

void SyncTracker::edited()
{
    m_failure.reset();
    m_rejectedField.clear();
}

void SyncTracker::pushStarted(const DeviceTuning &edited)
{
    m_pushing = edited;
    m_pushed.reset();
    m_failure.reset();
    m_rejectedField.clear();
}

bool SyncTracker::pushFinished(const Outcome &outcome)
{
    if (!m_pushing)
        return false;
    const DeviceTuning pushed = *m_pushing;
    m_pushing.reset();
    if (const auto *done = std::get_if<outcome::Done>(&outcome.result)) {
        m_device = m_device.updatedBy(outcome.received);
        m_pushed = pushed;
        if (done->readBack == outcome::ReadBack::Unanswered) {
            m_failure = SyncState::AwaitingReadback;
            m_failureText = tr("pushing… (waiting for the read-back)");
        }
        return true;
    }
    if (const auto *refused = std::get_if<outcome::Refused>(&outcome.result)) {
        m_failure = SyncState::Rejected;
        const std::string_view field =
            isEffectCommand(refused->step)      ? effectFieldName(refused->field)
            : isPassivityCommand(refused->step) ? passivityFieldName(refused->field)
                                                : deviceFieldName(refused->field);
        m_rejectedField = QString::fromLatin1(field.data(), qsizetype(field.size()));
    } else {
        m_failure = std::holds_alternative<outcome::TimedOut>(outcome.result) ? SyncState::Timeout
                                                                              : SyncState::Failed;
    }
    // A push that failed part-way changed the device all the same: what it accepted (its
    // read-back where it came) is the device's now.
    if (const outcome::Stopped *stop = outcome.stopped())
        m_device = m_device.updatedBy(stop->applied);
    m_failureText = SessionWording::commandFailureBrief(outcome);
    return true;
}

SyncState SyncTracker::state(const DeviceTuning &edited) const
{
    if (!m_canPush)
        return SyncState::NotConnected;
    if (m_pushing)
        return SyncState::Pushing;
    if (m_failure)
        return *m_failure;
    if (!m_device.params || (m_effectsTracked && !m_device.effects) ||
        (m_passivityTracked && !m_device.passivity))
        return SyncState::NotRead;
    // The parts that count: each block only while the device has it.
    const DeviceTuning device = counted(m_device);
    const DeviceTuning wanted = counted(edited);
    if (sameOnWire(wanted, device))
        return SyncState::InSync;
    if (m_pushed && sameOnWire(wanted, *m_pushed))
        return SyncState::ReadbackDiffers;
    return SyncState::Edited;
}

QString SyncTracker::text(const DeviceTuning &edited) const
{
    switch (state(edited)) {
    case SyncState::NotConnected:
        return m_cannotPushReason.isEmpty() ? tr("not connected") : m_cannotPushReason;
    case SyncState::NotRead:
        return tr("device values not read yet");
    case SyncState::Edited:
        return tr("edited — not pushed");
    case SyncState::Pushing:
        return tr("pushing…");
    case SyncState::InSync:
        return tr("in sync");
    case SyncState::ReadbackDiffers:
        return tr("not in sync: the device's read-back differs (see ● markers)");
    case SyncState::AwaitingReadback:
    case SyncState::Rejected:
    case SyncState::Timeout:
    case SyncState::Failed:
        return m_failureText;
    }
    return {};
}

} // namespace hatpic
