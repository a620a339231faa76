#include "editor/synctracker.h"

#include <QCoreApplication>

namespace hatpic {

using namespace Qt::StringLiterals;

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
        m_pushedOk = false;
        m_failure.reset();
        m_rejectedField = -1;
    } else if (m_pushing) {
        // The read-back of this push may arrive before the push's own result.
        m_readbackDuringPush = true;
    } else {
        m_awaitingReadback = false;
    }
}

void SyncTracker::edited()
{
    m_failure.reset();
    m_rejectedField = -1;
}

void SyncTracker::pushStarted(const DeviceParams &pushed)
{
    m_pushing = true;
    m_awaitingReadback = true;
    m_readbackDuringPush = false;
    m_pushedOk = false;
    m_failure.reset();
    m_rejectedField = -1;
    m_lastPushed = pushed;
}

bool SyncTracker::pushFinished(const CommandResult &result)
{
    if (!m_pushing)
        return false;
    m_pushing = false;
    if (result.ok()) {
        m_pushedOk = true;
        m_awaitingReadback = !m_readbackDuringPush;
        return true;
    }
    m_awaitingReadback = false;
    switch (result.status) {
    case CommandResult::Status::Rejected: {
        m_failure = SyncState::Rejected;
        QString reason = v2::ackStatusName(result.ackStatus);
        const QString name = QString::fromLatin1(deviceFieldName(result.field));
        if (!name.isEmpty() && !reason.contains(name))
            reason += u" ("_s + name + u')';
        m_failureText = tr("device rejected: %1").arg(reason);
        m_rejectedField = result.field;
        break;
    }
    case CommandResult::Status::Timeout:
        m_failure = SyncState::Timeout;
        m_failureText = tr("timeout: the device did not answer");
        break;
    case CommandResult::Status::NotConnected:
        m_failure = SyncState::Failed;
        m_failureText = tr("push failed: not connected to the device");
        break;
    case CommandResult::Status::Unsupported:
        m_failure = SyncState::Failed;
        m_failureText = tr("push failed: the device's protocol cannot carry parameters");
        break;
    default:
        m_failure = SyncState::Failed;
        m_failureText = result.problems.isEmpty()
                            ? tr("push failed: the command was not sent")
                            : tr("push failed: %1").arg(result.problems.join(u"; "_s));
        break;
    }
    return true;
}

SyncState SyncTracker::state(const DeviceParams &edited) const
{
    if (!m_canPush)
        return SyncState::NotConnected;
    if (m_pushing)
        return SyncState::Pushing;
    if (m_failure)
        return *m_failure;
    if (!m_device)
        return SyncState::NotRead;
    if (m_awaitingReadback)
        return SyncState::AwaitingReadback;
    if (sameOnWire(edited, *m_device))
        return SyncState::InSync;
    if (m_pushedOk && edited == m_lastPushed)
        return SyncState::ReadbackDiffers;
    return SyncState::Edited;
}

QString SyncTracker::text(const DeviceParams &edited) const
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
