#include "editor/deviceparameterlink.h"

#include "editor/commandtext.h"
#include "editor/parametereditor.h"
#include "session/deviceclient.h"

namespace hatpic {

DeviceParameterLink::DeviceParameterLink(DeviceClient *client, ParameterEditor *editor,
                                         QObject *parent)
    : QObject(parent), m_client(client), m_editor(editor)
{
    connect(m_editor, &ParameterEditor::pushRequested, this, [this](const DeviceParams &params) {
        const DeviceParams before = m_client->deviceParams();
        m_push = Push{m_client->pushParams(params), before, params};
    });
    connect(m_editor, &ParameterEditor::readRequested, this, &DeviceParameterLink::readFromDevice);
    connect(m_editor, &ParameterEditor::hostParamsChanged, m_client, &DeviceClient::setHostParams);
    connect(m_client, &DeviceClient::stateChanged, this,
            [this](SessionState state) { onStateChanged(state); });
    connect(m_client, &DeviceClient::deviceInfoChanged, this, &DeviceParameterLink::onDeviceInfo);
    connect(m_client, &DeviceClient::deviceParamsChanged, m_editor,
            &ParameterEditor::setDeviceParams);
    connect(m_client, &DeviceClient::commandFinished, this,
            &DeviceParameterLink::onCommandFinished);
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

void DeviceParameterLink::readFromDevice()
{
    m_commands.insert(m_client->readParams(), Command::Read);
}

void DeviceParameterLink::zero()
{
    m_commands.insert(m_client->zero(), Command::Zero);
}

void DeviceParameterLink::saveInDevice()
{
    m_commands.insert(m_client->saveParams(), Command::Save);
}

void DeviceParameterLink::onStateChanged(SessionState state)
{
    const bool connected = state == SessionState::Connected;
    m_editor->setCanPush(connected && m_client->deviceInfo().canSetParams(),
                         connected ? tr("the legacy protocol cannot carry parameters") : QString());
    if (state == SessionState::Disconnected)
        m_editor->clearDeviceParams();
}

void DeviceParameterLink::onDeviceInfo(const DeviceInfo &info)
{
    if (info.protocol == WireProtocol::V2) // a legacy device reports no limit
        m_editor->setTauLimit(shortestFloatDecimal(info.tauLimit));
}

void DeviceParameterLink::onCommandFinished(quint64 id, const CommandResult &result)
{
    if (m_push && m_push->id == id) {
        finishPush(result);
    } else if (const auto it = m_commands.constFind(id); it != m_commands.cend()) {
        const Command command = it.value();
        m_commands.erase(it);
        finishCommand(command, result);
    }
}

void DeviceParameterLink::finishPush(const CommandResult &result)
{
    const Push push = *m_push;
    m_push.reset();
    m_editor->pushFinished(result);
    if (result.ok()) {
        const QString change = describeParamChange(push.before, push.pushed);
        m_lastMessage = change.isEmpty() ? tr("Pushed (no change).") : tr("Pushed: %1").arg(change);
        if (!change.isEmpty())
            Q_EMIT deviceChanged(change);
    } else {
        m_lastMessage = tr("Push failed: %1").arg(CommandText::commandFailure(result));
    }
    Q_EMIT commandFinished(m_lastMessage);
}

void DeviceParameterLink::finishCommand(Command command, const CommandResult &result)
{
    QString what;
    switch (command) {
    case Command::Read:
        what = tr("Read");
        break;
    case Command::Zero:
        what = tr("ZERO");
        break;
    case Command::Save:
        what = tr("Save in device");
        break;
    }
    m_lastMessage = result.ok()
                        ? tr("%1: done.").arg(what)
                        : tr("%1 failed: %2").arg(what, CommandText::commandFailure(result));
    if (result.ok() && command == Command::Zero)
        Q_EMIT deviceChanged(tr("ZERO: θ0 := current angle"));
    Q_EMIT commandFinished(m_lastMessage);
}

} // namespace hatpic
