#include "editor/deviceparameterlink.h"

#include "editor/parametereditor.h"
#include "session/deviceclient.h"
#include "session/sessionwording.h"

namespace hatpic {

DeviceParameterLink::DeviceParameterLink(DeviceClient *client, ParameterEditor *editor,
                                         QObject *parent)
    : QObject(parent), m_client(client), m_editor(editor)
{
    connect(m_editor, &ParameterEditor::pushRequested, this, &DeviceParameterLink::onPushRequested);
    connect(m_editor, &ParameterEditor::vibrateRequested, this,
            [this](const Vibration &v) { m_client->vibrate(v, then(CommandKind::Vibrate)); });
    connect(m_editor, &ParameterEditor::readRequested, this, &DeviceParameterLink::readFromDevice);
    connect(m_editor, &ParameterEditor::hostParamsChanged, m_client, &DeviceClient::setHostParams);
    connect(m_client, &DeviceClient::stateChanged, this,
            [this](SessionState state) { onStateChanged(state); });
    connect(m_client, &DeviceClient::deviceInfoChanged, this, &DeviceParameterLink::onDeviceInfo);
    connect(m_client, &DeviceClient::deviceTuningChanged, m_editor,
            &ParameterEditor::setDeviceTuning);
    onStateChanged(m_client->state());
}

void DeviceParameterLink::prepare(ConnectOptions &options)
{
    // The published firmware does not report its torque limit: the editor's tau_limit (the
    // profile's) scales the legacy feedback and stays what it is.
    if (m_editor->hostParams().tau_limit > 0)
        options.legacy.tauLimit = m_editor->hostParams().tau_limit;
    m_client->setHostParams(m_editor->hostParams());
}

CommandDone DeviceParameterLink::then(CommandKind kind)
{
    return {this, [this, kind](const CommandResult &result) { finishCommand(kind, result); }};
}

void DeviceParameterLink::onPushRequested(const DeviceTuning &tuning)
{
    m_client->pushTuning(
        tuning, {this, [this, before = m_client->deviceTuning()](const CommandResult &result) {
                     finishPush(before, result);
                 }});
}

void DeviceParameterLink::readFromDevice()
{
    m_client->readTuning(then(CommandKind::GetParams));
}

void DeviceParameterLink::zero()
{
    m_client->zero(then(CommandKind::Zero));
}

void DeviceParameterLink::saveInDevice()
{
    m_client->saveParams(then(CommandKind::SaveParams));
}

void DeviceParameterLink::onStateChanged(SessionState state)
{
    const bool connected = state == SessionState::Connected;
    m_editor->setCanPush(connected && m_client->deviceInfo().canSetParams(),
                         connected ? tr("the legacy protocol cannot carry parameters") : QString());
    if (state == SessionState::Disconnected)
        m_editor->setDeviceTuning({});
    refreshEffectsAvailability();
}

void DeviceParameterLink::onDeviceInfo(const DeviceInfo &info)
{
    if (info.protocol == WireProtocol::V2) // a legacy device reports no limit
        m_editor->setTauLimit(shortestFloatDecimal(info.tauLimit));
    refreshEffectsAvailability();
}

void DeviceParameterLink::refreshEffectsAvailability()
{
    const DeviceInfo &info = m_client->deviceInfo();
    const bool connected = m_client->state() == SessionState::Connected;
    const bool available = connected && info.hasEffects();
    // Our device core streams at most at its control rate, so max_stream_hz is that rate.
    const double rate = available ? double(info.maxStreamHz) : 0.0;
    m_editor->setEffectsAvailable(
        available,
        connected && !available
            ? SessionWording::noEffectsReason(info.protocol == WireProtocol::Legacy)
            : QString(),
        rate);
    const bool controller = connected && info.hasPassivity();
    m_editor->setPassivityAvailable(
        controller, connected && !controller
                        ? SessionWording::noPassivityReason(info.protocol == WireProtocol::Legacy)
                        : QString());
}

void DeviceParameterLink::finishPush(const DeviceTuning &before, const CommandResult &result)
{
    m_editor->pushFinished(result);
    if (result.ok()) {
        // What changed is what the device held against what travelled (float32, bounds kept
        // by the session's one rounding: `sent`), never the editor's doubles: the walls' ±π
        // travel as the float just inside π, which the device already held.
        const QString change = describeTuningChange(before, result.sent);
        m_lastMessage = change.isEmpty() ? tr("Pushed (no change).") : tr("Pushed: %1").arg(change);
        if (!change.isEmpty())
            Q_EMIT deviceChanged(change);
    } else {
        m_lastMessage = tr("Push failed: %1").arg(SessionWording::commandFailure(result));
    }
    Q_EMIT commandFinished(m_lastMessage);
}

void DeviceParameterLink::finishCommand(CommandKind kind, const CommandResult &result)
{
    QString what;
    switch (kind) {
    case CommandKind::GetParams:
        what = tr("Read");
        break;
    case CommandKind::Vibrate:
        what = result.vibration.amplitude > 0 ? tr("Vibrate") : tr("Stop vibration");
        break;
    case CommandKind::Zero:
        what = tr("ZERO");
        break;
    case CommandKind::SaveParams:
        what = tr("Save in device");
        break;
    default:
        return; // pushes finish in finishPush(); the link asks for nothing else
    }
    m_lastMessage = result.ok()
                        ? tr("%1: done.").arg(what)
                        : tr("%1 failed: %2").arg(what, SessionWording::commandFailure(result));
    if (result.ok() && kind == CommandKind::Zero)
        Q_EMIT deviceChanged(tr("ZERO: θ0 := current angle"));
    Q_EMIT commandFinished(m_lastMessage);
}

} // namespace hatpic
