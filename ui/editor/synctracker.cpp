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
    if (!canPush) {
        m_pushing = false;
        m_awaitingReadback = false;
    }
}

void SyncTracker::setDevice(const std::optional<DeviceParams> &device)
{
    m_device = device;
    if (!device) {
        m_pushing = false;
        m_awaitingReadback = false;
        m_awaitingEffectsReadback = false;
        m_pushedOk = false;
        m_failure.reset();
        m_rejectedField.clear();
        m_deviceEffects.reset();
    } else if (m_pushing) {
        // The read-back of this push may arrive before the push's own result.
        m_readbackDuringPush = true;
    } else {
        m_awaitingReadback = false;
    }
}

void SyncTracker::setEffectsTracked(bool tracked)
{
    m_effectsTracked = tracked;
    if (!tracked) {
        m_deviceEffects.reset();
        m_awaitingEffectsReadback = false;
    }
}

void SyncTracker::setDeviceEffects(const std::optional<EffectParams> &effects)
{
    m_deviceEffects = effects;
    if (m_pushing)
        m_effectsReadbackDuringPush = true; // it may arrive before the push's own result
    else
        m_awaitingEffectsReadback = false;
}

void SyncTracker::edited()
{
    m_failure.reset();
    m_rejectedField.clear();
}

void SyncTracker::pushStarted(const DeviceParams &pushed,
                              const std::optional<EffectParams> &effects)
{
    m_pushing = true;
    m_awaitingReadback = true;
    m_awaitingEffectsReadback = effects.has_value();
    m_readbackDuringPush = false;
    m_effectsReadbackDuringPush = false;
    m_pushedOk = false;
    m_failure.reset();
    m_rejectedField.clear();
    m_lastPushed = pushed;
    m_lastPushedEffects = effects;
}

bool SyncTracker::pushFinished(const CommandResult &result)
{
    if (!m_pushing)
        return false;
    m_pushing = false;
    if (result.ok()) {
        m_pushedOk = true;
        m_awaitingReadback = !m_readbackDuringPush;
        m_awaitingEffectsReadback = m_awaitingEffectsReadback && !m_effectsReadbackDuringPush;
        return true;
    }
    m_awaitingReadback = false;
    m_awaitingEffectsReadback = false;
    switch (result.status) {
    case CommandResult::Status::Rejected: {
        m_failure = SyncState::Rejected;
        const std::string_view field = isEffectCommand(result.command)
                                           ? effectFieldName(result.field)
                                           : deviceFieldName(result.field);
        m_rejectedField = QString::fromLatin1(field.data(), qsizetype(field.size()));
        break;
    }
    case CommandResult::Status::Timeout:
        m_failure = SyncState::Timeout;
        break;
    default:
        m_failure = SyncState::Failed;
        break;
    }
    m_failureText = SessionWording::commandFailureBrief(result);
    return true;
}

bool SyncTracker::inSync(const DeviceParams &edited, const EffectParams &editedEffects) const
{
    if (!sameOnWire(edited, *m_device))
        return false;
    return !m_effectsTracked || (m_deviceEffects && sameOnWire(editedEffects, *m_deviceEffects));
}

SyncState SyncTracker::state(const DeviceParams &edited, const EffectParams &editedEffects) const
{
    if (!m_canPush)
        return SyncState::NotConnected;
    if (m_pushing)
        return SyncState::Pushing;
    if (m_failure)
        return *m_failure;
    if (!m_device || (m_effectsTracked && !m_deviceEffects))
        return SyncState::NotRead;
    if (m_awaitingReadback || m_awaitingEffectsReadback)
        return SyncState::AwaitingReadback;
    if (inSync(edited, editedEffects))
        return SyncState::InSync;
    const bool effectsAsPushed =
        !m_effectsTracked || (m_lastPushedEffects && *m_lastPushedEffects == editedEffects);
    if (m_pushedOk && edited == m_lastPushed && effectsAsPushed)
        return SyncState::ReadbackDiffers;
    return SyncState::Edited;
}

QString SyncTracker::text(const DeviceParams &edited, const EffectParams &editedEffects) const
{
    switch (state(edited, editedEffects)) {
    case SyncState::NotConnected:
        return m_cannotPushReason.isEmpty() ? tr("not connected") : m_cannotPushReason;
    case SyncState::NotRead:
        return tr("device values not read yet");
    case SyncState::Edited:
        return tr("edited — not pushed");
    case SyncState::Pushing:
        return tr("pushing…");
    case SyncState::AwaitingReadback:
        return tr("pushing… (waiting for the read-back)");
    case SyncState::InSync:
        return tr("in sync");
    case SyncState::ReadbackDiffers:
        return tr("not in sync: the device's read-back differs (see ● markers)");
    case SyncState::Rejected:
    case SyncState::Timeout:
    case SyncState::Failed:
        return m_failureText;
    }
    return {};
}

} // namespace hatpic
